#!/usr/bin/python3
"""plot_convergence.py RUN_DIR PNG: the error E_J and the estimate eta of
uniform and adaptive refinement against the number of unknowns, log-log,
from the files uniform.csv and adaptive.csv that './step-4' writes into
RUN_DIR, with the slopes N^(-1/2) (the optimal rate of Q1 in 2D) and
N^(-0.272) (the corner singularity's, gamma/2 with gamma = 0.5445);
written to PNG (doc/convergence.png is made by
  ./step-4 && doc/plot_convergence.py . doc/convergence.png).
Needs matplotlib (Debian: python3-matplotlib)."""
import csv
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

run_dir, png = sys.argv[1], sys.argv[2]
fig, ax = plt.subplots(figsize=(6, 4.5))
for name, color in (("uniform", "C0"), ("adaptive", "C1")):
    with open(f"{run_dir}/{name}.csv") as f:
        rows = list(csv.DictReader(f))
    N = np.array([float(r["dofs"]) for r in rows])
    # a row without E_J (an empty field: its energy is not above the
    # reference's) is left out of the E_J line
    E = np.array([float(r["error"]) if r["error"] else np.nan for r in rows])
    eta = np.array([float(r["estimate"]) for r in rows])
    ax.loglog(N, E, "o-", color=color, label=f"E_J, {name}")
    ax.loglog(N, eta, "s--", color=color, mfc="none",
              label=f"η, {name}")
    if name == "adaptive":
        ax.loglog(N, 0.5 * E[0] * np.sqrt(N[0] / N), "k:",
                  label="n_dofs^(-1/2)")
    else:
        ax.loglog(N, 0.5 * E[0] * (N[0] / N) ** 0.272, "k-.",
                  label="n_dofs^(-0.272)")
ax.set_xlabel("unknowns n_dofs")
ax.set_ylabel("error and estimate (energy norm)")
ax.set_title("step-4: the L-shaped body")
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(png, dpi=100)
