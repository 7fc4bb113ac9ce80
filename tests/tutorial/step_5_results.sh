#!/usr/bin/env bash
# step_5_results.sh STEP_5 SOURCE_DIR WORKDIR
# tutorial/step-5 prints exactly the output shown on its results page (the
# block after `./step-5` in tutorial/step-5/doc/results.md): the branches
# and fixed-point iterations of the block at each load value and the
# convergence table of the manufactured solution. 'step-5 block' writes
# the files the page names, its four load values are scaled copies of one
# another (the page's homogeneity, to 1e-10), the contact zone and the slip
# nodes are those the page names, and the two plot scripts draw their
# PNGs from the files.
set -euo pipefail
step=$1; src=$2; work=$3
page=$src/tutorial/step-5/doc/results.md
rm -rf "$work"; mkdir -p "$work/block"; cd "$work"
"$step" > printed.txt 2> step-5.err || { echo "FAIL: step-5"; cat printed.txt step-5.err; exit 1; }
awk -v command='./step-5' -f "$src/tests/tutorial/page_block.awk" "$page" > expected.txt
[ -s expected.txt ] || { echo "FAIL: no block after \`./step-5\` in $page"; exit 1; }
diff -u expected.txt printed.txt ||
  { echo "FAIL: step-5 prints something else than $page shows"; exit 1; }
(cd block && "$step" block > ../block.txt 2>&1) || { echo "FAIL: step-5 block"; cat block.txt; exit 1; }
for file in solution-04.vtu contact-04.csv displacement-04.txt body-04.csv; do
  [ -f "block/$file" ] || { echo "FAIL: step-5 block wrote no $file"; exit 1; }
done
/usr/bin/python3 - block "$page" <<'PY'
import sys
import numpy as np
run, page = sys.argv[1], open(sys.argv[2]).read()
one = np.loadtxt(f"{run}/displacement-01.txt")
for n in range(2, 5):
    other = np.loadtxt(f"{run}/displacement-{n:02d}.txt")
    scale = np.abs(other[:, 2:]).max()
    assert np.abs(n * one[:, 2:] - other[:, 2:]).max() <= 1e-10 * scale, n
table = np.genfromtxt(f"{run}/contact-04.csv", delimiter=",", names=True)
separated = table["x"][table["normal_branch"] == 0]
on_wall = table["x"][table["normal_branch"] == 1]
slip = table["x"][(table["normal_branch"] == 1) & (table["tangential_branch"] == 1)]
quotes = [f"up to $x = {separated.max():g}$", f"from $x = {on_wall.min():g}$",
          "at $x = " + "$ and $".join(f"{x:g}" for x in slip[:-1]) + "$",
          f"free end $x = {slip[-1]:g}$"]
flat = " ".join(page.split())
for quote in quotes:
    assert quote in flat, f"not on the page: {quote}"
print("homogeneous to 1e-10; the page names the contact zone and the slip: "
      + "; ".join(quotes))
PY
"$src/tutorial/step-5/doc/plot_body.py" block body.png
"$src/tutorial/step-5/doc/plot_contact.py" block contact.png
for png in body.png contact.png; do
  [ "$(head -c 4 "$png" | od -An -c | tr -d ' ')" = "211PNG" ] ||
    { echo "FAIL: $png is not a PNG"; exit 1; }
done
echo "step-5 prints the $(wc -l < printed.txt) lines its results page shows; its plot scripts draw their PNGs"
