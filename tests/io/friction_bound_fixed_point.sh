#!/usr/bin/env bash
# A friction bound in the step's own unknown (doc/theory.md, section 9.8):
# in the static class a bound in u_nu is found by fixed-point iterations.
# 1. F_b = 0.6 + 2 pos(u_nu): the run converges, steps.csv counts the
#    iterations (more than one where the bound changes), and at every
#    contact node of the last load value the bound used equals the bound of
#    the solution to the tolerance.
# 2. A bound that does not settle (3 + 2.9 sin(2000 u_nu)): exit code 3 and
#    a message naming the fixed point and its tolerance parameter.
set -euo pipefail
exe=$1; prm=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
write_prm() { # NAME BOUND
  { cat "$prm"
    printf 'subsection data\n  set friction bound = %s\nend\n' "$2"
    printf 'subsection output\n  set directory = %s\n  set output interval = 10\nend\n' "$1"; } > "$1.prm"
}
write_prm settles "0.6 + 2*pos(u_nu)"
write_prm oscillates "3 + 2.9*sin(2000*u_nu)"
"$exe" settles.prm > settles.out 2> settles.err ||
  { echo "FAIL: the settling bound failed"; cat settles.err; exit 1; }
/usr/bin/python3 - settles <<'PY'
import csv, sys
d = sys.argv[1]
rows = list(csv.DictReader(open(d + "/steps.csv")))
counts = [int(r["bound_iterations"]) for r in rows]
assert min(counts) >= 1, ("a load value without the fixed point", counts)
assert max(counts) > 1, ("the bound never iterated", counts)
nodes = list(csv.DictReader(open(d + "/contact_00010.csv")))
largest = max(float(n["friction_bound"]) for n in nodes)
worst = max(abs(float(n["friction_bound"]) - (0.6 + 2 * max(float(n["u_nu"]), 0)))
            for n in nodes)
assert worst <= 1e-6 * largest, ("bound and solution disagree", worst)
print("settles: %d load values, fixed-point iterations %d to %d, the bound "
      "of the solution at every node to 1e-6: yes" % (len(rows), min(counts), max(counts)))
PY
set +e
"$exe" oscillates.prm > oscillates.out 2> oscillates.err
code=$?
set -e
[ "$code" -eq 3 ] || { echo "FAIL: exit code $code, expected 3"; cat oscillates.err; exit 1; }
grep -q "did not settle: after .* fixed-point iterations .*'nonlinear solver/friction bound tolerance'" oscillates.err ||
  { echo "FAIL: the message does not name the fixed point"; cat oscillates.err; exit 1; }
echo "oscillates: exit code 3, the fixed point named"
