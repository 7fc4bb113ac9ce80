#!/usr/bin/env bash
# compare_runs.sh DIR_A DIR_B [bitwise]: the steps.csv and probes.csv of two
# runs agree (step, time, mesh, branch counts exactly; energies and probe
# values to a relative 1e-7), and so do their solution.pvd series.
# Newton/Krylov counts, residuals and wall times are left out: they may
# differ between MPI rank counts while the results agree to solver
# tolerance. With 'bitwise' (a resume on the number of ranks of the
# interrupted run): every column of steps.csv but the wall time, probes.csv
# and every contact_NNNNN.csv are the same bytes.
set -euo pipefail
a=$1; b=$2; mode=${3:-tolerance}
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
if [ "$mode" = bitwise ]; then
  without_wall() { # FILE: the table without its wall_seconds column
    awk -F, 'BEGIN { OFS = "," } NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "wall_seconds") w = i }
      { line = ""; for (i = 1; i <= NF; ++i) if (i != w) line = line (line == "" ? "" : OFS) $i; print line }' "$1"
  }
  for f in steps.csv probes.csv; do
    [ -f "$a/$f" ] || continue
    without_wall "$a/$f" > "$tmp/a"; without_wall "$b/$f" > "$tmp/b"
    cmp -s "$tmp/a" "$tmp/b" ||
      { echo "FAIL: $f differs:"; diff "$tmp/a" "$tmp/b" | head -6; exit 1; }
    echo "$f: $(($(wc -l < "$tmp/a") - 1)) rows bitwise equal"
  done
  (cd "$a" && ls contact_*.csv 2> /dev/null) > "$tmp/list_a" || true
  (cd "$b" && ls contact_*.csv 2> /dev/null) > "$tmp/list_b" || true
  cmp -s "$tmp/list_a" "$tmp/list_b" || { echo "FAIL: the contact_*.csv files differ in number"; exit 1; }
  while read -r f; do
    cmp -s "$a/$f" "$b/$f" || { echo "FAIL: $f differs"; exit 1; }
  done < "$tmp/list_a"
  echo "contact_*.csv: $(wc -l < "$tmp/list_a") files bitwise equal"
fi
# the compared columns of steps.csv, by name (all columns of probes.csv)
steps_columns="step time n_cells n_dofs n_separating n_normal_stick n_damped n_stick n_slip
  kinetic_energy elastic_energy viscous_dissipation friction_dissipation
  normal_damping_dissipation external_work numerical_dissipation"
columns_of() { # FILE [COLUMN...]: those columns (all if none), in that order
  local file=$1; shift
  awk -F, -v want="$*" 'BEGIN { OFS = "," }
    NR == 1 { n = split(want, w, " "); if (n == 0) for (i = 1; i <= NF; ++i) w[++n] = $i
              for (j = 1; j <= n; ++j) { col[j] = 0
                for (i = 1; i <= NF; ++i) if ($i == w[j]) col[j] = i
                if (col[j] == 0) { print "no column " w[j] " in " FILENAME > "/dev/stderr"; exit 1 } } }
    { line = $col[1]; for (j = 2; j <= n; ++j) line = line OFS $col[j]; print line }' "$file"
}
for f in steps.csv probes.csv; do
  [ -f "$a/$f" ] || continue
  if [ "$f" = steps.csv ]; then columns=$steps_columns; else columns=""; fi
  columns_of "$a/$f" $columns > "$tmp/a"; columns_of "$b/$f" $columns > "$tmp/b"
  if [ "$(wc -l < "$tmp/a")" != "$(wc -l < "$tmp/b")" ]; then
    echo "FAIL: $f has $(wc -l < "$tmp/a") rows in $a but $(wc -l < "$tmp/b") in $b"; exit 1
  fi
  numdiff -q -r 1e-7 -a 1e-10 -s ',\n' "$tmp/a" "$tmp/b" > /dev/null ||
    { echo "FAIL: $f differs:"; numdiff -r 1e-7 -a 1e-10 -s ',\n' "$tmp/a" "$tmp/b" | head -20; exit 1; }
  echo "$f: $(($(wc -l < "$tmp/a") - 1)) rows agree"
done
diff <(grep -o 'file="[^"]*"' "$a/solution.pvd") <(grep -o 'file="[^"]*"' "$b/solution.pvd") > /dev/null ||
  { echo "FAIL: the solution.pvd series differ"; exit 1; }
echo "solution.pvd: same series"
