#!/usr/bin/env bash
# step_3_vs_hemicontact.sh HEMICONTACT STEP_3 SOURCE_DIR WORKDIR
# tutorial/step-3 and the full program solve the same static problem with
# long memory (the block of step_3_block.prm: a Prony relaxation kernel and
# memory in the normal response, 17 load values) and give the same nodal
# displacements to 1e-10 relative, with the same branch counts
# (step_3_vs_hemicontact.py).
set -euo pipefail
exe=$1; step=$2; src=$3; work=$4
rm -rf "$work"; mkdir -p "$work/step-3"; cd "$work"
"$exe" "$src/tests/tutorial/step_3_block.prm" > hemicontact.log 2>&1 ||
  { echo "FAIL: hemicontact"; cat hemicontact.log; exit 1; }
(cd step-3 && "$step" block > step-3.log 2>&1) ||
  { echo "FAIL: step-3"; cat step-3/step-3.log; exit 1; }
/usr/bin/python3 "$src/tests/tutorial/step_3_vs_hemicontact.py" \
  step-3 hemicontact step-3/step-3.log
