#!/usr/bin/env bash
# resume_changed_output.sh EXE PRM WORKDIR
# A run writing VTU (series solution.pvd) stopped after 6 steps is resumed
# with 'output/format = hdf5', and then with 'output/precision = double':
# each resume is refused with exit code 2, naming the entry with both
# values, and leaves every file of the output directory as it was (one
# series per run, never two halves); a resume with the run's own format
# then continues solution.pvd to the end time.
set -euo pipefail
exe=$1; prm=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
{ cat "$prm"
  printf 'subsection output\n  set directory = run\n  set terminal = quiet\n'
  printf '  set format = vtu\n  set output interval = 2\nend\n'
  printf 'subsection checkpoint\n  set interval = 3\n  set stop after = 6\nend\n'; } > run.prm
status=0; "$exe" run.prm 2> stop.err || status=$?
[ "$status" -eq 5 ] || { echo "FAIL: the stopped run exited with $status, not 5"; cat stop.err; exit 1; }
listing() { (cd run && find . -type f ! -name '*.lock' | sort | xargs md5sum); }
before=$(listing)

for change in "format = hdf5|output/format = 'hdf5' (the checkpoint's run: 'vtu')" \
              "precision = double|output/precision = 'double' (the checkpoint's run: 'float')"; do
  entry=${change%%|*}; named=${change#*|}
  { cat run.prm
    printf 'subsection output\n  set %s\nend\n' "$entry"
    printf 'subsection checkpoint\n  set stop after = 0\nend\n'; } > changed.prm
  status=0; "$exe" --resume changed.prm > changed.out 2> changed.err || status=$?
  [ "$status" -eq 2 ] || { echo "FAIL: the resume with '$entry' exited with $status, not 2"; cat changed.err; exit 1; }
  grep -qF "$named" changed.err || { echo "FAIL: the message does not name: $named"; cat changed.err; exit 1; }
  [ "$(listing)" = "$before" ] ||
    { echo "FAIL: the refused resume with '$entry' changed the output directory"; exit 1; }
  [ ! -e run/solution.xdmf ] && [ ! -e run/nodal.xdmf ] ||
    { echo "FAIL: the refused resume with '$entry' started another series"; exit 1; }
  echo "refused: $(cat changed.err)"
done

{ cat run.prm
  printf 'subsection checkpoint\n  set stop after = 0\nend\n'; } > same.prm
"$exe" --resume same.prm
# solution.pvd lists every output time of the run: 0, 2, ..., 24 steps of
# k = 0.04 from t = 0 and the last at t = 1
times=$(grep -o 'timestep="[^"]*"' run/solution.pvd | cut -d'"' -f2 | tr '\n' ' ')
expected=$(for s in $(seq 0 2 24) 25; do awk -v s="$s" 'BEGIN { printf "%g ", s * 0.04 }'; done)
[ "$times" = "$expected" ] ||
  { echo "FAIL: solution.pvd lists '$times', not '$expected'"; exit 1; }
[ ! -e run/solution.xdmf ] || { echo "FAIL: the resumed run wrote solution.xdmf"; exit 1; }
echo "resumed with the run's own format: solution.pvd lists $(echo $times | wc -w) output times"
