#!/usr/bin/env bash
# step_4_vs_hemicontact.sh HEMICONTACT STEP_4 SOURCE_DIR WORKDIR
# tutorial/step-4 and the full program solve the same static problem (the
# L-shaped body of step_4_l_shape.prm) on the same sequence of meshes,
# adapted by the same error estimate: ten cycles of step-4's adaptive
# loop against ten load values of the full program's static class with
# 'indicator = estimator'. step_4_vs_hemicontact.py checks that the meshes
# are the same and compares the nodal displacements, the energy J_h(u_h)
# and the estimate with its four parts, each to 1e-10 relative.
set -euo pipefail
exe=$1; step=$2; src=$3; work=$4
rm -rf "$work"; mkdir -p "$work/step-4" "$work/prm/gmsh"; cd "$work"
cp "$src/prm/gmsh/l_shape.msh" prm/gmsh/
"$exe" "$src/tests/tutorial/step_4_l_shape.prm" > hemicontact.log 2>&1 ||
  { echo "FAIL: hemicontact"; cat hemicontact.log; exit 1; }
(cd step-4 && "$step" adaptive 10 > step-4.log 2>&1) ||
  { echo "FAIL: step-4 adaptive 10"; cat step-4/step-4.log; exit 1; }
/usr/bin/python3 "$src/tests/tutorial/step_4_vs_hemicontact.py" step-4 hemicontact 10
