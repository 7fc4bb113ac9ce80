#!/usr/bin/env bash
# step_2_results.sh STEP_2 SOURCE_DIR WORKDIR
# The block printed on tutorial/step-2/doc/results.md under the command
# `./step-2 block output-block` is, as a whole (header, every step line,
# the output folder and the blank line), what that command prints; the
# command writes its files into output-block/ as the page says.
set -euo pipefail
step2=$1; src=$2; work=$3
page=$src/tutorial/step-2/doc/results.md
rm -rf "$work"; mkdir -p "$work"; cd "$work"
"$step2" block output-block > printed.txt 2> step-2.err ||
  { echo "FAIL: step-2 block output-block"; cat printed.txt step-2.err; exit 1; }
awk -v command='./step-2 block output-block' \
  -f "$src/tests/tutorial/page_block.awk" "$page" > expected.txt
[ -s expected.txt ] ||
  { echo "FAIL: no block after \`./step-2 block output-block\` in $page"; exit 1; }
diff -u expected.txt printed.txt ||
  { echo "FAIL: step-2 block output-block prints something else than $page shows"; exit 1; }
[ -f output-block/nodal_00025.txt ] ||
  { echo "FAIL: no output-block/nodal_00025.txt"; exit 1; }
echo "step-2 block output-block prints the $(wc -l < printed.txt) lines its results page shows"
