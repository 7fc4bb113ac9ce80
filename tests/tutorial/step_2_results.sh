#!/usr/bin/env bash
# step_2_results.sh STEP_2 SOURCE_DIR WORKDIR
# The block printed on tutorial/step-2/doc/results.md under the command
# `./step-2 block` is, as a whole (header, the line with lambda_1 and every
# step line), what that command prints; the command writes its files into
# the current directory as the page says, and the page's count of nodes
# below the foundation's surface (u_nu > 0) at t = 0.92, when all of them
# separate (w_nu < 0), is that of these files; the pages quote the
# lambda_1 it prints.
set -euo pipefail
step2=$1; src=$2; work=$3
page=$src/tutorial/step-2/doc/results.md
rm -rf "$work"; mkdir -p "$work"; cd "$work"
mkdir run
(cd run && "$step2" block > ../printed.txt 2> ../step-2.err) ||
  { echo "FAIL: step-2 block"; cat printed.txt step-2.err; exit 1; }
awk -v command='./step-2 block' \
  -f "$src/tests/tutorial/page_block.awk" "$page" > expected.txt
[ -s expected.txt ] ||
  { echo "FAIL: no block after \`./step-2 block\` in $page"; exit 1; }
diff -u expected.txt printed.txt ||
  { echo "FAIL: step-2 block prints something else than $page shows"; exit 1; }
for file in solution-25.vtu contact-25.csv displacement-25.txt body-25.csv; do
  [ -f "run/$file" ] || { echo "FAIL: step-2 block wrote no $file"; exit 1; }
done
# The page's count of nodes still below the foundation's surface at
# t = 0.92 (step 23: bottom nodes y = 0 off the clamped corner, u_nu = -u_y;
# the columns are x y u_x u_y w_x w_y)
read -r below largest < <(awk '$2 == 0 && $1 > 0 && $4 < 0 \
  {n++; if (-$4 > m) m = -$4} END {printf "%d %.3f\n", n, m}' run/displacement-23.txt)
grep -qF "while $below of the 32 nodes are" "$page" && grep -qF "up to \$u_\\nu = $largest\$" "$page" ||
  { echo "FAIL: at t = 0.92 $below nodes have u_nu > 0, up to $largest: not what $page says"; exit 1; }
# The smallness constant lambda_1 of K0 that the introduction and the
# results quote is the one printed.
lambda=$(sed -n 's/^ *[0-9]* dofs, alpha_nu = [0-9.]*, lambda_1 = \([0-9.]*\) .*/\1/p' printed.txt)
[ -n "$lambda" ] || { echo "FAIL: step-2 block prints no lambda_1"; exit 1; }
for quote in "\$\\lambda_1 = $lambda > \\alpha_\\nu = 5\$|intro.md" "finds \$\\lambda_1 = $lambda\$ for \$K_0\$|results.md"; do
  doc=$src/tutorial/step-2/doc/${quote#*|}
  tr '\n' ' ' < "$doc" | grep -qF -- "${quote%%|*}" ||
    { echo "FAIL: '${quote%%|*}' is not in $doc"; exit 1; }
done
echo "step-2 block prints the $(wc -l < printed.txt) lines its results page shows; lambda_1 = $lambda as the pages quote"
