#!/usr/bin/env bash
# step_1_nonconvex.sh STEP_1 SOURCE_DIR WORKDIR
# tutorial/step-1's study of nonconvexity ('step-1 nonconvex': the block
# with a law whose alpha_nu = 145 breaks the smallness condition): the
# program says that the condition fails, finds a solution from each of its
# three starts, and their energies J_h are distinct (pairwise relative
# differences above 1e-3), so the three are different solutions; the
# results page quotes each energy and penetration as printed (in its
# table); and the two plot scripts draw the page's pictures of the body
# from the files of the run and of 'step-1 block'.
set -euo pipefail
step=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work/block"; cd "$work"
"$step" nonconvex > printed.txt 2> step-1.err ||
  { echo "FAIL: step-1 nonconvex"; cat printed.txt step-1.err; exit 1; }
cat printed.txt
grep -qF "(alpha_nu >= lambda_1: maybe several solutions)" printed.txt ||
  { echo "FAIL: step-1 does not report the smallness condition as failed"; exit 1; }
energies=$(sed -n 's/.*: J_h = \([-0-9.e]*\), largest u_nu = \([-0-9.e]*\)$/\1 \2/p' printed.txt)
[ "$(echo "$energies" | wc -l)" = 3 ] ||
  { echo "FAIL: expected three 'J_h = ..., largest u_nu = ...' lines"; exit 1; }
echo "$energies" | awk '
  {J[NR] = $1}
  END {
    for (i = 1; i <= 3; ++i)
      for (k = i + 1; k <= 3; ++k) {
        d = J[i] - J[k]; if (d < 0) d = -d
        s = (J[i] < 0 ? -J[i] : J[i]) + (J[k] < 0 ? -J[k] : J[k])
        if (d <= 1e-3 * s) {
          printf "FAIL: energies %d and %d are not distinct: %s %s\n", i, k, J[i], J[k]
          exit 1
        }
      }
  }'
page=$src/tutorial/step-1/doc/results.md
while read -r J u; do
  row="| ${J/-/−} | $u |"
  grep -qF -- "$row" "$page" || { echo "FAIL: results.md lacks the row cells '$row'"; exit 1; }
done <<< "$energies"
# the pictures: the three solutions and the block at its four load values
/usr/bin/python3 "$src/tutorial/step-1/doc/plot_nonconvex.py" . nonconvex.png
(cd block && "$step" block > step-1.log 2>&1) || { echo "FAIL: step-1 block"; exit 1; }
/usr/bin/python3 "$src/tutorial/step-1/doc/plot_body.py" block body.png
for png in nonconvex.png body.png; do
  [ "$(head -c 4 "$png" | od -An -c | tr -d ' ')" = "211PNG" ] ||
    { echo "FAIL: $png is not a PNG"; exit 1; }
done
echo "three distinct solutions, J_h =" $(echo "$energies" | cut -d' ' -f1) "as results.md quotes; both pictures drawn"
