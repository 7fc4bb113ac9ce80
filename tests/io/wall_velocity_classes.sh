#!/usr/bin/env bash
# The wall in the velocity classes (doc/theory.md section 10): with normal
# compliance up to u_nu = g = 0.02, the quasistatic class (left point) and
# the dynamic class (implicit rule) keep every probe on the contact
# boundary at u_nu <= g, the probes under the largest pressure reach it,
# and the wall's reaction is >= 0 at every node held there, > 0 at some.
set -euo pipefail
exe=$1; source_dir=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
for case in finite_penetration_quasistatic_2d finite_penetration_dynamic_implicit_2d; do
  { cat "$source_dir/$case.prm"
    printf 'subsection output\n  set directory = %s\n  set output interval = 1\n  set terminal = quiet\nend\n' "$case"; } > "$case.prm"
  "$exe" "$case.prm"
done
/usr/bin/python3 - <<'PY'
import csv, glob, sys
g = 0.02
for case in ['finite_penetration_quasistatic_2d', 'finite_penetration_dynamic_implicit_2d']:
    u_nu = [-float(p['u_y']) for p in csv.DictReader(open(case + '/probes.csv'))]
    largest = max(u_nu)
    if largest > g * (1 + 1e-9):
        sys.exit(f"FAIL {case}: a probe passes the wall, u_nu = {largest!r} > g = {g}")
    if largest < g * (1 - 1e-9):
        sys.exit(f"FAIL {case}: no probe reaches the wall (largest u_nu {largest!r})")
    reactions = [float(r['wall_pressure']) for f in sorted(glob.glob(case + '/contact_*.csv'))
                 for r in csv.DictReader(open(f)) if r['normal_branch'] == '4']
    if not reactions or min(reactions) < -1e-8 or max(reactions) <= 0:
        sys.exit(f"FAIL {case}: wall reactions {min(reactions, default=None)} .. {max(reactions, default=None)}")
    print(f"{case}: largest probe u_nu = g to {abs(largest - g)/g:.0e}, "
          f"{len(reactions)} (node, step) pairs at the wall, reactions >= {min(reactions):.2e}")
PY
