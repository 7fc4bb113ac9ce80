#!/usr/bin/env bash
# kill_and_resume.sh EXE PRM WORKDIR SIGNAL
# Start a run that checkpoints every 5 steps, kill it with SIGNAL (TERM,
# INT or KILL) at a random moment, resume it, and compare with an
# uninterrupted run (bitwise). SIGTERM and SIGINT (Ctrl-C) must also leave
# a checkpoint of the step it was in (exit 5).
set -euo pipefail
exe=$1; prm=$2; work=$3; signal=$4
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"; mkdir -p "$work"; cd "$work"
write_prm() { # NAME DIRECTORY
  { cat "$prm"
    printf 'subsection output\n  set directory = %s\n  set vtu interval = 10\n' "$2"
    printf '  set probe points = 4, 0\n  set terminal = quiet\nend\n'
    printf 'subsection checkpoint\n  set interval = 5\nend\n'; } > "$1"
}
write_prm whole.prm whole
write_prm killed.prm killed
"$exe" whole.prm

# kill once the run is past its first checkpoint, at a random later step
# (a step count, not a wait: a fast machine runs the 100 steps in 1 s)
"$exe" killed.prm 2> killed.err & pid=$!
while kill -0 $pid 2> /dev/null && [ ! -f killed/checkpoint/step-000005.state ]; do sleep 0.02; done
at=$((6 + RANDOM % 40))
while kill -0 $pid 2> /dev/null && [ "$(($(wc -l < killed/steps.csv) - 1))" -lt $at ]; do sleep 0.005; done
kill -s "$signal" $pid 2> /dev/null || true
status=0; wait $pid || status=$?
rows=$(($(wc -l < killed/steps.csv) - 1))
echo "killed with SIG$signal after $rows steps (exit status $status)"
# (the signal comes at step 45 of 100 at the latest: a run that ends
# normally has ignored the signal; a shell starts background jobs with
# SIGINT ignored, as the program must not)
if [ "$status" -eq 0 ] && [ "$signal" != KILL ]; then
  echo "FAIL: the run went on to its end after SIG$signal"; exit 1
elif [ "$status" -eq 0 ]; then
  echo "(the run had finished before the signal: nothing to resume)"
else
  if [ "$signal" != KILL ]; then
    [ "$status" -eq 5 ] || { echo "FAIL: SIG$signal gave exit status $status, not 5"; cat killed.err; exit 1; }
    last=$(ls killed/checkpoint | grep '\.state$' | tail -1)
    [ "$last" = "$(printf 'step-%06d.state' "$rows")" ] ||
      { echo "FAIL: SIG$signal left no checkpoint of step $rows (newest: $last)"; exit 1; }
    echo "SIG$signal wrote a checkpoint of step $rows"
  fi
  "$exe" --resume killed.prm
fi
bash "$here/compare_runs.sh" whole killed bitwise
