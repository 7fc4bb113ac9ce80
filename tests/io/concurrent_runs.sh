#!/usr/bin/env bash
# concurrent_runs.sh EXE PRM WORKDIR
# A second run started on the same output directory while a first one
# writes it is refused (exit code 2, the directory named) and changes
# nothing: the first run ends with all its rows. A run after the first
# has ended (or was killed) may use the directory again.
set -euo pipefail
exe=$1; prm=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
{ cat "$prm"
  printf 'subsection geometry\n  set global refinements = 5\nend\n'
  printf 'subsection time\n  set end time = 6\n  set time step = 0.04\nend\n'
  printf 'subsection output\n  set directory = shared\n  set terminal = quiet\nend\n'; } > run.prm
"$exe" run.prm & first=$!
while [ ! -s shared/steps.csv ]; do
  kill -0 $first 2> /dev/null || { echo "FAIL: the first run ended before writing a row"; exit 1; }
  sleep 0.05
done
status=0; "$exe" run.prm 2> second.err || status=$?
kill -0 $first 2> /dev/null || { echo "FAIL: the first run ended before the second was refused (too short)"; exit 1; }
[ "$status" -eq 2 ] || { echo "FAIL: the second run exited with $status, not 2"; cat second.err; kill $first; exit 1; }
grep -q "input error: output: another hemicontact run is writing into 'shared'" second.err ||
  { echo "FAIL: no clear refusal"; cat second.err; kill $first; exit 1; }
wait $first
rows=$(($(wc -l < shared/steps.csv) - 1))
[ "$rows" -eq 150 ] || { echo "FAIL: the first run wrote $rows rows, not 150"; exit 1; }
echo "refused: $(cat second.err)"
# a killed run leaves no lock behind
rm shared/steps.csv
"$exe" run.prm & pid=$!
while [ ! -s shared/steps.csv ]; do sleep 0.05; done
kill -KILL $pid; wait $pid 2> /dev/null || true
{ cat run.prm; printf 'subsection time\n  set end time = 0.48\nend\n'; } > short.prm
"$exe" short.prm
echo "after the first run and after a killed run the directory is free again"
