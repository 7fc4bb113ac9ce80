#!/usr/bin/env bash
# step_3_results.sh STEP_3 SOURCE_DIR WORKDIR
# The block printed on tutorial/step-3/doc/results.md under the command
# `./step-3 block` is, as a whole, what that command prints; the command
# writes its files as the page says (17 load values and history.csv); and
# the numbers the page and the introduction quote in prose are those
# printed: lambda_1, the largest penetration and memory pressure at
# t = 0.75 and t = 2, and the free end's penetration without memory.
set -euo pipefail
step=$1; src=$2; work=$3
page=$src/tutorial/step-3/doc/results.md
intro=$src/tutorial/step-3/doc/intro.md
rm -rf "$work"; mkdir -p "$work"; cd "$work"
"$step" block > printed.txt 2> step-3.err ||
  { echo "FAIL: step-3 block"; cat printed.txt step-3.err; exit 1; }
awk -v command='./step-3 block' \
  -f "$src/tests/tutorial/page_block.awk" "$page" > expected.txt
[ -s expected.txt ] || { echo "FAIL: no block after \`./step-3 block\` in $page"; exit 1; }
diff -u expected.txt printed.txt ||
  { echo "FAIL: step-3 block prints something else than $page shows"; exit 1; }
for f in solution-16.vtu contact-16.csv displacement-16.txt history.csv; do
  [ -s "$f" ] || { echo "FAIL: no $f"; exit 1; }
done
# the numbers quoted in prose
lambda=$(sed -n 's/.*lambda_1 = \([0-9.]*\) .*/\1/p' printed.txt)
read -r u075 N075 < <(awk '/t = 0.750:/ {sub(",", "", $(NF-3)); print $(NF-3), $NF}' printed.txt)
read -r u2 N2 < <(awk '/t = 2.000:/ {sub(",", "", $(NF-3)); print $(NF-3), $NF}' printed.txt)
elastic=$(awk -F, '$1 == 2 {printf "%.2f", $5}' history.csv)
check() { # check PAGE TEXT
  tr '\n' ' ' < "$1" | tr -s ' ' | grep -qF -- "$2" ||
    { echo "FAIL: '$2' is not in $1"; exit 1; }
}
check "$intro" "λ₁ = $lambda on the block"
check "$page" "\$\\lambda_1 = $lambda > \\alpha_\\nu"
check "$page" "(\$u_\\nu = $u075\$, the largest)"
check "$page" "from $N075 at \$t = 0.75\$ to $N2 at \$t = 2\$"
check "$page" "falls to $u2 under the same load"
check "$page" "jumps to $elastic when"
echo "step-3 block prints the $(wc -l < printed.txt) lines of its results page; lambda_1 = $lambda, max u_nu $u075 -> $u2, N $N075 -> $N2, without memory $elastic, as the pages quote"
