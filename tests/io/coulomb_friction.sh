#!/usr/bin/env bash
# Coulomb friction, F_b = mu*pos(p_nu) with p_nu = -sigma_nu (doc/theory.md,
# section 9.9), checked on the contact CSV files:
# 1. the static class (prm/coulomb_block_2d.prm) on 1 and 2 MPI ranks: at
#    every node of every load value F_b = mu (-sigma_nu)_+ of the solution
#    (the fixed point), |sigma_tau| = mu p on slipping nodes and
#    |sigma_tau| <= mu p on sticking ones; both zones occur; the two rank
#    counts give the same rows, and fixed-point iterations within one of
#    each other (the last change may fall on either side of the tolerance);
# 2. the quasistatic class (tests/coulomb_quasistatic_2d.prm): the bound of
#    step n is mu (-sigma_nu)_+ of step n-1, no fixed point, the same
#    slip/stick conditions with that bound; the w_0 problem before step 1
#    reads its own pressure (a fixed point);
# 3. the same with the mesh adapted every other step on 2 ranks: the lag
#    holds at every node the two meshes share (the pressure moves with the
#    mesh).
set -euo pipefail
exe=$1; src=$2; work=$3
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
rm -rf "$work"; mkdir -p "$work"; cd "$work"
with_output() { # PRM DIRECTORY [EXTRA]
  cat "$1"
  printf 'subsection output\n  set directory = %s\n  set output interval = 1\n  set terminal = quiet\nend\n' "$2"
  printf '%b' "${3:-}"
}
with_output "$src/prm/coulomb_block_2d.prm" static > static.prm
with_output "$src/tests/coulomb_quasistatic_2d.prm" quasistatic > quasistatic.prm
with_output "$src/tests/coulomb_quasistatic_2d.prm" adapted \
  'subsection adaptivity\n  set interval = 2\n  set indicator = kelly contact\n  set refine fraction = 0.3\n  set coarsen fraction = 0.1\n  set min level = 2\n  set max level = 5\nend\n' > adapted.prm
"$exe" static.prm
mkdir -p ranks2; (cd ranks2 && mpirun -np 2 "$exe" ../static.prm)
"$exe" quasistatic.prm
mpirun -np 2 "$exe" adapted.prm
/usr/bin/python3 - <<'PY'
import csv, glob

MU = 0.3

def table(path):
    return list(csv.DictReader(open(path)))

def contact(d, n):
    return table("%s/contact_%05d.csv" % (d, n))

def pressure(row):
    return max(-float(row["sigma_nu"]), 0.0)

def coulomb(rows, bound_of, label):
    """|sigma_tau| = F_b on slip nodes, <= F_b on stick nodes; F_b as given."""
    scale = max(max(bound_of(r) for r in rows), 1e-12)
    n_slip = n_stick = 0
    for r in rows:
        fb, st = float(r["friction_bound"]), float(r["sigma_tau_norm"])
        assert abs(fb - bound_of(r)) <= 1e-6 * scale, (label, "bound", r["x"], fb, bound_of(r))
        if r["tangential_branch"] == "1":
            n_slip += 1
            assert abs(st - fb) <= 1e-6 * scale, (label, "slip", r["x"], st, fb)
        else:
            n_stick += 1
            assert st <= fb + 1e-6 * scale, (label, "stick", r["x"], st, fb)
    return n_slip, n_stick

# 1. static, 1 and 2 ranks
steps = table("static/steps.csv")
its = [int(r["bound_iterations"]) for r in steps]
assert min(its) >= 2, ("a load value without the fixed point", its)
slip = stick = 0
for r in steps:
    n = int(r["step"])
    rows = contact("static", n)
    a, b = coulomb(rows, lambda r: MU * pressure(r), "static %d" % n)
    slip += a; stick += b
    other = contact("ranks2/static", n)
    assert len(other) == len(rows)
    scale = max(abs(float(x["sigma_nu"])) for x in rows)
    for x, y in zip(rows, other):
        assert x["x"] == y["x"] and x["tangential_branch"] == y["tangential_branch"], (n, x["x"])
        for c in ("sigma_nu", "sigma_tau_norm", "friction_bound"):
            assert abs(float(x[c]) - float(y[c])) <= 1e-6 * scale, (n, c, x[c], y[c])
assert slip > 0 and stick > 0, (slip, stick)
its2 = [int(r["bound_iterations"]) for r in table("ranks2/static/steps.csv")]
# the last iteration may fall on either side of the tolerance
assert all(abs(a - b) <= 1 for a, b in zip(its, its2)), (its, its2)
print("static: %d load values, fixed-point iterations %d to %d, "
      "%d slip and %d stick node rows: |sigma_tau| = mu p on slip, <= mu p on stick; "
      "1 and 2 ranks agree (iterations within 1)" % (len(steps), min(its), max(its), slip, stick))

# 2. and 3. quasistatic: the bound of step n from the pressure of step n-1
for d in ("quasistatic", "adapted"):
    steps = table(d + "/steps.csv")
    assert all(r["bound_iterations"] == "0" for r in steps), d
    # w_0 has no step before it: its bound reads its own pressure
    for p in contact(d, 0):
        assert abs(float(p["friction_bound"]) - MU * pressure(p)) <= 1e-9, (d, "w_0", p["x"])
    slip = stick = shared = 0
    for r in steps:
        n = int(r["step"])
        before = {(p["x"], p["y"]): pressure(p) for p in contact(d, n - 1)}
        rows = [p for p in contact(d, n) if (p["x"], p["y"]) in before]
        shared += len(rows)
        a, b = coulomb(rows, lambda p: MU * before[(p["x"], p["y"])], "%s %d" % (d, n))
        slip += a; stick += b
    cells = sorted(set(int(r["n_cells"]) for r in steps))
    assert slip > 0 and stick > 0, (d, slip, stick)
    print("%s: %d steps (%s cells), at %d node rows F_b = mu p of the step before; "
          "%d slip, %d stick" % (d, len(steps), "/".join(map(str, cells)), shared, slip, stick))
    if d == "adapted":
        assert len(cells) > 1, "the mesh was not adapted"
PY
