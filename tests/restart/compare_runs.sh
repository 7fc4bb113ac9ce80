#!/usr/bin/env bash
# compare_runs.sh DIR_A DIR_B: the steps.csv and probes.csv of two runs agree
# (step, time, mesh, branch counts exactly; energies and probe values to a
# relative 1e-7), and so do their solution.pvd series. Newton/Krylov counts,
# residuals and wall times are left out: they may differ between MPI rank
# counts while the results agree to solver tolerance.
set -euo pipefail
a=$1; b=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
for f in steps.csv probes.csv; do
  [ -f "$a/$f" ] || continue
  if [ "$f" = steps.csv ]; then fields=1-4,7-11,13-19; else fields=1-; fi
  cut -d, -f$fields "$a/$f" > "$tmp/a"; cut -d, -f$fields "$b/$f" > "$tmp/b"
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
