#!/usr/bin/python3
"""Uniform against adaptive meshes on the default 2D example.

Every run uses prm/block_2d.prm with its time step (k = 0.01). The errors
are measured against a fine uniform reference run (7 global refinements,
132k dofs) on the contact boundary Gamma_3, where the solution is roughest:
at t = 0.3, 0.5, 0.7 and 0.9 the L2(Gamma_3) errors of the velocity w and of
the contact traction sigma nu, with each run's nodal values interpolated
linearly along Gamma_3 at the reference nodes. They are reported against
the mean number of dofs over the run.

  /usr/bin/python3 bench/adaptivity_study.py     # ~5 min; writes bench/results/adaptivity.csv
"""
import csv
import glob
import os
import subprocess
import sys

import numpy as np
import pandas as pd

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "hemicontact")
WORK = os.path.join(ROOT, "bench", "work", "adaptivity")
TIMES = [0.3, 0.5, 0.7, 0.9]


def run(name, refinements, adaptivity=None):
    directory = os.path.join(WORK, name)
    os.makedirs(directory, exist_ok=True)
    text = open(os.path.join(ROOT, "prm", "block_2d.prm")).read()
    text += "subsection geometry\n  set global refinements = %d\nend\n" % refinements
    text += ("subsection output\n  set directory = %s\n  set vtu interval = 10\n"
             "  set terminal = quiet\n  set timing summary = false\nend\n" % directory)
    if adaptivity:
        text += "subsection adaptivity\n"
        for key, value in adaptivity.items():
            text += "  set %s = %s\n" % (key, value)
        text += "end\n"
    prm = os.path.join(directory, "run.prm")
    open(prm, "w").write(text)
    print("running", name, file=sys.stderr, flush=True)
    subprocess.run([EXE, prm], check=True, stdout=subprocess.DEVNULL)
    return directory


def boundary_fields(directory, time):
    files = sorted(glob.glob(os.path.join(directory, "contact_*.csv")))
    for f in files:
        data = pd.read_csv(f)
        if abs(data["time"].iloc[0] - time) < 1e-9:
            return data.sort_values("x")
    raise RuntimeError("no contact CSV at t = %g in %s" % (time, directory))


def errors(directory, reference):
    result = {}
    for time in TIMES:
        ref = boundary_fields(reference, time)
        run_ = boundary_fields(directory, time)
        x = ref["x"].to_numpy()
        for field, columns in (("w", ["w_nu", "w_tau_x"]),
                               ("sigma", ["sigma_nu", "sigma_tau_x"])):
            sq = np.zeros_like(x)
            for c in columns:
                sq += (np.interp(x, run_["x"], run_[c]) - ref[c].to_numpy()) ** 2
            result["%s_t%g" % (field, time)] = np.sqrt(np.trapz(sq, x))
    steps = pd.read_csv(os.path.join(directory, "steps.csv"))
    result["mean_dofs"] = steps["n_dofs"].mean()
    result["max_dofs"] = steps["n_dofs"].max()
    return result


def main():
    reference = run("reference-r7", 7)
    cases = [("uniform-r%d" % r, r, None) for r in (3, 4, 5, 6)]
    for max_level in (5, 6, 7):
        cases.append(("adaptive-kelly-contact-L%d" % max_level, 3, {
            "interval": 2, "indicator": "kelly contact",
            "strategy": "fixed fraction", "refine fraction": 0.5,
            "coarsen fraction": 0.02, "min level": 1,
            "max level": max_level}))
        cases.append(("adaptive-kelly-L%d" % max_level, 3, {
            "interval": 2, "indicator": "kelly",
            "strategy": "fixed fraction", "refine fraction": 0.5,
            "coarsen fraction": 0.02, "min level": 1,
            "max level": max_level}))
    rows = []
    for name, r, adaptivity in cases:
        row = {"case": name}
        row.update(errors(run(name, r, adaptivity), reference))
        rows.append(row)
    table = pd.DataFrame(rows)
    table["w_mean"] = table[["w_t%g" % t for t in TIMES]].mean(axis=1)
    table["sigma_mean"] = table[["sigma_t%g" % t for t in TIMES]].mean(axis=1)
    pd.set_option("display.width", 200)
    print(table[["case", "mean_dofs", "max_dofs", "w_mean", "sigma_mean"] +
                ["sigma_t%g" % t for t in TIMES]].to_string(
                    index=False, float_format=lambda v: "%.3e" % v))
    out = os.path.join(ROOT, "bench", "results", "adaptivity.csv")
    os.makedirs(os.path.dirname(out), exist_ok=True)
    table.to_csv(out, index=False)
    print("written to", out)


if __name__ == "__main__":
    main()
