#!/usr/bin/env bash
# gmsh_formats.sh EXE SOURCE_DIR WORKDIR
# The arch example (prm/arch_2d_gmsh.prm, 5 steps) on one mesh written by
# Gmsh in three formats: MSH 4.1 ASCII (the shipped prm/gmsh/arch_2d.msh),
# MSH 2.2 ASCII and MSH 4.1 binary (tests/io/meshes/). The physical groups
# are named; their tags must arrive as boundary ids in every format, and
# the three runs must agree (steps.csv, probes.csv).
set -euo pipefail
exe=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
run() { # NAME MESH
  { sed "s|set mesh file *=.*|set mesh file = $2|" "$src/prm/arch_2d_gmsh.prm"
    printf 'subsection time\n  set end time = 0.05\nend\n'
    printf 'subsection output\n  set directory = %s\n  set vtu interval = 0\n' "$1"
    printf '  set terminal = quiet\nend\n'; } > "$1.prm"
  "$exe" "$1.prm" 2> "$1.err" || { echo "FAIL: the run on $2 failed"; cat "$1.err"; exit 1; }
}
format_of() { sed -n 2p "$1" | cut -c1-7; }
[ "$(format_of "$src/prm/gmsh/arch_2d.msh")" = "4.1 0 8" ] || { echo "FAIL: the shipped mesh is not MSH 4.1 ASCII"; exit 1; }
[ "$(format_of "$src/tests/io/meshes/arch_2d_msh22.msh")" = "2.2 0 8" ] || { echo "FAIL: not MSH 2.2"; exit 1; }
[ "$(format_of "$src/tests/io/meshes/arch_2d_binary.msh")" = "4.1 1 8" ] || { echo "FAIL: not binary MSH 4.1"; exit 1; }
run msh41 "$src/prm/gmsh/arch_2d.msh"
run msh22 "$src/tests/io/meshes/arch_2d_msh22.msh"
run binary "$src/tests/io/meshes/arch_2d_binary.msh"
bash "$src/tests/restart/compare_runs.sh" msh41 msh22
bash "$src/tests/restart/compare_runs.sh" msh41 binary
echo "MSH 4.1 ASCII, MSH 2.2 ASCII and MSH 4.1 binary give the same run"
