#!/usr/bin/env bash
# mesh_out_of_memory.sh EXE SOURCE_DIR WORKDIR
# A mesh that passes the memory estimate but does not fit into the memory
# the process may use (ulimit -v 700 MB; 'global refinements' = 9 needs
# about 5 GB): exit 2 naming 'geometry/global refinements', for the p4est
# (hypercube) and the simplex mesh. Skipped (exit 77) under AddressSanitizer,
# which reserves more address space than the limit.
set -uo pipefail
exe=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
if ldd "$exe" | grep -q libasan; then echo "AddressSanitizer build: skipped"; exit 77; fi
for cell_type in hypercube simplex; do
  printf 'subsection geometry\n  set cell type = %s\n  set global refinements = 9\nend\n' \
    "$cell_type" > $cell_type.prm
  ( ulimit -v 700000; "$exe" $cell_type.prm > $cell_type.log 2>&1 )
  rc=$?
  [ $rc -eq 2 ] || { echo "FAIL: $cell_type: exit $rc, expected 2"; cat $cell_type.log; exit 1; }
  grep -q "input error: geometry: the mesh needs more memory than there is ('global refinements' = 9 of the rectangle); lower 'geometry/global refinements'" $cell_type.log ||
    { echo "FAIL: $cell_type: message"; cat $cell_type.log; exit 1; }
  echo "$cell_type: $(cat $cell_type.log)"
done
