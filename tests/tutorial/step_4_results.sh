#!/usr/bin/env bash
# step_4_results.sh STEP_4 SOURCE_DIR WORKDIR
# tutorial/step-4 prints exactly the output shown in its results page (the
# block after "What the program prints" in tutorial/step-4/doc/results.md,
# compared as a whole, so line by line); the numbers that the pages quote
# in prose (lambda_1, the reference, the branches, the rates, the
# effectivity range, the errors at the last rows, the contact part of the
# estimate) are those of this run; and the figure's script, called by its
# path, draws a PNG from the files of this run.
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
             END {printf "between N^(−%s) and N^(−%s)", min, max}' rows.txt)
last_u=$(awk '$1 == "u" {r = $0} END {split(r, a, " "); print a[6], a[4], a[7]}' rows.txt)
last_a=$(awk '$1 == "a" {r = $0} END {split(r, a, " "); print a[6], a[4]}' rows.txt)
read -r u_E u_dofs u_rate <<< "$last_u"; read -r a_E a_dofs <<< "$last_a"
comma() { echo "$1" | sed ':a;s/\B[0-9]\{3\}\>/,&/;ta'; }
read -r uE ueta < <(sed -n 's/^rate from level 0 to 3: E_J \([0-9.]*\), eta \([0-9.]*\)$/\1 \2/p' printed.txt)
read -r aE aeta < <(sed -n 's/^rate from cycle 0 to 8: E_J \([0-9.]*\), eta \([0-9.]*\)$/\1 \2/p' printed.txt)
contact=$(/usr/bin/python3 -c "
import csv
rows = list(csv.DictReader(open('adaptive.csv')))
print(f\"{float(rows[0]['estimate_contact']):.3f} of η = {float(rows[0]['estimate']):.3f} at cycle 0|\"
      f\"{float(rows[8]['estimate_contact']):.4f} of {float(rows[8]['estimate']):.3f} at cycle 8\")")
failures=0
[ "$sep" = 0 ] || { echo "FAIL: $sep separating nodes, the pages say none"; failures=1; }
for quote in "λ₁ = $lambda > α_ν|$intro" "λ₁ = $lambda > α_ν = 0.769|$results" \
             "$pen contact nodes penetrate, $stick are held|$intro" \
             "78 stick tangentially and $slip slip|$intro" \
             "$pen of the $((sep + stick + pen)) contact nodes penetrate|$results" \
             "$stick are held at u_ν = 0, none separates; $slip slip|$results" \
             "cycle 14 of the same adaptive loop, $ref_dofs unknowns|$intro" \
             "N^(−$uE) over the table|$results" "N^(−$u_rate) between its last two levels|$results" \
             "N^(−$aE) from cycle 0 to cycle 8|$results" "$rates from one cycle|$results" \
             "estimate falls at N^(−$aeta)|$results" \
             "$(range a) on the adaptive meshes|$results" "$(range u) on the uniform ones|$results" \
             "At $(comma "$a_dofs") unknowns the adaptive error is $a_E, below the $u_E of the uniform mesh with $(comma "$u_dofs")|$results" \
             "${contact%%|*}|$results" "${contact##*|}|$results"; do
  page=${quote##*|}; text=${quote%|*}
  tr '\n' ' ' < "$page" | sed 's/  */ /g' | grep -qF -- "$text" ||
    { echo "FAIL: '$text' is not in $page"; failures=$((failures + 1)); }
done
[ $failures -eq 0 ] || exit 1

# the figure, drawn as the page says from the files of this run
[ -x "$src/tutorial/step-4/doc/plot_convergence.py" ] ||
  { echo "FAIL: tutorial/step-4/doc/plot_convergence.py is not executable"; exit 1; }
"$src/tutorial/step-4/doc/plot_convergence.py" . convergence.png
[ "$(head -c 4 convergence.png | od -An -c | tr -d ' ')" = "211PNG" ] ||
  { echo "FAIL: convergence.png is not a PNG"; exit 1; }
echo "step-4 prints the $(wc -l < printed.txt) lines of its results page; the quoted numbers are this run's; the figure's script draws its PNG"
