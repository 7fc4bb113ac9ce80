#!/usr/bin/env bash
# step_3_convergence.sh STEP_3 SOURCE_DIR WORKDIR
# The two tables of tutorial/step-3 on three levels (h and k refined
# together; the order in k alone on one mesh) equal
# tests/tutorial/step_3_convergence.output and, as a whole, the block under
# `./step-3 convergence 3` in tutorial/step-3/doc/results.md; each of their
# lines is also in the page's five-level tables (from 'step-3 convergence
# 5'), so the page's numbers are what the program computes.
set -euo pipefail
step=$1; src=$2; work=$3
page=$src/tutorial/step-3/doc/results.md
rm -rf "$work"; mkdir -p "$work"; cd "$work"
"$step" convergence 3 > convergence.txt 2>&1 ||
  { echo "FAIL: step-3"; cat convergence.txt; exit 1; }
diff -u "$src/tests/tutorial/step_3_convergence.output" convergence.txt ||
  { echo "FAIL: the tables differ from the expected output"; exit 1; }
awk -v command='./step-3 convergence 3' \
  -f "$src/tests/tutorial/page_block.awk" "$page" > page.txt
[ -s page.txt ] || { echo "FAIL: no block after \`./step-3 convergence 3\` in doc/results.md"; exit 1; }
diff -u page.txt convergence.txt ||
  { echo "FAIL: doc/results.md shows another output of 'step-3 convergence 3'"; exit 1; }
awk -v command='./step-3 convergence 5' \
  -f "$src/tests/tutorial/page_block.awk" "$page" > page5.txt
while IFS= read -r line; do
  grep -qxF -- "$line" page5.txt ||
    { echo "FAIL: not in the five-level tables of doc/results.md: '$line'"; exit 1; }
done < convergence.txt
echo "step-3 convergence tables as expected and as in doc/results.md"
