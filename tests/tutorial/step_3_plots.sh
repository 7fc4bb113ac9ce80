#!/usr/bin/env bash
# step_3_plots.sh STEP_3 SOURCE_DIR WORKDIR
# The plot scripts of tutorial/step-3 run as its results page says, on
# what the program writes: each is executable and, called by its path,
# draws its PNG (doc/plot_history.py from the history.csv and
# doc/plot_body.py from the body-NN.csv of 'step-3 block',
# doc/plot_convergence.py from the tables of
# 'step-3 convergence 2'). A script that is not executable, does not find
# its input or fails exits non-zero.
set -euo pipefail
step=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
"$step" block > block.log 2>&1 || { echo "FAIL: step-3 block"; cat block.log; exit 1; }
"$step" convergence 2 > table.txt 2>&1 || { echo "FAIL: step-3 convergence 2"; cat table.txt; exit 1; }
for script in plot_history.py plot_body.py plot_convergence.py; do
  [ -x "$src/tutorial/step-3/doc/$script" ] ||
    { echo "FAIL: tutorial/step-3/doc/$script is not executable"; exit 1; }
done
"$src/tutorial/step-3/doc/plot_history.py" . history.png
"$src/tutorial/step-3/doc/plot_body.py" . body.png
"$src/tutorial/step-3/doc/plot_convergence.py" table.txt convergence.png
for png in history.png body.png convergence.png; do
  [ "$(head -c 4 "$png" | od -An -c | tr -d ' ')" = "211PNG" ] ||
    { echo "FAIL: $png is not a PNG"; exit 1; }
done
echo "the three plot scripts of step-3 run as its results page says and draw their PNGs"
