#!/usr/bin/env bash
# step_1_vs_hemicontact.sh HEMICONTACT STEP_1 SOURCE_DIR WORKDIR
# tutorial/step-1 and the full program solve the same static problem (the
# block of step_1_block.prm, four load values) and give the same nodal
# displacements to 1e-10 relative (step_1_vs_hemicontact.py).
set -euo pipefail
exe=$1; step=$2; src=$3; work=$4
rm -rf "$work"; mkdir -p "$work/step-1"; cd "$work"
"$exe" "$src/tests/tutorial/step_1_block.prm" > hemicontact.log 2>&1 ||
  { echo "FAIL: hemicontact"; cat hemicontact.log; exit 1; }
(cd step-1 && "$step" > step-1.log 2>&1) ||
  { echo "FAIL: step-1"; cat step-1/step-1.log; exit 1; }
/usr/bin/python3 "$src/tests/tutorial/step_1_vs_hemicontact.py" step-1 hemicontact
