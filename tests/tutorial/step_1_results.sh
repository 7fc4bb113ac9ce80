#!/usr/bin/env bash
# step_1_results.sh STEP_1 SOURCE_DIR WORKDIR
# tutorial/step-1 prints exactly the output shown in its results section
# (the text block after "What the program prints" in
# tutorial/step-1/doc/results.md): the branches of the block at each load
# value and the convergence table of the manufactured solution.
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
echo "step-1 prints the $(wc -l < printed.txt) lines of its results section"
