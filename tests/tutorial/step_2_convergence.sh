#!/usr/bin/env bash
# step_2_convergence.sh STEP_2 SOURCE_DIR WORKDIR
# The convergence table of tutorial/step-2 on three levels of coupled
# refinement equals tests/tutorial/step_2_convergence.output and, as a
# whole, the block under `./step-2 convergence 3` in
# tutorial/step-2/doc/results.md; each of its lines is also in the page's
# four-level table (whose last level comes from 'step-2 convergence 4').
set -euo pipefail
step2=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
"$step2" convergence 3 > convergence.txt 2>&1 ||
  { echo "FAIL: step-2"; cat convergence.txt; exit 1; }
diff -u "$src/tests/tutorial/step_2_convergence.output" convergence.txt ||
  { echo "FAIL: the table differs from the expected output"; exit 1; }
awk -v command='./step-2 convergence 3' \
  -f "$src/tests/tutorial/page_block.awk" "$src/tutorial/step-2/doc/results.md" > page.txt
[ -s page.txt ] || { echo "FAIL: no block after \`./step-2 convergence 3\` in doc/results.md"; exit 1; }
diff -u page.txt convergence.txt ||
  { echo "FAIL: doc/results.md shows another output of 'step-2 convergence 3'"; exit 1; }
while IFS= read -r line; do
  grep -qxF -- "$line" "$src/tutorial/step-2/doc/results.md" ||
    { echo "FAIL: not in doc/results.md: '$line'"; exit 1; }
done < convergence.txt
echo "step-2 convergence table as expected and as in doc/results.md"
