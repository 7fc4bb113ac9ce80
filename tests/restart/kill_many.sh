#!/usr/bin/env bash
# kill_many.sh EXE PRM WORKDIR [KILLS]
# KILLS times (default 20): start a run that writes a checkpoint after
# every step (so that many kills land while a checkpoint is written), kill
# it with SIGKILL at a random moment after its first checkpoint, resume it to the end (or
# start it again if it was killed before its first checkpoint), and check
# that it ends bitwise equal to the uninterrupted run (default solver
# settings: a checkpoint holds everything the next step reads, the
# preconditioner's state included). CI runs a few kills; the full
# run by hand:
#   bash tests/restart/kill_many.sh build/hemicontact prm/block_2d.prm /tmp/kills 20
set -euo pipefail
exe=$1; prm=$2; work=$3; kills=${4:-20}
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"; mkdir -p "$work"; cd "$work"
write_prm() { # NAME DIRECTORY
  { cat "$prm"
    printf 'subsection output\n  set directory = %s\n  set vtu interval = 4\n' "$2"
    printf '  set terminal = quiet\nend\n'
    printf 'subsection checkpoint\n  set interval = 1\nend\n'; } > "$1"
}
write_prm whole.prm whole
write_prm killed.prm killed
start=$(date +%s%N); "$exe" whole.prm; span=$((($(date +%s%N) - start) / 1000000))
echo "uninterrupted run: $span ms"

landed=0; resumed=0; restarted=0
for trial in $(seq 1 "$kills"); do
  rm -rf killed
  "$exe" killed.prm 2> killed.err & pid=$!
  # from its first checkpoint on, a random moment of about the time the
  # steps take (the start-up before is not what this tests)
  while kill -0 $pid 2> /dev/null && ! ls killed/checkpoint/step-*.state > /dev/null 2>&1; do
    sleep 0.01
  done
  sleep "$(awk -v s="$RANDOM" -v span="$span" 'BEGIN { printf "%.3f", (s % 1000) / 1000 * span / 1500 }')"
  kill -KILL $pid 2> /dev/null && landed=$((landed + 1)) || true
  status=0; wait $pid 2> /dev/null || status=$?
  if [ $status -ne 0 ]; then
    [ $status -eq 137 ] || { echo "FAIL: exit status $status after SIGKILL"; cat killed.err; exit 1; }
    if ls killed/checkpoint/step-*.state > /dev/null 2>&1; then
      "$exe" --resume killed.prm 2> resume.err ||
        { echo "FAIL: trial $trial: the resume failed"; cat resume.err; exit 1; }
      resumed=$((resumed + 1))
    else
      "$exe" killed.prm; restarted=$((restarted + 1))
    fi
  fi
  bash "$here/compare_runs.sh" whole killed bitwise > compare.log ||
    { echo "FAIL: trial $trial differs from the uninterrupted run"; cat compare.log; exit 1; }
done
echo "$kills trials: $landed SIGKILLs during the run, $resumed resumed, $restarted started again (killed before the first checkpoint); every run ends bitwise equal to the uninterrupted one"
