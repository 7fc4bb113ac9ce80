#!/usr/bin/env bash
# resume_changed_problem.sh EXE PRM WORKDIR
# A run stopped after 6 steps is resumed from a parameter file that changes
# the problem (the normal law and the mesh refinement): the resume is
# refused with exit code 2, naming each changed entry, and leaves the
# checkpoint and steps.csv as they were; a resume with the run's own file
# (a changed output or solver setting is allowed) then succeeds.
set -euo pipefail
exe=$1; prm=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
{ cat "$prm"
  printf 'subsection output\n  set directory = run\n  set terminal = quiet\nend\n'
  printf 'subsection checkpoint\n  set interval = 3\n  set stop after = 6\nend\n'; } > run.prm
status=0; "$exe" run.prm 2> stop.err || status=$?
[ "$status" -eq 5 ] || { echo "FAIL: the stopped run exited with $status, not 5"; cat stop.err; exit 1; }
before=$(cat run/steps.csv run/checkpoint/* | md5sum)

{ cat run.prm
  printf 'subsection normal law\n  set law = linear damping\nend\n'
  printf 'subsection geometry\n  set global refinements = 2\nend\n'
  printf 'subsection checkpoint\n  set stop after = 0\nend\n'; } > changed.prm
status=0; "$exe" --resume changed.prm 2> changed.err || status=$?
[ "$status" -eq 2 ] || { echo "FAIL: the changed resume exited with $status, not 2"; cat changed.err; exit 1; }
for entry in "normal law/law = 'linear damping' (the checkpoint's run: 'exponential')" \
             "geometry/global refinements = '2' (the checkpoint's run: '3')"; do
  grep -qF "$entry" changed.err || { echo "FAIL: the message does not name: $entry"; cat changed.err; exit 1; }
done
[ "$(cat run/steps.csv run/checkpoint/* | md5sum)" = "$before" ] ||
  { echo "FAIL: the refused resume changed the checkpoint or steps.csv"; exit 1; }
echo "refused: $(cat changed.err)"

{ cat run.prm
  printf 'subsection checkpoint\n  set stop after = 0\nend\n'
  printf 'subsection nonlinear solver\n  set tolerance = 1e-10\nend\n'; } > same.prm
"$exe" --resume same.prm
rows=$(($(wc -l < run/steps.csv) - 1))
# one row per step, the last at the end time 1
[ "$(cut -d, -f1 run/steps.csv | tail -n +2 | tr '\n' ' ')" = "$(seq -s ' ' 1 "$rows") " ] &&
  [ "$(tail -1 run/steps.csv | cut -d, -f2)" = 1 ] ||
  { echo "FAIL: the resumed run's steps.csv does not end at t = 1 with one row per step"; exit 1; }
echo "resumed with the same problem: $rows steps"
