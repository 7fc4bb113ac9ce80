#!/usr/bin/python3
"""plot_contact.py RUN_DIR OUTPUT.png [COEFFICIENT]: the contact pressure
p_nu = -sigma_nu, the shear |sigma_tau| and the Coulomb bound
COEFFICIENT * p_nu (default 0.3, the block's) along the contact boundary,
from the file contact-04.csv that 'step-5 block' writes in RUN_DIR (the
full load t = 1). Where the body sticks the shear lies below the bound,
where it slips on the bound, and where it has left the wall both vanish.
Needs matplotlib (Debian: python3-matplotlib)."""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

run_dir, output = sys.argv[1], sys.argv[2]
coefficient = float(sys.argv[3]) if len(sys.argv) > 3 else 0.3
table = np.genfromtxt(f"{run_dir}/contact-04.csv", delimiter=",", names=True)
x = table["x"]
pressure = np.maximum(table["minus_sigma_nu"], 0)
shear = np.abs(table["sigma_tau"])
contact = table["normal_branch"] == 1
slip = contact & (table["tangential_branch"] == 1)

fig, ax = plt.subplots(figsize=(7, 3.4))
ax.plot(x, pressure, "-", color="tab:blue", label="pressure $p_\\nu$")
ax.plot(x, coefficient * pressure, "--", color="k",
        label=f"Coulomb bound {coefficient:g} $p_\\nu$")
ax.plot(x, shear, "-", color="tab:orange", label="shear $|\\sigma_\\tau|$")
ax.plot(x[slip], shear[slip], "^", color="tab:red", label="slip")
ax.plot(x[contact & ~slip], shear[contact & ~slip], "o", ms=3,
        color="tab:green", label="stick")
ax.axvspan(x.min(), x[contact].min(), color="0.92", zorder=0)
ax.text(0.5 * (x.min() + x[contact].min()), 0.9 * pressure.max(),
        "separated", ha="center", fontsize=9)
ax.set_xlabel("x along the contact boundary")
ax.set_ylabel("traction")
ax.set_title("step-5: the block at t = 1")
ax.legend(fontsize=8, loc="upper left", bbox_to_anchor=(0.02, 0.8))
fig.tight_layout()
fig.savefig(output, dpi=90)
