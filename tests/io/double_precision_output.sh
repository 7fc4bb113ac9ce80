#!/usr/bin/env bash
# double_precision_output.sh EXE SOURCE_DIR WORKDIR
# 'output/precision = double' writes nodal_NNNNN.h5 and nodal.xdmf beside
# the solution series: at every output time the velocity of the VTU output
# rounded to float, in true double precision (2D, 2 ranks); a run stopped
# and resumed from a checkpoint writes the same collection and bit for bit
# the same values.
set -euo pipefail
exe=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
{
  cat "$src/tests/block_2d_short.prm"
  printf 'subsection time\n  set end time = 0.16\nend\n'
  printf 'subsection output\n  set directory = double\n  set precision = double\n'
  printf '  set output interval = 1\n  set terminal = quiet\nend\n'
} > double.prm
mpirun -np 2 "$exe" double.prm > double.log 2>&1 ||
  { echo "FAIL: run"; cat double.log; exit 1; }

{ cat double.prm; printf 'subsection output\n  set directory = resumed\nend\n'
  printf 'subsection checkpoint\n  set interval = 1\n  set stop after = 2\nend\n'; } > stop.prm
sed 's/set stop after = 2/set stop after = 0/' stop.prm > resume.prm
status=0; mpirun -np 2 "$exe" stop.prm > stop.log 2>&1 || status=$?
[ "$status" -eq 5 ] || { echo "FAIL: the stopped run exited with $status, not 5"; cat stop.log; exit 1; }
mpirun -np 2 "$exe" --resume resume.prm > resume.log 2>&1 ||
  { echo "FAIL: resume"; cat resume.log; exit 1; }

/usr/bin/python3 "$src/tests/io/double_precision_check.py" double resumed
