#!/usr/bin/env bash
# fixed_names.sh EXE PRM WORKDIR
# An output directory in which a name the run writes is taken by something
# else (a file 'checkpoint', a directory 'solution.pvd' or 'steps.csv', a
# file 'earlier_run') is refused at start-up with exit code 2, naming the
# path, and nothing in the directory is touched (not even the lock file is
# created). With the name free, the same run writes its checkpoints.
set -euo pipefail
exe=$1; prm=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
{ cat "$prm"
  printf 'subsection time\n  set time step = 0.04\nend\n'
  printf 'subsection output\n  set directory = out\n  set vtu interval = 5\n'
  printf '  set terminal = quiet\nend\n'
  printf 'subsection checkpoint\n  set interval = 5\nend\n'; } > run.prm

check() { # NAME KIND MESSAGE
  rm -rf out; mkdir out
  if [ "$2" = file ]; then echo "not the run's" > "out/$1"; else mkdir "out/$1"; fi
  before=$(ls -la --time-style=+ out)
  status=0; "$exe" run.prm 2> run.err || status=$?
  [ "$status" -eq 2 ] || { echo "FAIL ($1): exit code $status, not 2"; cat run.err; exit 1; }
  grep -q "input error: output: 'out/$1' $3" run.err ||
    { echo "FAIL ($1): the message does not name the path"; cat run.err; exit 1; }
  [ "$before" = "$(ls -la --time-style=+ out)" ] ||
    { echo "FAIL ($1): the directory was changed"; ls -la out; exit 1; }
  echo "$1 ($2): $(cat run.err)"
}
check checkpoint file "is not a directory"
check earlier_run file "is not a directory"
check solution.pvd directory "is a directory"
check steps.csv directory "is a directory"

rm -rf out
"$exe" run.prm
[ -f out/checkpoint/step-000025.state ] || { echo "FAIL: no checkpoint written"; ls out/checkpoint; exit 1; }
echo "with the names free: checkpoints of steps $(ls out/checkpoint | grep -o '[0-9]*\.state' | tr '\n' ' ')"
