#!/usr/bin/python3
"""plot_law.py RUN_DIR OUTPUT.png: the figure of intro.md from the law that
step-1 writes in RUN_DIR (law.csv: r, xi, potential, is_breakpoint).
Left: the graph of the Clarke subdifferential of j_nu, a set-valued map
(the vertical segment [0, a] at r = 0, single values elsewhere); right:
the potential j_nu, which is not convex where the law falls, and
j_nu + alpha_nu r^2 / 2, which is, with alpha_nu the steepest descent slope
of the law computed from its breakpoints.
Needs matplotlib (Debian: python3-matplotlib)."""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

run_dir, output = sys.argv[1], sys.argv[2]
law = np.genfromtxt(f"{run_dir}/law.csv", delimiter=",", names=True)
points = law[law["is_breakpoint"] == 1]
slopes = np.diff(points["xi"]) / np.diff(points["r"])
alpha = max(0.0, -slopes.min())
r, xi, j = law["r"], law["xi"], law["potential"]

fig, (left, right) = plt.subplots(1, 2, figsize=(10, 3.8))
left.plot(r, xi, color="C0", lw=2)
left.plot([0, 0], [0, points["xi"][0]], color="C3", lw=4,
          label="$\\partial j_\\nu(0) = [0, a]$")
for k, (rk, xk) in enumerate(zip(points["r"], points["xi"])):
    if rk > 0:
        left.plot(rk, xk, "ko", ms=4)
left.set_xlabel("$r = u_\\nu$ (> 0: penetration)")
left.set_ylabel("$\\xi \\in \\partial j_\\nu(r)$")
left.set_title("the law: rises, then falls")
left.legend(loc="lower right")
right.plot(r, j, color="C0", lw=2, label="$j_\\nu(r) = \\int_0^r \\xi$")
right.plot(r, j + alpha * r**2 / 2, color="C2", lw=2, ls="--",
           label=f"$j_\\nu + \\alpha_\\nu r^2/2$, $\\alpha_\\nu = {alpha:.3g}$")
right.set_xlabel("$r$")
right.set_title("the potential: not convex; convex once relaxed")
right.legend()
fig.tight_layout()
fig.savefig(output, dpi=100)
