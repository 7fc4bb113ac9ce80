#!/usr/bin/env bash
# wear.sh EXE WORKDIR PRM: the run of PRM (Archard wear on a foundation
# moving with v* = (1, 0), k_w = 0.005, a compliant law c_p u_nu up to a
# wall at g = 0.02; doc/theory.md, section 11.12), in its quasistatic
# class (implicit rule) and in the static class, writes in its contact
# CSVs a wear depth that follows the rule at every contact node,
#   omega_{n+1} = omega_n + k_w k p_n |w_tau,n - v*_tau|   (quasistatic),
#   omega_{n+1} = omega_n + k_w p_n |u_tau,n - u_tau,n-1 - k v*_tau| (static),
# p_n = (-sigma_nu)_+ of the row (the row of step n holds omega_{n+1}); and
# the foundation moves away by omega_n in step n: every node satisfies
# u_nu <= g + omega_n with equality at the nodes held at the wall (the
# quasistatic u_nu summed from the written w_nu, u_n = u_{n-1} + k w_n),
# and in the static class the law acts on u_nu - omega_n: -sigma_nu =
# c_p (u_nu - omega_n) at the damped nodes, u_nu <= omega_n at the
# separating ones. To the CSV's 10 digits. The double-precision nodal
# file of the last step holds the same wear at the contact nodes. The wear must grow and the
# wall must hold nodes whose wear is positive (the test fails otherwise).
set -euo pipefail
exe=$1; work=$2; prm=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
for class in quasistatic static; do
  { sed "s/set class *=.*/set class = $class/; s/set directory *=.*/set directory = $class/" "$prm"
    printf 'subsection output\n  set precision = double\nend\n'; } > $class.prm
  "$exe" $class.prm > $class.log
done
/usr/bin/python3 - <<'PY'
import glob
import h5py
import numpy as np, pandas as pd
k, kw, g, cp = 0.0625, 0.005, 0.02, 100.0
vstar = np.array([1.0, 0.0])
for cls, unknown in (("quasistatic", "w"), ("static", "u")):
    tables = [pd.read_csv(f) for f in sorted(glob.glob(f"{cls}/contact_*.csv"))]
    assert tables[0].columns[-1] == "wear", "wear is not the last column"
    nu = tables[0][["normal_x", "normal_y"]].values
    vtau = vstar - (nu @ vstar)[:, None] * nu
    omega = np.zeros(len(tables[0]))
    u_nu = np.zeros(len(tables[0]))
    worst_rule = worst_wall = worst_law = 0.0
    n_wall = n_damped = 0
    for n in range(1, len(tables)):
        T, before = tables[n], tables[n - 1]
        assert (T["x"].values == tables[0]["x"].values).all()
        p = np.maximum(-T["sigma_nu"].values, 0)
        tau = T[[f"{unknown}_tau_x", f"{unknown}_tau_y"]].values
        if cls == "quasistatic":
            u_nu = u_nu + k * T["w_nu"].values
            term = kw * k * p * np.linalg.norm(tau - vtau, axis=1)
        else:
            u_nu = T["u_nu"].values
            prev = before[["u_tau_x", "u_tau_y"]].values
            term = kw * p * np.linalg.norm(tau - prev - k * vtau, axis=1)
        # the wall of step n is at g + omega_n, the wear before the step
        wall = g + omega
        branch = T["normal_branch"].values
        scale = g + omega.max()
        worst_wall = max(worst_wall, (u_nu - wall).max() / scale)
        held = branch == 4
        if held.any():
            worst_wall = max(worst_wall, np.abs(u_nu - wall)[held].max() / scale)
            n_wall += int((held & (omega > 1e-4)).sum())
        if cls == "static":
            damped = branch == 2
            if damped.any():
                law = cp * (u_nu - omega)
                worst_law = max(worst_law, np.abs(-T["sigma_nu"].values - law)[damped].max()
                                / max(1e-12, np.abs(T["sigma_nu"].values).max()))
                n_damped += int((damped & (omega > 1e-4)).sum())
            free = branch == 0
            if free.any():
                worst_law = max(worst_law, (u_nu - omega)[free].max() / scale)
        omega = omega + term
        worst_rule = max(worst_rule, np.abs(T["wear"].values - omega).max()
                         / max(1e-12, omega.max()))
    # the nodal file's field 'wear': omega at each node's first component
    with h5py.File(sorted(glob.glob(f"{cls}/nodal_*.h5"))[-1]) as h5:
        nodes, field = h5["nodes"][:], h5["wear"][:]
    on = dict(zip(map(tuple, np.round(nodes, 9)), field[:, 0]))
    rows = map(tuple, np.round(tables[-1][["x", "y"]].values, 9))
    worst_file = max(abs(on[r] - w) for r, w in zip(rows, tables[-1]["wear"].values))
    worst_rule = max(worst_rule, worst_file / omega.max())
    print(f"{cls}: {len(tables) - 1} steps, largest wear {omega.max():.4g}, "
          f"wear against the rule {worst_rule:.3g}, wall {worst_wall:.3g} "
          f"({n_wall} held nodes with wear), law {worst_law:.3g} "
          f"({n_damped} damped nodes with wear)")
    assert omega.max() > 0.005, "the foundation does not wear"
    assert n_wall > 0, "no worn node is held at the wall"
    assert cls == "quasistatic" or n_damped > 0, "no worn node on the law"
    assert worst_rule < 1e-8 and worst_wall < 1e-8 and worst_law < 1e-8, "FAIL"
print("PASS")
PY
