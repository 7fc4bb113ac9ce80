#!/usr/bin/env bash
# step_plots.sh STEP_1 STEP_2 SOURCE_DIR WORKDIR
# The plot scripts of the tutorial run as the results pages say, on what
# the programs write: each is executable and, called by its path, draws
# its PNG (step-1's two from the files of 'step-1 block', law.csv among
# them; step-2's from the table of 'step-2 convergence 2' and from the
# body-NN.csv files of 'step-2 block'). A script that
# is not executable, does not find its input or fails exits non-zero.
set -euo pipefail
step1=$1; step2=$2; src=$3; work=$4
rm -rf "$work"; mkdir -p "$work"; cd "$work"
"$step1" block > step-1.log 2>&1 || { echo "FAIL: step-1 block"; cat step-1.log; exit 1; }
"$step2" convergence 2 > table.txt 2>&1 || { echo "FAIL: step-2"; cat table.txt; exit 1; }
mkdir step-2-block
(cd step-2-block && "$step2" block > ../step-2.log 2>&1) ||
  { echo "FAIL: step-2 block"; cat step-2.log; exit 1; }
for script in step-1/doc/plot_contact.py step-1/doc/plot_law.py \
              step-2/doc/plot_convergence.py step-2/doc/plot_body.py; do
  [ -x "$src/tutorial/$script" ] || { echo "FAIL: tutorial/$script is not executable"; exit 1; }
done
"$src/tutorial/step-1/doc/plot_contact.py" . contact.png
"$src/tutorial/step-1/doc/plot_law.py" . law.png
"$src/tutorial/step-2/doc/plot_convergence.py" table.txt convergence.png
"$src/tutorial/step-2/doc/plot_body.py" step-2-block body-2.png
for png in contact.png law.png convergence.png body-2.png; do
  [ "$(head -c 4 "$png" | od -An -c | tr -d ' ')" = "211PNG" ] ||
    { echo "FAIL: $png is not a PNG"; exit 1; }
done
echo "the four plot scripts run as the results pages say and draw their PNGs"
