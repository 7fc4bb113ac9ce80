#!/usr/bin/env bash
# A block pressed uniformly onto a rigid wall (tests/signorini_block_2d.prm:
# Signorini, frictionless, static class) has the linear exact solution
# u = (-P t x/(lambda + 2 mu), 0) with the wall's pressure Q t at every
# contact node. With a direct linear solver it is reproduced to the 10
# digits of the CSV files (the same deviation, 5e-10, on every mesh: the
# printed precision) on quadrilaterals at two refinements, on triangles, on
# 2 ranks, and on the 3D block (hexahedra; the y faces carry the pressure
# Q t as well).
set -euo pipefail
exe=$1; prm=$2; work=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
run() { # NAME RANKS REFINEMENTS CELL_TYPE
  { cat "$prm"
    printf 'subsection geometry\n  set global refinements = %s\n  set cell type = %s\nend\n' "$3" "$4"
    printf 'subsection linear solver\n  set type = direct\nend\n'
    printf 'subsection output\n  set directory = %s\n  set terminal = quiet\nend\n' "$1"; } > "$1.prm"
  if [ "$2" -gt 1 ]; then mpirun -np "$2" "$exe" "$1.prm"; else "$exe" "$1.prm"; fi
}
run quads 1 2 hypercube
run quads_fine 1 4 hypercube
run triangles 1 3 simplex
run quads_2_ranks 2 3 hypercube
{ grep -v "^set dimension" quads.prm
  printf 'set dimension = 3\nsubsection geometry\n  set lower left corner = 0, 0, 0\n'
  printf '  set upper right corner = 2, 1, 1\n  set subdivisions = 2, 1, 1\n  set global refinements = 2\nend\n'
  printf 'subsection boundary\n  set clamped boundary ids = 0\n  set traction boundary ids = 1, 2, 3, 5\n  set contact boundary ids = 4\nend\n'
  printf 'subsection data\n  set surface traction = x > 1.9999 ? -P*t : 0; y < 1e-4 ? Q*t : (y > 0.9999 ? -Q*t : 0); z > 0.9999 ? -Q*t : 0\nend\n'
  printf 'subsection output\n  set directory = hexahedra\n  set probe points = 2, 0.5, 0.5; 1, 1, 1\nend\n'; } > hexahedra.prm
"$exe" hexahedra.prm
/usr/bin/python3 - <<'PY'
import csv, glob, sys
E, nu, P, Q = 100.0, 0.3, 3.0, 1.2857142857142858
lam = E*nu/((1+nu)*(1-2*nu)); mu = E/(2*(1+nu))
worst = 0.0
for run in ['quads', 'quads_fine', 'triangles', 'quads_2_ranks', 'hexahedra']:
    rows = list(csv.DictReader(open(sorted(glob.glob(run + '/contact_*.csv'))[-1])))
    t = float(rows[0]['time'])
    for r in rows:
        if r['normal_branch'] != '4':
            sys.exit(f"FAIL {run}: node at x = {r['x']} not at the wall (branch {r['normal_branch']})")
        worst = max(worst, abs(float(r['u_nu'])) / (P*t/(lam+2*mu)),
                    abs(float(r['wall_pressure']) - Q*t) / (Q*t),
                    abs(float(r['sigma_nu']) + Q*t) / (Q*t))
        ux = float(r['u_tau_x'])
        worst = max(worst, abs(ux + P*t*float(r['x'])/(lam+2*mu)) / (P*t/(lam+2*mu)))
    for p in csv.DictReader(open(run + '/probes.csv')):
        t, x = float(p['time']), float(p['x'])
        if t == 0: continue
        scale = P*t/(lam+2*mu)
        worst = max(worst, abs(float(p['u_x']) + scale*x)/scale, abs(float(p['u_y']))/scale,
                    abs(float(p.get('u_z', 0)))/scale)
print(f"largest relative deviation from the exact solution: {worst:.1e}")
if worst >= 1e-9:
    sys.exit("FAIL: not reproduced to round-off")
PY
