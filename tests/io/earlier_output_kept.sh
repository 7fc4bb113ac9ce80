#!/usr/bin/env bash
# earlier_output_kept.sh EXE PRM WORKDIR STUDY_PRM
# A run that stops on bad data at its first step, in a directory holding an
# earlier run's results, leaves every file of that directory as it was
# (steps.csv, probes.csv, solution.pvd, the solution and contact files),
# on 1 and on 2 MPI ranks;
# so does such a run after one killed before its first step (which left the
# earlier files in earlier_run/); a run that completes leaves only its own
# files and no earlier_run/. A convergence study that stops on bad data
# leaves an earlier convergence.csv as it was.
set -euo pipefail
exe=$1; prm=$2; work=$3; study_prm=$(realpath "$4")
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
rm -rf "$work"; mkdir -p "$work"; cd "$work"
{ cat "$prm"
  printf 'subsection time\n  set time step = 0.04\nend\n'
  printf 'subsection output\n  set directory = out\n  set vtu interval = 5\n'
  printf '  set probe points = 4, 0\n  set terminal = quiet\nend\n'; } > good.prm
{ cat good.prm; printf 'subsection data\n  set body force = 0; sqrt(t - 0.1)\nend\n'; } > bad.prm

"$exe" good.prm
cp -a out earlier
status=0; "$exe" bad.prm 2> bad.err || status=$?
[ "$status" -eq 2 ] || { echo "FAIL: the bad run exited with $status, not 2"; cat bad.err; exit 1; }
grep -q "input error: data: 'body force'" bad.err || { echo "FAIL: no input error"; cat bad.err; exit 1; }
diff -r earlier out || { echo "FAIL: the bad run changed the earlier run's files"; exit 1; }
echo "bad data at step 1: exit 2, the earlier run's $(ls out | wc -l) files unchanged"
# the same on 2 MPI ranks (each writes its own piece of solution_00000)
status=0; mpirun -np 2 "$exe" bad.prm > /dev/null 2> bad.err || status=$?
[ "$status" -ne 0 ] || { echo "FAIL: the bad run on 2 ranks succeeded"; exit 1; }
grep -q "input error: data: 'body force'" bad.err || { echo "FAIL: no input error on 2 ranks"; cat bad.err; exit 1; }
diff -r earlier out || { echo "FAIL: the bad run on 2 ranks changed the earlier run's files"; exit 1; }
echo "the same on 2 ranks: the earlier files unchanged"

# a run killed before its first step (a large mesh: the first step takes a
# while), then the bad run: the earlier files come back
{ cat good.prm
  printf 'subsection geometry\n  set global refinements = 6\nend\n'
  printf 'subsection time\n  set time step = 0.01\nend\n'; } > slow.prm
"$exe" slow.prm & pid=$!
while [ ! -f out/earlier_run/steps.csv ] || [ ! -f out/steps.csv ]; do
  kill -0 $pid 2> /dev/null || { echo "FAIL: the slow run ended"; exit 1; }
  sleep 0.02
done
kill -KILL $pid; wait $pid 2> /dev/null || true
if [ -d out/earlier_run ]; then
  [ "$(ls out/earlier_run | wc -l)" -eq "$(ls earlier | wc -l)" ] ||
    { echo "FAIL: earlier_run/ does not hold the earlier run's files"; ls out/earlier_run; exit 1; }
  status=0; "$exe" bad.prm 2> bad.err || status=$?
  [ "$status" -eq 2 ] || { echo "FAIL: the bad run after the kill exited with $status"; cat bad.err; exit 1; }
  diff -r earlier out || { echo "FAIL: after a killed run and a bad run the earlier files are not back"; exit 1; }
  echo "killed before step 1, then bad data: the earlier run's files are back"
else
  echo "the kill came after the first step: that part is not checked this time"
fi

# a run that completes: its own files only
sed 's/vtu interval = 5/vtu interval = 10/' good.prm > other.prm
"$exe" other.prm
[ ! -e out/earlier_run ] || { echo "FAIL: earlier_run/ left after a complete run"; exit 1; }
[ ! -e out/solution_00005.pvtu ] || { echo "FAIL: a solution file of the earlier run is left"; exit 1; }
[ "$(grep -c DataSet out/solution.pvd)" -eq 4 ] || { echo "FAIL: solution.pvd"; cat out/solution.pvd; exit 1; }
[ "$(wc -l < out/steps.csv)" -eq 26 ] || { echo "FAIL: steps.csv has $(wc -l < out/steps.csv) lines"; exit 1; }
echo "a complete run: its own files, no earlier_run/"

# a convergence study with data that are not finite at its first step
{ cat "$study_prm"
  printf 'subsection geometry\n  set global refinements = 2\nend\n'
  printf 'subsection time\n  set time step = 0.25\nend\n'
  printf 'subsection convergence study\n  set levels = 2\nend\n'
  printf 'subsection output\n  set directory = study\nend\n'; } > study.prm
{ cat study.prm
  printf 'subsection manufactured solution\n'
  printf '  set exact displacement = (1-y)*x*sqrt(0.1 - t); 0\nend\n'; } > bad_study.prm
"$exe" study.prm > /dev/null
cp study/convergence.csv earlier_convergence.csv
status=0; "$exe" bad_study.prm > /dev/null 2> bad_study.err || status=$?
[ "$status" -eq 2 ] || { echo "FAIL: the bad study exited with $status, not 2"; cat bad_study.err; exit 1; }
cmp earlier_convergence.csv study/convergence.csv ||
  { echo "FAIL: the bad study changed convergence.csv"; cat study/convergence.csv; exit 1; }
[ "$(ls study)" = convergence.csv ] || { echo "FAIL: files left: $(ls study)"; exit 1; }
echo "bad data in a study: exit 2, convergence.csv ($(wc -l < study/convergence.csv) lines) unchanged"
