#!/usr/bin/env bash
# hdf5_output.sh EXE SOURCE_DIR WORKDIR
# 'output/format = hdf5' writes one .h5 file per output time and the
# solution.xdmf series; the fields in it are those of the VTU output of the
# same run (2D, 2 ranks; 3D simplex, 1 rank), and a run resumed from a
# checkpoint continues the series.
set -euo pipefail
exe=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
run() { # NAME RANKS FORMAT BASE END_TIME EXTRA...
  local name=$1 ranks=$2 format=$3 base=$4 end=$5; shift 5
  {
    cat "$src/tests/$base.prm"
    printf 'subsection time\n  set end time = %s\nend\n' "$end"
    printf 'subsection output\n  set directory = %s\n  set format = %s\n' "$name" "$format"
    printf '  set vtu interval = 1\n  set terminal = quiet\nend\n'
    printf '%s\n' "$@"
  } > "$name.prm"
  mpirun -np "$ranks" "$exe" "$name.prm" > "$name.log" 2>&1 ||
    { echo "FAIL: run $name"; cat "$name.log"; exit 1; }
}
run vtu 2 vtu block_2d_short 0.16
run hdf5 2 hdf5 block_2d_short 0.16
for format in vtu hdf5; do
  run ${format}_simplex 1 $format block_3d_short 0.06 \
    'subsection geometry' '  set cell type = simplex' '  set global refinements = 1' 'end'
done
/usr/bin/python3 "$src/tests/io/hdf5_vs_vtu.py" vtu hdf5
/usr/bin/python3 "$src/tests/io/hdf5_vs_vtu.py" vtu_simplex hdf5_simplex

# stopped after step 2 (exit code 5) and resumed: the same series
{ cat hdf5.prm; printf 'subsection output\n  set directory = resumed\nend\n'
  printf 'subsection checkpoint\n  set interval = 1\n  set stop after = 2\nend\n'; } > stop.prm
sed 's/set stop after = 2/set stop after = 0/' stop.prm > resume.prm
status=0; mpirun -np 2 "$exe" stop.prm > stop.log 2>&1 || status=$?
[ "$status" -eq 5 ] || { echo "FAIL: the stopped run exited with $status, not 5"; cat stop.log; exit 1; }
mpirun -np 2 "$exe" --resume resume.prm > resume.log 2>&1 ||
  { echo "FAIL: resume"; cat resume.log; exit 1; }
cmp <(grep -o 'Time Value="[^"]*"' hdf5/solution.xdmf) \
    <(grep -o 'Time Value="[^"]*"' resumed/solution.xdmf) ||
  { echo "FAIL: the resumed series differs"; exit 1; }
echo "resumed run: solution.xdmf lists the same $(grep -c 'Time Value' resumed/solution.xdmf) output times"
echo "HDF5/XDMF output holds the fields of the VTU output"
