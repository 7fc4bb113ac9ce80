#!/usr/bin/env bash
# prony_vs_expression.sh EXE WORKDIR PRM...: each run with long memory
# (doc/theory.md, section 11) gives the same steps.csv and probes.csv with
# its two-term Prony kernel and with the same kernel written as expressions
# mu_R(t), lambda_R(t) (the recursion against the sum over the stored
# states): the branch counts exactly, every energy, its memory work and
# every probe value to a relative 1e-9. The two sums differ by round-off;
# the Newton solves they feed are run to a tight tolerance, so that their
# stopping points do not hide a difference in the memory.
set -euo pipefail
exe=$1; work=$2; shift 2
rm -rf "$work"; mkdir -p "$work"; cd "$work"
columns="step time n_separating n_normal_stick n_damped n_stick n_slip
  kinetic_energy elastic_energy viscous_dissipation friction_dissipation
  normal_damping_dissipation external_work numerical_dissipation memory_work"
columns_of() { # FILE [COLUMN...]
  local file=$1; shift
  awk -F, -v want="$*" 'BEGIN { OFS = "," }
    NR == 1 { n = split(want, w, " "); if (n == 0) for (i = 1; i <= NF; ++i) w[++n] = $i
              for (j = 1; j <= n; ++j) { col[j] = 0
                for (i = 1; i <= NF; ++i) if ($i == w[j]) col[j] = i
                if (col[j] == 0) { print "no column " w[j] > "/dev/stderr"; exit 1 } } }
    { line = $col[1]; for (j = 2; j <= n; ++j) line = line OFS $col[j]; print line }' "$file"
}
for prm in "$@"; do
  name=$(basename "$prm" .prm)
  for kernel in prony expression; do
    { cat "$prm"
      printf 'subsection output\n  set directory = %s-%s\n  set terminal = quiet\n' "$name" "$kernel"
      printf '  set probe points = 4, 0; 2, 0; 1, 0.5\nend\n'
      printf 'subsection nonlinear solver\n  set tolerance = 1e-11\nend\n'
      printf 'subsection linear solver\n  set relative tolerance = 1e-12\nend\n'
      if [ $kernel = expression ]; then
        printf 'subsection relaxation\n  set kernel = expression\n'
        printf '  set mu = 20*exp(-t/0.2) + 5*exp(-t)\n'
        printf '  set lambda = 30*exp(-t/0.2) + 5*exp(-t)\nend\n'
      fi; } > "$name-$kernel.prm"
    "$exe" "$name-$kernel.prm"
  done
  grep -q "kernel *= *prony" "$prm" || { echo "FAIL: $prm has no Prony kernel"; exit 1; }
  for f in steps.csv probes.csv; do
    if [ $f = steps.csv ]; then c=$columns; else c=""; fi
    columns_of "$name-prony/$f" $c > a.csv; columns_of "$name-expression/$f" $c > b.csv
    [ "$(wc -l < a.csv)" = "$(wc -l < b.csv)" ] || { echo "FAIL: $name $f row counts differ"; exit 1; }
    numdiff -q -r 1e-9 -a 1e-13 -s ',\n' a.csv b.csv > /dev/null ||
      { echo "FAIL: $name $f differs:"; numdiff -r 1e-9 -a 1e-13 -s ',\n' a.csv b.csv | head -20; exit 1; }
    # the largest relative difference, for the record
    largest=$(paste -d, a.csv b.csv | awk -F, 'NR > 1 { n = NF / 2
      for (i = 1; i <= n; ++i) { a = $i; b = $(i + n); s = (a < 0 ? -a : a) + (b < 0 ? -b : b)
        if (s > 1e-13) { d = (a - b) / s * 2; if (d < 0) d = -d; if (d > m) m = d } } }
      END { printf "%.2e", m }')
    echo "$name: $f of the Prony and the expression kernel agree (largest relative difference $largest)"
  done
  # a run named *halving* halves steps
  if [[ $name == *halving* ]]; then
    halvings=$(columns_of "$name-prony/steps.csv" time_step_halvings | awk 'NR > 1 { s += $1 } END { print s + 0 }')
    [ "$halvings" -gt 0 ] || { echo "FAIL: $name halves no step"; exit 1; }
    echo "$name: $halvings halvings"
  fi
  # a run named *adaptive* adapts its mesh
  if [[ $name == *adaptive* ]]; then
    adapted=$(columns_of "$name-prony/steps.csv" adapted | awk 'NR > 1 { s += $1 } END { print s + 0 }')
    [ "$adapted" -gt 0 ] || { echo "FAIL: $name adapts no mesh"; exit 1; }
    echo "$name: $adapted adaptations"
  fi
  # the memory did something: its work is not zero at the end
  last=$(columns_of "$name-prony/steps.csv" memory_work | tail -1)
  awk -v m="$last" 'BEGIN { exit !(m != 0) }' || { echo "FAIL: $name: memory_work is 0"; exit 1; }
done
