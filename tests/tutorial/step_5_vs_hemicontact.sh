#!/usr/bin/env bash
# step_5_vs_hemicontact.sh HEMICONTACT STEP_5 SOURCE_DIR WORKDIR
# tutorial/step-5 and the full program solve the same static problem (the
# block of step_5_block.prm on the rigid foundation with Coulomb friction,
# four load values) and give the same nodal displacements to 1e-10
# relative, the same fixed-point iterations on the friction bound and the
# same branch counts (step_5_vs_hemicontact.py).
set -euo pipefail
exe=$1; step=$2; src=$3; work=$4
rm -rf "$work"; mkdir -p "$work/step-5"; cd "$work"
"$exe" "$src/tests/tutorial/step_5_block.prm" > hemicontact.log 2>&1 ||
  { echo "FAIL: hemicontact"; cat hemicontact.log; exit 1; }
(cd step-5 && "$step" block > step-5.log 2>&1) ||
  { echo "FAIL: step-5"; cat step-5/step-5.log; exit 1; }
/usr/bin/python3 "$src/tests/tutorial/step_5_vs_hemicontact.py" step-5 hemicontact
