#!/usr/bin/python3
"""Draws doc/figures/reduced-regularity.png from bench/results/reduced_regularity.csv
(bench/reduced_regularity_study.py): E_J and the estimate against the dofs for
uniform, Kelly-adapted and estimator-adapted meshes, with the slopes -1/2 and
the uniform family's.

  /usr/bin/python3 bench/plot_reduced_regularity.py
"""
import os

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import pandas as pd

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
data = pd.read_csv(os.path.join(ROOT, "bench", "results", "reduced_regularity.csv"))
fig, ax = plt.subplots(figsize=(6.4, 4.4))
for (family, group), marker in zip(data.groupby("family", sort=False), "osd"):
    slope = group.slope_last_four.iloc[0]
    ax.loglog(group.dofs, group.E_J, marker=marker, label=f"{family}: E_J (last slope {slope:.2f})")
    if family == "estimator":
        ax.loglog(group.dofs, group.estimate, marker=marker, ls="--", color="0.4",
                  label="estimator: the estimate $\\eta$")
n0, e0 = 1e3, 0.02
ax.loglog([n0, 1e5], [e0, e0 * (1e5 / n0) ** -0.5], color="k", lw=0.8, label="$N^{-1/2}$")
ax.set_xlabel("dofs N")
ax.set_ylabel("energy error $E_J$, estimate")
ax.set_title("L-shaped body on a Signorini foundation (prm/l_shape_signorini.prm)", fontsize=9)
ax.legend(fontsize=8)
fig.savefig(os.path.join(ROOT, "doc", "figures", "reduced-regularity.png"), dpi=110, bbox_inches="tight")
print("wrote doc/figures/reduced-regularity.png")
