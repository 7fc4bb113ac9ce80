#!/usr/bin/env bash
# gmsh_simplex.sh EXE SOURCE_DIR WORKDIR
# A triangle mesh read from a Gmsh file (MSH 2.2, physical tags as boundary
# ids) runs on the fully distributed simplex mesh: the short 2D block on 1
# and on 2 ranks gives the same run (compare_runs.sh).
set -euo pipefail
exe=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
# 32 x 8 squares of [0,4] x [0,1], each cut into two triangles along the
# diagonal from its lower left corner; boundary ids 0 (x = 0), 1 (x = 4),
# 2 (y = 0), 3 (y = 1)
/usr/bin/python3 - <<'PY'
nx, ny = 32, 8
node = lambda i, j: 1 + j * (nx + 1) + i
lines, triangles = [], []
for i in range(nx):
    lines.append((2, node(i, 0), node(i + 1, 0)))
    lines.append((3, node(i, ny), node(i + 1, ny)))
for j in range(ny):
    lines.append((0, node(0, j), node(0, j + 1)))
    lines.append((1, node(nx, j), node(nx, j + 1)))
for j in range(ny):
    for i in range(nx):
        a, b, c, d = node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)
        triangles += [(a, b, c), (a, c, d)]
with open("block.msh", "w") as f:
    f.write("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n%d\n" % ((nx + 1) * (ny + 1)))
    for j in range(ny + 1):
        for i in range(nx + 1):
            f.write("%d %.17g %.17g 0\n" % (node(i, j), 4 * i / nx, j / ny))
    f.write("$EndNodes\n$Elements\n%d\n" % (len(lines) + len(triangles)))
    k = 0
    for tag, p, q in lines:
        k += 1
        f.write("%d 1 2 %d %d %d %d\n" % (k, tag, tag, p, q))
    for t in triangles:
        k += 1
        f.write("%d 2 2 10 10 %d %d %d\n" % ((k,) + t))
    f.write("$EndElements\n")
PY
for ranks in 1 2; do
  { cat "$src/tests/block_2d_short.prm"
    printf 'subsection geometry\n  set mesh = gmsh\n  set mesh file = block.msh\n'
    printf '  set cell type = simplex\n  set global refinements = 0\nend\n'
    # the triangles' stability limit of the left-point rule is k <= 0.0437
    printf 'subsection time\n  set time step = 0.04\nend\n'
    printf 'subsection output\n  set directory = np%s\n  set vtu interval = 1\n' "$ranks"
    printf '  set probe points = 4, 0; 2, 0\n  set terminal = quiet\nend\n'; } > np$ranks.prm
  mpirun -np $ranks "$exe" np$ranks.prm > np$ranks.log 2>&1 ||
    { echo "FAIL: the run on $ranks rank(s)"; cat np$ranks.log; exit 1; }
done
bash "$src/tests/restart/compare_runs.sh" np1 np2
echo "the Gmsh triangle mesh gives the same run on 1 and 2 ranks ($(tail -n +2 np2/steps.csv | wc -l) steps, $(sed -n 2p np2/steps.csv | cut -d, -f3) cells)"
