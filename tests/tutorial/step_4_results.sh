#!/usr/bin/env bash
# step_4_results.sh STEP_4 SOURCE_DIR WORKDIR
# tutorial/step-4 prints exactly the output shown in its results page (the
# block after "What the program prints" in tutorial/step-4/doc/results.md,
# compared as a whole, so line by line); the numbers that the pages quote
# in prose (lambda_1, the reference, the branches, the rates, the
# effectivity range, the errors at the last rows, the contact part of the
# estimate) are those of this run; and the figures' scripts (the
# convergence plot, the adapted meshes), called by their paths, draw PNGs
# from the files of this run.
set -euo pipefail
step=$1; src=$2; work=$3
intro=$src/tutorial/step-4/doc/intro.md
results=$src/tutorial/step-4/doc/results.md
rm -rf "$work"; mkdir -p "$work"; cd "$work"
"$step" > printed.txt 2> step-4.err || { echo "FAIL: step-4"; cat printed.txt step-4.err; exit 1; }
awk '/^## What the program prints/ {found = 1; next}
     found && /^```/ {if (inside) exit; inside = 1; next}
     inside {print}' "$results" > expected.txt
[ -s expected.txt ] || { echo "FAIL: no output block in $results"; exit 1; }
diff -u expected.txt printed.txt ||
  { echo "FAIL: step-4 prints something else than $results shows"; exit 1; }

# the numbers quoted in prose, taken from this run
lambda=$(sed -n 's/.*lambda_1 = \([0-9.]*\) .*/\1/p' printed.txt)
read -r sep stick pen tstick slip < <(sed -n \
  's|^cycle 14: normal separating/stick/penetrating \([0-9]*\)/\([0-9]*\)/\([0-9]*\), tangential stick/slip \([0-9]*\)/\([0-9]*\)$|\1 \2 \3 \4 \5|p' printed.txt)
ref_dofs=$(sed -n 's/^reference: cycle 14, \([0-9]*\) dofs.*/\1/p' printed.txt | sed ':a;s/\B[0-9]\{3\}\>/,&/;ta')
# the tables: uniform rows follow "level cells", adaptive rows "cycle cells"
awk '/^level cells/ {t = "u"; next} /^cycle cells/ {t = "a"; next}
     /^ *[0-9]+ +[0-9]+ +[0-9]+ +[0-9]+ / && t {print t, $0}' printed.txt > rows.txt
range() { awk -v t="$1" '$1 == t {v = $NF; if (min == "" || v < min) min = v; if (v > max) max = v}
                          END {printf "between %s and %s", min, max}' rows.txt; }
rates=$(awk '$1 == "a" && $7 != "-" {v = $7; if (min == "" || v < min) min = v; if (v > max) max = v}
             END {printf "between $n_\\text{dofs}^{-%s}$ and $n_\\text{dofs}^{-%s}$", min, max}' rows.txt)
last_u=$(awk '$1 == "u" {r = $0} END {split(r, a, " "); print a[6], a[4], a[7]}' rows.txt)
last_a=$(awk '$1 == "a" {r = $0} END {split(r, a, " "); print a[6], a[4]}' rows.txt)
read -r u_E u_dofs u_rate <<< "$last_u"; read -r a_E a_dofs <<< "$last_a"
comma() { echo "$1" | sed ':a;s/\B[0-9]\{3\}\>/,&/;ta'; }
read -r uE ueta < <(sed -n 's/^rate from level 0 to 3: E_J \([0-9.]*\), eta \([0-9.]*\)$/\1 \2/p' printed.txt)
read -r aE aeta < <(sed -n 's/^rate from cycle 0 to 8: E_J \([0-9.]*\), eta \([0-9.]*\)$/\1 \2/p' printed.txt)
contact=$(/usr/bin/python3 -c "
import csv
rows = list(csv.DictReader(open('adaptive.csv')))
print(f\"{float(rows[0]['estimate_contact']):.3f} of \$\\\\eta = {float(rows[0]['estimate']):.3f}\$ at cycle 0|\"
      f\"{float(rows[8]['estimate_contact']):.4f} of {float(rows[8]['estimate']):.3f} at cycle 8\")")
# the reference's error against the last cycle's, from the two estimates
bias=$(/usr/bin/python3 -c "
import sys
ref = float(sys.argv[1]); last = float(sys.argv[2])
r = ref / last
print(f'about a quarter ({r:.2f})|about {round(100 * r * r)} % of|low by at most about {round(100 * (1 - (1 - r * r) ** 0.5))} %')
" "$(sed -n 's/^reference: .*, eta = \([0-9.e+-]*\)$/\1/p' printed.txt)" \
  "$(awk '$1 == "a" {e = $8} END {print e}' rows.txt)")
# the Newton iterations: the first cycle, the later ones, the uniform levels
newton=$(awk '$1 == "a" && $2 == 0 {first = $5}
              $1 == "a" && $2 > 0 {v = $5; if (min == "" || v < min) min = v; if (v > max) max = v}
              $1 == "u" {w = $5; if (umin == "" || w < umin) umin = w; if (w > umax) umax = w}
              END {printf "takes %s iterations from zero; each later|takes %s to %s. The uniform levels, each started from zero, take %s to %s", first, min, max, umin, umax}' rows.txt)
failures=0
[ "$sep" = 0 ] || { echo "FAIL: $sep separating nodes, the pages say none"; failures=1; }
alpha=$(sed -n 's/^alpha_nu = \([0-9.]*\),.*/\1/p' printed.txt)
times=$(awk -v l="$lambda" -v a="$alpha" 'BEGIN {printf "%d", l / a}')
for quote in "λ₁ = $lambda, $times times α_ν|$intro" "\$\\lambda_1 = $lambda > \\alpha_\\nu = 0.769\$|$results" \
             "$pen contact nodes penetrate, $stick are held|$intro" \
             "78 stick tangentially and $slip slip|$intro" \
             "$pen of the $((sep + stick + pen)) contact nodes penetrate|$results" \
             "$stick are held at \$u_\\nu = 0\$, none separates; $slip slip|$results" \
             "cycle 14 of the same adaptive loop, $ref_dofs unknowns|$intro" \
             "\$n_\\text{dofs}^{-$uE}\$ over the table|$results" "\$n_\\text{dofs}^{-$u_rate}\$ between its last two levels|$results" \
             "\$n_\\text{dofs}^{-$aE}\$ from cycle 0 to cycle 8|$results" "$rates from one cycle|$results" \
             "estimate falls at \$n_\\text{dofs}^{-$aeta}\$|$results" \
             "$(range a) on the adaptive meshes|$results" "$(range u) on the uniform ones|$results" \
             "At $(comma "$a_dofs") unknowns the adaptive error is $a_E, below the $u_E of the uniform mesh with $(comma "$u_dofs")|$results" \
             "${contact%%|*}|$results" "${contact##*|}|$results" \
             "$(echo "$bias" | cut -d'|' -f1)|$intro" "$(echo "$bias" | cut -d'|' -f2)|$intro" \
             "$(echo "$bias" | cut -d'|' -f3)|$intro" \
             "${newton%%|*}|$results" "${newton##*|}|$results"; do
  page=${quote##*|}; text=${quote%|*}
  tr '\n' ' ' < "$page" | sed 's/  */ /g' | grep -qF -- "$text" ||
    { echo "FAIL: '$text' is not in $page"; failures=$((failures + 1)); }
done
[ $failures -eq 0 ] || exit 1

# where the finest cells of cycle 8 are (its solution-08.vtu, the cell
# values written per patch vertex): the results page says levels 8 to 10
# at the corner (1, 1) and at (0, 2) and (1, 2), and level 5 along y = 0
/usr/bin/python3 - "$results" <<'PYTHON' || exit 1
import sys
import meshio
import numpy as np
mesh = meshio.read("solution-08.vtu")
cells = mesh.cells[0].data
level = mesh.point_data["level"][cells[:, 0]].astype(int)
centre = mesh.points[cells].mean(axis=1)[:, :2]
points = np.array([[1, 1], [0, 2], [1, 2]])
distance = np.min(np.linalg.norm(centre[:, None, :] - points[None], axis=2), axis=1)
finest = level >= 8
on_gamma_3 = centre[:, 1] < 0.1
checks = {"the finest level is 10": level.max() == 10,
          "levels 8 to 10 lie within 0.1 of the three points":
              distance[finest].max() < 0.1,
          "each of the three points has a cell of level >= 8 within 0.1":
              all((np.linalg.norm(centre[finest] - p, axis=1) < 0.1).any()
                  for p in points),
          "the cells along y = 0 reach level 5": level[on_gamma_3].max() == 5}
page = " ".join(open(sys.argv[1]).read().split())
quote = "(levels 8 to 10; the starting mesh has level 2)"
checks[f"the page says '{quote}'"] = quote in page
checks["the page says 'the cells reach level 5'"] = "the cells reach level 5" in page
failed = [name for name, ok in checks.items() if not ok]
for name in failed:
    print("FAIL:", name)
sys.exit(1 if failed else 0)
PYTHON

# the figures, drawn as the page says from the files of this run
for figure in convergence meshes; do
  script=$src/tutorial/step-4/doc/plot_$figure.py
  [ -x "$script" ] || { echo "FAIL: $script is not executable"; exit 1; }
  "$script" . $figure.png
  [ "$(head -c 4 $figure.png | od -An -c | tr -d ' ')" = "211PNG" ] ||
    { echo "FAIL: $figure.png is not a PNG"; exit 1; }
done
echo "step-4 prints the $(wc -l < printed.txt) lines of its results page; the quoted numbers are this run's; the figures' scripts draw their PNGs"
