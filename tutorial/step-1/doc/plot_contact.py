#!/usr/bin/python3
"""plot_contact.py RUN_DIR OUTPUT.png: the figure of results.md from the
files that step-1 writes in RUN_DIR: the law (law.csv) and the contact
quantities at the load values t = 0.25, 0.5, 0.75, 1 (contact-NN.csv).
Left: the normal displacement u_nu along Gamma_3 with the law's
breakpoints; right: the nodes' (u_nu, -sigma_nu) on the graph of the
normal law (the jump [0, a] at zero, then the piecewise-linear response).
Needs matplotlib (Debian: python3-matplotlib)."""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

run_dir, output = sys.argv[1], sys.argv[2]
law = np.genfromtxt(f"{run_dir}/law.csv", delimiter=",", names=True)
kinks = law["r"][(law["is_breakpoint"] == 1) & (law["r"] > 0)]

fig, (left, right) = plt.subplots(1, 2, figsize=(10, 3.8))
right.plot(law["r"], law["xi"], color="0.6", lw=4,
           label="the law: $-\\sigma_\\nu \\in \\partial j_\\nu(u_\\nu)$")
for n in range(1, 5):
    d = np.genfromtxt(f"{run_dir}/contact-{n:02d}.csv", delimiter=",", names=True)
    left.plot(d["x"], d["u_nu"], marker=".", label=f"t = {0.25 * n:.2f}")
    right.plot(d["u_nu"], d["minus_sigma_nu"], ".", ms=7, label=f"t = {0.25 * n:.2f}")
left.axhline(0, color="k", lw=0.5)
for r in kinks:
    left.axhline(r, color="0.6", lw=0.5, ls="--")
left.set_xlabel("x on $\\Gamma_3$")
left.set_ylabel("$u_\\nu$ (> 0: penetration)")
left.legend()
right.set_xlabel("$u_\\nu$")
right.set_ylabel("$-\\sigma_\\nu$")
right.set_xlim(law["r"][0] / 5, law["r"][-1])
right.legend(fontsize=8)
fig.tight_layout()
fig.savefig(output, dpi=100)
