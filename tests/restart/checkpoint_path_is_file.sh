#!/usr/bin/env bash
# checkpoint_path_is_file.sh EXE PRM WORKDIR
# A file named 'checkpoint' in the output directory, where the checkpoints
# go: the run is refused at its start (exit code 2, the path named) and
# leaves the directory as it was.
set -euo pipefail
exe=$1; prm=$2; work=$3
rm -rf "$work"; mkdir -p "$work/out"; cd "$work"
{ cat "$prm"
  printf 'subsection output\n  set directory = out\n  set terminal = quiet\nend\n'; } > run.prm
echo "an earlier run" > out/steps.csv; echo "a file" > out/checkpoint
before=$(cat out/* | md5sum)
status=0; "$exe" run.prm 2> run.err || status=$?
[ "$status" -eq 2 ] || { echo "FAIL: exit status $status, not 2"; cat run.err; exit 1; }
grep -q "input error: output: 'out/checkpoint' is not a directory, but the run's checkpoints go there" run.err ||
  { echo "FAIL: the path is not named"; cat run.err; exit 1; }
[ "$(cat out/* | md5sum)" = "$before" ] || { echo "FAIL: the refused run changed the output directory"; exit 1; }
echo "refused: $(cat run.err)"
