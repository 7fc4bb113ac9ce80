#!/usr/bin/env bash
# A friction bound that grows with u_nu raises the slip-rate-weakening law's
# alpha_tau during the run: the convexity check is repeated where it grows,
# and the step that leaves the convex regime is named (a warning, or exit 3
# with 'strict convexity check').
set -euo pipefail
exe=$1; prm=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
make_prm() { # NAME STRICT
  { cat "$prm"
    printf 'subsection data\n  set friction bound = 0.3 + 40*pos(u_nu)\nend\n'
    printf 'subsection nonlinear solver\n  set strict convexity check = %s\nend\n' "$2"
    printf 'subsection output\n  set directory = %s\n  set terminal = test\nend\n' "$1"; } > "$1.prm"
}
make_prm warn false
status=0; "$exe" warn.prm > warn.out 2> warn.err || status=$?
grep -q "convexity: alpha_nu = 5, alpha_tau <= 0.3.* -> each step is strongly convex" warn.out ||
  { echo "FAIL: the start was not convex"; cat warn.out; exit 1; }
grep -q "warning: at t = [0-9.e+-]* (the friction bound or the mesh changed since the last convexity check) the step energy J_n is not convex" warn.err ||
  { echo "FAIL: no warning when the step left the convex regime (exit $status)"; cat warn.err; exit 1; }
[ "$(grep -c 'the step energy J_n is not convex' warn.err)" -eq 1 ] ||
  { echo "FAIL: a step that stays non-convex is named more than once"; cat warn.err; exit 1; }
make_prm strict true
status=0; "$exe" strict.prm > strict.out 2> strict.err || status=$?
[ "$status" -eq 3 ] || { echo "FAIL: exit $status with strict convexity check, not 3"; cat strict.err; exit 1; }
grep -q "solver failure: step [0-9]* (t = [0-9.]*) failed: at t = .* the step energy J_n is not convex" strict.err ||
  { echo "FAIL: no clear message"; cat strict.err; exit 1; }
echo "left the convex regime: $(grep -o 'at t = [0-9.e+-]*' warn.err | head -1)"
