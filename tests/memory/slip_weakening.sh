#!/usr/bin/env bash
# slip_weakening.sh EXE WORKDIR PRM: the run of PRM (a friction bound in the
# accumulated slip s_tau, mu*pos(p_nu)*(0.4 + 0.6*exp(-s_tau/0.02)); doc/
# theory.md, section 11.10), in its quasistatic class and in the static
# class, writes in its contact CSVs an s_tau that follows the rule at every
# contact node, S_n = sum_{j=1}^{n-1} k |w_tau,j| (quasistatic) and
# S_n = sum_{j=1}^{n-1} |u_tau,j - u_tau,j-1| (static, from u_0): the
# row of step n holds S_{n+1}, the slip up to the state written, and a
# friction bound equal to the expression at S_n; to the CSV's 10 digits. The slip must grow (the test fails on a run that never slides).
set -euo pipefail
exe=$1; work=$2; prm=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
for class in quasistatic static; do
  sed "s/set class *=.*/set class = $class/; s/set directory *=.*/set directory = $class/" \
    "$prm" > $class.prm
  "$exe" $class.prm > $class.log
done
/usr/bin/python3 - <<'PY'
import glob, math
import numpy as np, pandas as pd
k = 0.0625
for cls, unknown in (("quasistatic", "w"), ("static", "u")):
    files = sorted(glob.glob(f"{cls}/contact_*.csv"))
    tables = [pd.read_csv(f) for f in files]
    S = np.zeros(len(tables[0]))
    worst_slip = worst_bound = 0.0
    largest = 0.0
    for n in range(1, len(tables)):
        T = tables[n]
        assert (T["x"].values == tables[0]["x"].values).all()
        # the bound of step n read S_n, the slip before it
        p = np.maximum(-tables[n - 1 if cls == "quasistatic" else n]["sigma_nu"].values, 0)
        bound = 0.3 * p * (0.4 + 0.6 * np.exp(-S / 0.02))
        worst_bound = max(worst_bound, np.abs(T["friction_bound"].values - bound).max()
                          / max(1e-12, np.abs(bound).max()))
        # the slip of step n joins S: the row's s_tau, S_{n+1}
        tau = np.stack([T[f"{unknown}_tau_x"].values, T[f"{unknown}_tau_y"].values], 1)
        if cls == "quasistatic":
            S = S + k * np.linalg.norm(tau, axis=1)
        else:
            before = tables[n - 1]
            prev = np.stack([before["u_tau_x"].values, before["u_tau_y"].values], 1)
            S = S + np.linalg.norm(tau - prev, axis=1)
        worst_slip = max(worst_slip, np.abs(T["s_tau"].values - S).max()
                         / max(1e-12, np.abs(S).max()))
        largest = max(largest, np.abs(S).max())
    print(f"{cls}: {len(tables) - 1} steps, largest s_tau {largest:.4g}, "
          f"s_tau against the rule {worst_slip:.3g}, bound {worst_bound:.3g}")
    assert largest > 0.01, "the block does not slide"
    assert worst_slip < 1e-8 and worst_bound < 1e-8, "FAIL"
print("PASS")
PY
