#!/usr/bin/env bash
# A time step above the stability limit of the left-point rule, run anyway
# with 'time/allow unstable time step = true': the start-up check warns, the
# stored energy outgrows the energy put in (a warning once), and the energy
# check of the summary says no.
set -euo pipefail
exe=$1; prm=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
{ cat "$prm"
  printf 'subsection time\n  set end time = 2\n  set time step = 0.1\n  set allow unstable time step = true\nend\n'
  printf 'subsection output\n  set directory = run\n  set terminal = test\nend\n'; } > run.prm
status=0; "$exe" run.prm > out.log 2> err.log || status=$?
[ "$status" -eq 0 ] || { echo "FAIL: exit $status"; cat err.log; exit 1; }
grep -q "warning: the time step k = 0.1 is above the stability limit" err.log ||
  { echo "FAIL: no start-up warning"; cat err.log; exit 1; }
grep -q "warning: the stored energy E_n = .* times the energy put into the body" err.log ||
  { echo "FAIL: no warning of the energy growth"; cat err.log; exit 1; }
[ "$(grep -c 'warning: the stored energy' err.log)" -eq 1 ] ||
  { echo "FAIL: the growth warning is not given once"; cat err.log; exit 1; }
grep -q "energy defect < 1e-7 relative: no" out.log ||
  { echo "FAIL: the energy check passed an exploding run"; cat out.log; exit 1; }
# the same run without the parameter is refused before it writes anything
{ cat "$prm"
  printf 'subsection time\n  set end time = 2\n  set time step = 0.1\nend\n'
  printf 'subsection output\n  set directory = refused\n  set terminal = quiet\nend\n'; } > refused.prm
status=0; "$exe" refused.prm > /dev/null 2> refused.err || status=$?
[ "$status" -eq 2 ] || { echo "FAIL: exit $status, not 2"; cat refused.err; exit 1; }
[ ! -e refused/steps.csv ] || { echo "FAIL: the refused run wrote steps.csv"; exit 1; }
echo "unstable time step: refused by default; with the parameter warned, growth $(grep -o 'is [0-9.e+]* times' err.log)"
