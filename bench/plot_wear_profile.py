#!/usr/bin/python3
"""Draws doc/figures/wear-profile.png from the contact CSVs of
prm/wear_block_2d.prm (doc/examples.md, "Wear"): the wear depth omega(x)
along the contact boundary at several load values (left), and the contact
pressure -sigma_nu at the same values (right).

  ./build/hemicontact prm/wear_block_2d.prm
  /usr/bin/python3 bench/plot_wear_profile.py [output-wear-block-2d]

HEMICONTACT_OUTPUT_ROOT=dir writes the figure to dir/doc/figures/.
"""
import glob
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import pandas as pd

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
run = sys.argv[1] if len(sys.argv) > 1 else os.path.join(ROOT, "output-wear-block-2d")
files = sorted(glob.glob(os.path.join(run, "contact_*.csv")))
assert files, f"no contact CSV in {run}: run prm/wear_block_2d.prm first"
tables = [pd.read_csv(f) for f in files]
shown = [tables[i] for i in sorted({1, len(tables) // 4, len(tables) // 2,
                                    3 * len(tables) // 4, len(tables) - 1})]

fig, (left, right) = plt.subplots(1, 2, figsize=(10, 3.8))
colors = plt.cm.viridis([i / max(1, len(shown) - 1) for i in range(len(shown))])
for table, color in zip(shown, colors):
    t = table["time"].iloc[0]
    left.plot(table["x"], table["wear"], color=color, label=f"t = {t:g}")
    right.plot(table["x"], -table["sigma_nu"], color=color, label=f"t = {t:g}")
left.set_xlabel("x")
left.set_ylabel("wear depth $\\omega$")
left.set_title("wear profile (up to the state written)", fontsize=9)
right.set_xlabel("x")
right.set_ylabel("contact pressure $-\\sigma_\\nu$")
right.set_title("pressure: the peak at the free right end flattens as it wears",
                fontsize=9)
for ax in (left, right):
    ax.legend(fontsize=8)
    ax.grid(alpha=0.3)
fig.suptitle("Block on a foundation moving with v* = (1, 0), Archard wear "
             "(prm/wear_block_2d.prm)", fontsize=10)
out = os.path.join(os.environ.get("HEMICONTACT_OUTPUT_ROOT", ROOT), "doc", "figures")
os.makedirs(out, exist_ok=True)
fig.savefig(os.path.join(out, "wear-profile.png"), dpi=110, bbox_inches="tight")
print(f"wrote {os.path.join(out, 'wear-profile.png')}")
