#!/usr/bin/env bash
# step_1_results.sh STEP_1 SOURCE_DIR WORKDIR
# tutorial/step-1 prints exactly the output shown in its results section
# (the text block after "What the program prints" in
# tutorial/step-1/doc/results.md): the branches of the block at each load
# value, the convergence table of the manufactured solution and the three
# solutions of the nonconvex law; and the
# values of lambda_1 that the introduction and the results quote in prose.
set -euo pipefail
step=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
"$step" > printed.txt 2> step-1.err || { echo "FAIL: step-1"; cat printed.txt step-1.err; exit 1; }
awk '/^## What the program prints/ {found = 1; next}
     found && /^```/ {if (inside) exit; inside = 1; next}
     inside {print}' "$src/tutorial/step-1/doc/results.md" > expected.txt
# ConvergenceTable pads its lines with blanks: compare without them
sed -i 's/ *$//' expected.txt printed.txt
[ -s expected.txt ] || { echo "FAIL: no output block in results.md"; exit 1; }
if ! diff -u expected.txt printed.txt; then
  echo "FAIL: step-1 prints something else than tutorial/step-1/doc/results.md shows"
  exit 1
fi
# The prose quotes the smallness constant lambda_1: the block's value (in
# the introduction and the results) and the square's on the coarsest and
# finest mesh (the results) must be those printed.
block_lambda=$(awk '/lambda_1 = / {sub(/.*lambda_1 = /, ""); sub(/ .*/, ""); print; exit}' printed.txt)
coarse_lambda=$(awk '$1 == 4 {print $4}' printed.txt)
fine_lambda=$(awk '$1 == 64 {print $4}' printed.txt)
for quote in "prints it: $block_lambda >|intro.md" \
             "finds λ₁ = $block_lambda on|results.md" \
             "from $coarse_lambda at|results.md" \
             "to $fine_lambda at h = 1/64|results.md"; do
  page=$src/tutorial/step-1/doc/${quote#*|}
  tr '\n' ' ' < "$page" | grep -qF -- "${quote%%|*}" ||
    { echo "FAIL: '${quote%%|*}' is not in $page"; exit 1; }
done
echo "step-1 prints the $(wc -l < printed.txt) lines of its results section; lambda_1 = $block_lambda (block), $coarse_lambda to $fine_lambda (square) as the pages quote"
