#!/usr/bin/env bash
# damaged_checkpoint.sh EXE PRM WORKDIR
# A run stopped after 8 steps keeps the checkpoints of steps 6 and 8. The
# newest is damaged (its .mesh file truncated, then its field data changed):
# the resume names the damaged file, falls back to the checkpoint of step 6
# and ends with the same steps.csv, probes.csv and solution.pvd as the
# uninterrupted run. With both checkpoints damaged the resume is refused
# (exit code 2) and names them.
set -euo pipefail
exe=$1; prm=$2; work=$3
here=$(cd "$(dirname "$0")" && pwd)
rm -rf "$work"; mkdir -p "$work"; cd "$work"
write_prm() { # NAME DIRECTORY STOP_AFTER
  { cat "$prm"
    printf 'subsection output\n  set directory = %s\n  set vtu interval = 2\n' "$2"
    printf '  set probe points = 4, 0; 2, 0\n  set terminal = quiet\nend\n'
    printf 'subsection checkpoint\n  set interval = 3\n  set stop after = %s\nend\n' "$3"
    printf 'subsection nonlinear solver\n  set tolerance = 1e-10\nend\n'; } > "$1"
}
write_prm whole.prm whole 0
write_prm stop.prm parts 8
write_prm parts.prm parts 0
"$exe" whole.prm
status=0; "$exe" stop.prm 2> stop.err || status=$?
[ "$status" -eq 5 ] || { echo "FAIL: the stopped run exited with $status, not 5"; cat stop.err; exit 1; }
cp -r parts parts-saved

for damage in truncate flip; do
  rm -rf parts; cp -r parts-saved parts
  if [ $damage = truncate ]; then
    truncate -s 100 parts/checkpoint/step-000008.mesh
  else
    # one byte of the field data changed, the size kept
    printf 'X' | dd of=parts/checkpoint/step-000008.mesh_fixed.data bs=1 seek=200 conv=notrunc 2> /dev/null
  fi
  "$exe" --resume parts.prm 2> resume.err
  grep -q "the checkpoint of step 8 is damaged: 'parts/checkpoint/step-000008.mesh" resume.err ||
    { echo "FAIL ($damage): the damaged checkpoint is not named"; cat resume.err; exit 1; }
  echo "$damage: $(head -1 resume.err)"
  bash "$here/compare_runs.sh" whole parts
done

rm -rf parts; cp -r parts-saved parts
truncate -s 100 parts/checkpoint/step-000008.mesh
truncate -s 0 parts/checkpoint/step-000006.state
status=0; "$exe" --resume parts.prm 2> refused.err || status=$?
[ "$status" -eq 2 ] || { echo "FAIL: resuming from two damaged checkpoints exited with $status, not 2"; cat refused.err; exit 1; }
grep -q "input error: checkpoint: no checkpoint in 'parts/checkpoint' can be resumed from" refused.err ||
  { echo "FAIL: no clear refusal"; cat refused.err; exit 1; }
echo "both damaged: $(tail -1 refused.err)"
