#!/usr/bin/python3
"""plot_nonconvex.py RUN_DIR OUTPUT.png: the figure of the study of
nonconvexity in results.md, from the files that 'step-1 nonconvex' writes
in RUN_DIR. Top: the three solutions found from the three starts (the load
path, zero, three times the first), drawn as plot_body.py draws a body
(body-path.csv, body-zero.csv, body-triple.csv). Bottom left: their
contact nodes' (u_nu, -sigma_nu) on the graph of the law
(contact-NAME.csv, law-nonconvex.csv), with a logarithmic axis beyond
u_nu = 0.01; bottom middle (with the first 5 % enlarged) and right: the energy J_h on the straight
segments from the first solution to the second and to the third
(energy-nonconvex.csv).
Needs matplotlib (Debian: python3-matplotlib)."""
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from plot_body import draw_body, legend, nice_scale, read_body, save  # noqa: E402

STARTS = [("path", "along the load path", "tab:green"),
          ("zero", "from zero", "tab:purple"),
          ("triple", "from three times the first", "tab:orange")]


def main():
    run_dir, output = sys.argv[1], sys.argv[2]
    fig, axes = plt.subplots(2, 3, figsize=(12, 6.4),
                             gridspec_kw={"height_ratios": [1.25, 1]})
    for ax, (name, start, _) in zip(axes[0], STARTS):
        body = read_body(run_dir, name)
        draw_body(ax, body, nice_scale(body), start)

    law = np.genfromtxt(f"{run_dir}/law-nonconvex.csv", delimiter=",",
                        names=True)
    ax = axes[1][0]
    ax.plot(law["r"], law["xi"], color="0.6", lw=4, label="the law")
    for name, start, colour in STARTS:
        d = np.genfromtxt(f"{run_dir}/contact-{name}.csv", delimiter=",",
                          names=True)
        ax.plot(d["u_nu"], d["minus_sigma_nu"], ".", color=colour, ms=6,
                label=start)
    ax.set_xscale("symlog", linthresh=0.01, linscale=2)
    ax.set_xlim(-0.01, 3)
    ax.set_xlabel("$u_\\nu$")
    ax.set_ylabel("$-\\sigma_\\nu$")
    ax.legend(fontsize=7)

    energy = np.genfromtxt(f"{run_dir}/energy-nonconvex.csv", delimiter=",",
                           names=True)
    for ax, column, (name, start, colour) in zip(
            axes[1][1:], ["path_to_zero", "path_to_triple"], STARTS[1:]):
        ax.plot(energy["theta"], energy[column], color=colour)
        ax.plot([0, 1], [energy[column][0], energy[column][-1]], "o",
                color=colour)
        ax.set_xlabel("$\\theta$")
        ax.set_title("$J_h(u_{path} + \\theta\\,(u_{%s} - u_{path}))$" % name,
                     fontsize=9)
        ax.ticklabel_format(axis="y", style="sci", scilimits=(-2, 2))
    # the barrier between the first two: J_h rises before it falls
    ax = axes[1][1]
    inset = ax.inset_axes([0.45, 0.5, 0.5, 0.45])
    near = energy["theta"] <= 0.05
    inset.plot(energy["theta"][near], energy["path_to_zero"][near],
               color=STARTS[1][2])
    inset.plot([0], [energy["path_to_zero"][0]], "o", color=STARTS[1][2])
    inset.set_title("$\\theta \\leq 0.05$", fontsize=8)
    inset.tick_params(labelsize=7)
    legend(fig)
    fig.tight_layout(rect=(0, 0.05, 1, 1))
    save(fig, output)


if __name__ == "__main__":
    main()
