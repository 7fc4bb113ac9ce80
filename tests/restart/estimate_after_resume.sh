#!/usr/bin/env bash
# estimate_after_resume.sh EXE PRM WORKDIR: a run stopped after 6 steps
# without 'output/error estimate' and resumed with it sums the estimate of
# the steps it solved only, and its summary says so ("error estimate of
# steps 7 to N only, not of the whole run of N steps"); the uninterrupted
# run with the estimate sums every step and says nothing of the kind.
set -euo pipefail
exe=$1; prm=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
write_prm() { # NAME DIRECTORY STOP_AFTER ESTIMATE
  { cat "$prm"
    printf 'subsection output\n  set directory = %s\n  set terminal = test\n  set error estimate = %s\nend\n' "$2" "$4"
    printf 'subsection checkpoint\n  set interval = 3\n  set stop after = %s\nend\n' "$3"; } > "$1"
}
write_prm whole.prm whole 0 true
write_prm stop.prm parts 6 false
write_prm parts.prm parts 0 true
"$exe" whole.prm > whole.log 2>&1
status=0; "$exe" stop.prm > stop.log 2>&1 || status=$?
[ "$status" -eq 5 ] || { echo "FAIL: the stopped run exited with $status, not 5"; cat stop.log; exit 1; }
"$exe" --resume parts.prm > parts.log 2>&1
n=$(grep -o "done: [0-9]* steps" whole.log | grep -o "[0-9]*")
grep -q "^error estimate (energy norm" whole.log ||
  { echo "FAIL: the whole run's summary has no estimate line"; cat whole.log; exit 1; }
if grep -q "only, not of the whole run" whole.log; then
  echo "FAIL: the whole run's estimate is called partial"; cat whole.log; exit 1
fi
grep -q "^error estimate of steps 7 to $n only, not of the whole run of $n steps" parts.log ||
  { echo "FAIL: the resumed run's summary does not name the steps it covers"; cat parts.log; exit 1; }
grep "error estimate" parts.log
