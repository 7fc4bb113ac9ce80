#!/usr/bin/env bash
# temperature_contact_heat.sh EXE SOURCE_DIR WORKDIR
# The contact CSV reports the contact heat the heat step booked, and only
# what the model has (doc/outputs.md, "The contact CSV"):
# (a) frictional heating with theta prescribed on x = 0, whose corner node
#     is on Gamma_3 too: at every step k sum_i m_i exchanged_heat_i and
#     k sum_i m_i frictional_heat_i equal the step's increments of
#     steps.csv's exchanged_heat and frictional_heat (relative 1e-7), and
#     both columns are 0 at the held node;
# (b) the static class: the CSV has 'temperature' but no exchanged or
#     frictional heat, and a note names the contact heat law's entries
#     it does not use;
# (c) an isotropic conductivity written with function calls (commas inside
#     parentheses) runs as one expression.
set -euo pipefail
exe=$1; src=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"

{ cat "$src/prm/frictional_heating_2d.prm"
  printf 'subsection geometry\n  set global refinements = 1\nend\n'
  printf 'subsection time\n  set end time = 0.3\n  set time step = 0.02\nend\n'
  printf 'subsection temperature\n  set foundation temperature = 1\n'
  printf '  set prescribed temperature boundary ids = 0\n  set prescribed temperature = 2\nend\n'
  printf 'subsection output\n  set directory = held\n  set vtu interval = 1\n  set terminal = quiet\nend\n'
} > held.prm
"$exe" held.prm > held.out 2> held.err || { echo "FAIL (a): the run failed"; cat held.err; exit 1; }
python3 - held << 'PY'
import csv, glob, sys
d = sys.argv[1]
# one row per step, from step 1, the sums up to the step
steps = list(csv.DictReader(open(d + '/steps.csv')))
k = 0.02
worst = 0.0
held_rows = 0
for n in range(1, len(steps) + 1):
    rows = list(csv.DictReader(open('%s/contact_%05d.csv' % (d, n))))
    for name in ('exchanged_heat', 'frictional_heat'):
        csv_sum = k * sum(float(r['mass']) * float(r[name]) for r in rows)
        before = float(steps[n - 2][name]) if n > 1 else 0.0
        booked = float(steps[n - 1][name]) - before
        # the CSV's 10 digits, the difference of steps.csv's 12-digit sums
        scale = max(abs(booked), 1e-12)
        worst = max(worst, abs(csv_sum - booked) / scale)
        if abs(csv_sum - booked) > 1e-7 * scale + 1e-11 * abs(float(steps[n - 1][name])):
            sys.exit('FAIL (a): step %d: k sum m_i %s_i = %.12g, steps.csv books %.12g'
                     % (n, name, csv_sum, booked))
    for r in rows:
        if float(r['x']) == 0.0:
            held_rows += 1
            if float(r['exchanged_heat']) != 0 or float(r['frictional_heat']) != 0:
                sys.exit('FAIL (a): step %d: heat reported at the held node x = 0' % n)
if held_rows == 0:
    sys.exit('FAIL (a): no contact node at x = 0')
# the case means something: theta_F != theta there, so the exchange is not 0
if abs(float(steps[-1]['exchanged_heat'])) < 1e-6:
    sys.exit('FAIL (a): no heat exchanged')
print('(a) %d steps: the contact CSV sums equal steps.csv (worst %.1e relative)'
      % (len(steps), worst))
PY

{ cat "$src/tests/temperature_static_2d.prm"
  printf 'subsection time\n  set end time = 0.2\nend\n'
  printf 'subsection output\n  set directory = static\n  set vtu interval = 1\n  set terminal = quiet\nend\n'
} > static.prm
"$exe" static.prm > static.out 2> static.err || { echo "FAIL (b): the run failed"; cat static.err; exit 1; }
header=$(head -1 static/contact_00001.csv)
case "$header" in
  *,temperature) ;;
  *) echo "FAIL (b): the static class's contact CSV header is '$header'"; exit 1 ;;
esac
grep -q "hemicontact: note: the static class does not use 'temperature/exchange coefficient' = '1 \* step(u_nu)', 'temperature/foundation temperature' = '1' and 'temperature/frictional heat fraction' = 0.5" static.err ||
  { echo "FAIL (b): no note naming k_e, theta_F and gamma"; cat static.err; exit 1; }
echo "(b) static: the CSV ends in 'temperature'; $(grep -o 'note: .*(theta' static.err)"

for K in 'max(x, 1)' 'pow(x, 2) + 1' 'if(x < 1, 1, max(x, 2))'; do
  { cat held.prm
    printf 'subsection time\n  set end time = 0.02\nend\n'
    printf 'subsection temperature\n  set conductivity = %s\nend\n' "$K"
    printf 'subsection output\n  set directory = conductivity\n  set vtu interval = 0\nend\n'
  } > conductivity.prm
  "$exe" conductivity.prm > conductivity.out 2> conductivity.err ||
    { echo "FAIL (c): conductivity = $K is refused"; cat conductivity.err; exit 1; }
  echo "(c) conductivity = $K: runs"
done
