#!/usr/bin/env bash
# stale_checkpoints.sh EXE PRM WORKDIR
# Runs without --resume in a directory that holds the checkpoints of an
# earlier run: the later run's checkpoints replace the earlier run's (its
# newest is the one it names when stopped, and --resume continues it,
# bitwise equal to the uninterrupted later run); a run that stops before
# its first checkpoint leaves the directory to itself: --resume then
# refuses the checkpoints of the run before it (exit 2) instead of mixing
# both runs' output.
set -euo pipefail
exe=$1; prm=$2; work=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"; mkdir -p "$work"; cd "$work"
write_prm() { # NAME DIRECTORY INTERVAL STOP_AFTER [FRICTION_BOUND]
  { cat "$prm"
    printf 'subsection output\n  set directory = %s\n  set vtu interval = 2\n' "$2"
    printf '  set probe points = 4, 0; 2, 0\n  set terminal = quiet\nend\n'
    printf 'subsection checkpoint\n  set interval = %s\n  set stop after = %s\nend\n' "$3" "$4"
    [ -z "${5:-}" ] || printf 'subsection data\n  set friction bound = %s\nend\n' "$5"; } > "$1"
}
states() { ls out/checkpoint | grep '\.state$' | tr '\n' ' '; }
write_prm earlier.prm out 5 0 0.5
write_prm later_stop.prm out 3 4
write_prm later.prm out 3 0
write_prm whole.prm whole 3 0
write_prm failing.prm out 3 0 '0.6 - 10*t'

"$exe" earlier.prm
echo "earlier run: checkpoints $(states)"
[ -f out/checkpoint/step-000025.state ] || { echo "FAIL: the earlier run left no checkpoint of step 25"; exit 1; }

status=0; "$exe" later_stop.prm 2> stop.err || status=$?
[ "$status" -eq 5 ] || { echo "FAIL: the later run exited with $status, not 5"; cat stop.err; exit 1; }
grep -q "a checkpoint was written" stop.err || { echo "FAIL: no checkpoint named"; cat stop.err; exit 1; }
[ "$(states)" = "step-000003.state step-000004.state " ] ||
  { echo "FAIL: after the later run's checkpoints the directory holds $(states)"; exit 1; }
echo "later run stopped after step 4: checkpoints $(states)"
"$exe" --resume later.prm 2> resume.err || { echo "FAIL: the resume failed"; cat resume.err; exit 1; }
"$exe" whole.prm
bash "$here/compare_runs.sh" whole out bitwise

# a run that stops at its second step, before its first checkpoint
status=0; "$exe" failing.prm 2> failing.err || status=$?
[ "$status" -eq 2 ] || { echo "FAIL: the failing run exited with $status, not 2"; cat failing.err; exit 1; }
cp out/steps.csv steps-before.csv
status=0; "$exe" --resume later.prm 2> refused.err || status=$?
[ "$status" -eq 2 ] || { echo "FAIL: resuming an earlier run's checkpoint exited with $status, not 2"; cat refused.err; exit 1; }
grep -q "input error: checkpoint: no checkpoint in 'out/checkpoint' can be resumed from: 'out/checkpoint/step-0000[0-9]*.state' is of another run than the output in 'out'" refused.err ||
  { echo "FAIL: no clear refusal"; cat refused.err; exit 1; }
cmp -s steps-before.csv out/steps.csv || { echo "FAIL: the refused resume changed steps.csv"; exit 1; }
echo "after a run without checkpoints: $(tail -1 refused.err)"
