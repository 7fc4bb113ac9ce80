#!/usr/bin/env bash
# step_2_vs_hemicontact.sh HEMICONTACT STEP_2 SOURCE_DIR WORKDIR
# tutorial/step-2 and the full program solve the same problem (the block of
# tests/block_2d_short.prm: 32 x 8 cells, k = 0.04, 25 steps of the dynamic
# class with the left-point rule, the exponential law and Tresca friction)
# and agree on w_n and u_n at every node and every step to 1e-10 relative
# (double-precision nodal output of both), with the same branch counts; the
# run visits every branch (separating, normal stick, damped, stick, slip).
set -euo pipefail
hemicontact=$1; step2=$2; src=$3; work=$4
rm -rf "$work"; mkdir -p "$work"; cd "$work"
{
  cat "$src/tests/block_2d_short.prm"
  printf 'subsection nonlinear solver\n  set tolerance = 1e-12\nend\n'
  printf 'subsection linear solver\n  set type = direct\n  set relative tolerance = 1e-13\nend\n'
  printf 'subsection output\n  set directory = hemicontact\n  set precision = double\n'
  printf '  set output interval = 1\n  set terminal = quiet\nend\n'
} > block.prm
"$hemicontact" block.prm > hemicontact.log 2>&1 ||
  { echo "FAIL: hemicontact"; cat hemicontact.log; exit 1; }
mkdir step-2
(cd step-2 && "$step2" block > ../step-2.log 2>&1) ||
  { echo "FAIL: step-2"; cat step-2.log; exit 1; }
/usr/bin/python3 "$src/tests/tutorial/step_2_vs_hemicontact.py" \
  hemicontact step-2 step-2.log
