#!/usr/bin/python3
"""Uniform against adaptive meshes on the default 2D (or 3D) example.

Every run uses prm/block_2d.prm (or block_3d.prm) with its time step. The
errors are measured against a fine uniform reference run on the contact
boundary Gamma_3, where the solution is roughest: at t = 0.3, 0.5, 0.7 and
0.9 the L2(Gamma_3) errors of the velocity w and of the contact traction
sigma, with each run's nodal values interpolated along Gamma_3 at the
reference nodes (linearly along the line in 2D; in 3D along the centre
line y = 1/2 of the contact face z = 0). They are reported
against the mean number of dofs over the run.

For each adaptive run the script also prints the number of dofs a uniform
mesh needs for the same error (log-log interpolation between the uniform
runs) and the ratio of the two: the issue's target is a ratio <= 0.5.
A run with 'pre-refinement steps' starts again from t = 0: its mean dofs are
those after the restart (the steps before it are in
pre_refinement_mean_dofs).

  /usr/bin/python3 bench/adaptivity_study.py                 # 2D, ~1.5 h from scratch
  /usr/bin/python3 bench/adaptivity_study.py --dim 3         # 3D, ~5 min
  /usr/bin/python3 bench/adaptivity_study.py --reuse         # re-read runs
  /usr/bin/python3 bench/adaptivity_study.py --dim 3 --reference 5 \
      --coarsest 2 --max-levels 3,4 --only kelly --executable /tmp/hemicontact
        # a finer reference, adaptive runs from 2 refinements (named
        # '-from2'), one variant, a copy of the binary (build/ may change)

prints the errors and ratios (also as the Markdown table of doc/adaptivity.md)
and writes bench/results/adaptivity[_3d][-fromN].csv
"""
import argparse
import glob
import os
import subprocess
import sys

import numpy as np
import pandas as pd

import vtu_fields

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "hemicontact")
TIMES = [0.3, 0.5, 0.7, 0.9]
LOWER, UPPER = (0., 0.), (4., 1.)  # the 2D block

# refine fraction 0.3, no coarsening, never coarser than the starting mesh
REFINE_ONLY = {"refine fraction": 0.3, "coarsen fraction": 0,
               "min level": "start"}

# the adaptive settings compared (all start from the coarsest uniform mesh)
ADAPTIVE = {
    # coarsening allowed down to level 1
    "kelly": {"indicator": "kelly", "refine fraction": 0.5,
              "coarsen fraction": 0.02},
    "kelly-contact": {"indicator": "kelly contact", "refine fraction": 0.5,
                      "coarsen fraction": 0.02},
    "kelly-contact-w4": {"indicator": "kelly contact", "contact weight": 4,
                         "refine fraction": 0.5, "coarsen fraction": 0.02},
    "kelly-f03": {"indicator": "kelly", "refine fraction": 0.3,
                  "coarsen fraction": 0.02},
    # "start": never coarser than the starting mesh
    "kelly-minstart": {"indicator": "kelly", "refine fraction": 0.5,
                       "coarsen fraction": 0.02, "min level": "start"},
    "kelly-contact-minstart": {"indicator": "kelly contact",
                               "refine fraction": 0.5,
                               "coarsen fraction": 0.02,
                               "min level": "start"},
    "kelly-f03-minstart-interval10": {"indicator": "kelly",
                                      "refine fraction": 0.3,
                                      "coarsen fraction": 0.02,
                                      "min level": "start", "interval": 10},
    # refinement only
    "kelly-f03-nocoarsen-minstart": {"indicator": "kelly", **REFINE_ONLY},
    "kelly-contact-f03-nocoarsen-minstart": {"indicator": "kelly contact",
                                             **REFINE_ONLY},
    "kelly-contact-w025-f03-nocoarsen-minstart": {
        "indicator": "kelly contact", "contact weight": 0.25, **REFINE_ONLY},
    # the residual indicator, with coarsening as 'kelly', refinement only,
    # and refinement only with a restart after 50 steps
    "residual": {"indicator": "residual", "refine fraction": 0.5,
                 "coarsen fraction": 0.02},
    "residual-f03-nocoarsen-minstart": {"indicator": "residual",
                                        **REFINE_ONLY},
    "residual-f03-nocoarsen-minstart-pre50": {
        "indicator": "residual", "pre-refinement steps": 50, **REFINE_ONLY},
    "residual-pre50": {"indicator": "residual", "refine fraction": 0.5,
                       "coarsen fraction": 0.02, "pre-refinement steps": 50},
    "residual-w4-f03-nocoarsen-minstart-pre50": {
        "indicator": "residual", "contact weight": 4,
        "pre-refinement steps": 50, **REFINE_ONLY},
    # coarsening with 'state transfer = projection' (state_projection.cc)
    "kelly-project": {"indicator": "kelly", "refine fraction": 0.5,
                      "coarsen fraction": 0.02,
                      "state transfer": "projection"},
    "kelly-contact-project": {"indicator": "kelly contact",
                              "refine fraction": 0.5,
                              "coarsen fraction": 0.02,
                              "state transfer": "projection"},
    "residual-project": {"indicator": "residual", "refine fraction": 0.5,
                         "coarsen fraction": 0.02,
                         "state transfer": "projection"},
    # (the variants 'kelly energy', 'kelly stress' and 'indicator
    # accumulation' of doc/adaptivity.md were measured with an experimental
    # build that was not merged)
    # restart from t = 0 on the mesh after this many steps (step-26)
    "kelly-f03-nocoarsen-minstart-pre20": {
        "indicator": "kelly", "pre-refinement steps": 20, **REFINE_ONLY},
    **{f"kelly-contact-f03-nocoarsen-minstart-pre{p}": {
        "indicator": "kelly contact", "pre-refinement steps": p,
        **REFINE_ONLY} for p in (30, 50, 70, 100)},
    **{f"kelly-contact-w{name}-f03-nocoarsen-minstart-pre50": {
        "indicator": "kelly contact", "contact weight": weight,
        "pre-refinement steps": 50, **REFINE_ONLY}
       for name, weight in (("05", 0.5), ("2", 2))},
    # a cell budget: no refinement once the mesh has this many cells
    "kelly-f03-nocoarsen-minstart-maxcells8192": {
        "indicator": "kelly", "max cells": 8192, **REFINE_ONLY},
}


def run(work, base, name, refinements, adaptivity=None, reuse=False):
    directory = os.path.join(work, name)
    if reuse and os.path.exists(os.path.join(directory, "steps.csv")):
        return directory
    os.makedirs(directory, exist_ok=True)
    text = open(os.path.join(ROOT, "prm", base)).read()
    text += "subsection geometry\n  set global refinements = %d\nend\n" % refinements
    text += ("subsection output\n  set directory = %s\n  set output interval = 10\n"
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


def boundary_fields(directory, time, dim):
    for f in sorted(glob.glob(os.path.join(directory, "contact_*.csv"))):
        data = pd.read_csv(f)
        if abs(data["time"].iloc[0] - time) < 1e-9:
            if dim == 3:
                # the nodes on the centre line of the contact face
                y_mid = 0.5 * (data["y"].min() + data["y"].max())
                data = data[np.abs(data["y"] - y_mid) < 1e-9]
            return data.sort_values("x")
    raise RuntimeError("no contact CSV at t = %g in %s" % (time, directory))


def body_errors(directory, reference_grids, result):
    """L2 and H1 errors of w in the body at TIMES (2D: the block [0,4]x[0,1]
    with the reference's uniform grid)."""
    for time, (reference, n_cells) in reference_grids.items():
        arrays = vtu_fields.read_vtu(vtu_at(directory, time))
        grid = vtu_fields.fine_grid_values(arrays, "velocity", LOWER, UPPER,
                                           n_cells)
        result["wL2_t%g" % time], result["wH1_t%g" % time] = \
            vtu_fields.l2_and_h1_norms(grid - reference, LOWER, UPPER)


def vtu_at(directory, time):
    """The VTU of the step at @p time (output interval 10, k = 0.01)."""
    return os.path.join(directory, "solution_%05d.0.vtu" % round(time / 0.01))


def reference_grids(directory, level):
    n_cells = (4 * 2 ** level, 2 ** level)
    return {time: (vtu_fields.fine_grid_values(
        vtu_fields.read_vtu(vtu_at(directory, time)), "velocity", LOWER, UPPER,
        n_cells), n_cells) for time in TIMES}


def errors(directory, reference, dim, grids=None):
    result = {}
    if grids:
        body_errors(directory, grids, result)
    axes = "xyz"[:dim]
    tangential = ["w_tau_" + a for a in axes]
    traction = ["sigma_tau_" + a for a in axes]
    for time in TIMES:
        ref = boundary_fields(reference, time, dim)
        run_ = boundary_fields(directory, time, dim)
        x = ref["x"].to_numpy()
        for field, columns in (("w", ["w_nu"] + tangential),
                               ("sigma", ["sigma_nu"] + traction)):
            sq = np.zeros_like(x)
            for c in columns:
                sq += (np.interp(x, run_["x"], run_[c]) - ref[c].to_numpy()) ** 2
            result["%s_t%g" % (field, time)] = np.sqrt(np.trapz(sq, x))
    steps = pd.read_csv(os.path.join(directory, "steps.csv"))
    # a run with pre-refinement starts again from t = 0: the dofs of the
    # measured run are those after the (last) restart
    restarts = np.where(np.diff(steps["time"].to_numpy()) < 0)[0]
    result["pre_refinement_steps"] = 0
    if len(restarts):
        result["pre_refinement_steps"] = restarts[-1] + 1
        result["pre_refinement_mean_dofs"] = \
            steps["n_dofs"].iloc[:restarts[-1] + 1].mean()
        steps = steps.iloc[restarts[-1] + 1:]
    result["mean_dofs"] = steps["n_dofs"].mean()
    result["max_dofs"] = steps["n_dofs"].max()
    result["adaptations"] = int(steps["adapted"].sum())
    return result


def uniform_dofs_for(error, uniform, column):
    """Dofs of a uniform mesh with this error in @p column: log-log
    interpolation between the uniform runs (extrapolation by the nearest two
    beyond them)."""
    dofs = np.log(uniform["mean_dofs"].to_numpy())
    err = np.log(uniform[column].to_numpy())
    order = np.argsort(err)
    dofs, err = dofs[order], err[order]
    i = np.clip(np.searchsorted(err, np.log(error)), 1, len(err) - 1)
    slope = (dofs[i] - dofs[i - 1]) / (err[i] - err[i - 1])
    return float(np.exp(dofs[i - 1] + slope * (np.log(error) - err[i - 1])))


def print_markdown(table, fields):
    """The table of doc/adaptivity.md: errors and uniform-dof ratios."""
    names = {"w": "w on Γ3", "sigma": "σ on Γ3", "wL2": "w in L2(Ω)",
             "wH1": "w in H1(Ω)"}
    print("\n| case | mean dofs | " + " | ".join(
        "%s (ratio)" % names[f] for f in fields) + " |")
    print("|---|---|" + "---|" * len(fields))
    for _, row in table.iterrows():
        cells = ["%.2e" % row[f + "_mean"] +
                 ("" if row["case"].startswith("uniform") else
                  " (%.2f)" % row["dof_ratio_" + f]) for f in fields]
        print("| %s | %s | %s |" % (row["case"], "{:,.0f}".format(
            row["mean_dofs"]), " | ".join(cells)))
    print()


def main():
    global EXE
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--dim", type=int, default=2, choices=(2, 3))
    parser.add_argument("--reference", type=int, default=None,
                        help="refinements of the reference (2D: 8, 3D: 4)")
    parser.add_argument("--max-levels", default=None,
                        help="comma-separated max levels of the adaptive runs")
    parser.add_argument("--only", default=None,
                        help="comma-separated adaptive variants to run")
    parser.add_argument("--reuse", action="store_true",
                        help="reuse finished runs in the work directory")
    parser.add_argument("--coarsest", type=int, default=None,
                        help="refinements of the adaptive runs' starting mesh "
                        "(2D: 3, 3D: 1); another value is named in the case")
    parser.add_argument("--executable", default=EXE,
                        help="the hemicontact binary (default build/hemicontact;"
                        " a copy lets the build directory change meanwhile)")
    args = parser.parse_args()
    EXE = args.executable

    dim = args.dim
    base = "block_%dd.prm" % dim
    work = os.path.join(ROOT, "bench", "work",
                        "adaptivity" + ("" if dim == 2 else "_3d"))
    reference_level = args.reference or (8 if dim == 2 else 4)
    default_coarsest = 3 if dim == 2 else 1
    coarsest = args.coarsest or default_coarsest
    start = "" if coarsest == default_coarsest else "-from%d" % coarsest
    uniform_levels = range(coarsest, reference_level)
    max_levels = [int(v) for v in (args.max_levels or
                                   ("5,6,7" if dim == 2 else "2,3")).split(",")]
    variants = ADAPTIVE if not args.only else {
        k: ADAPTIVE[k] for k in args.only.split(",")}

    reference = run(work, base, "reference-r%d" % reference_level,
                    reference_level, reuse=args.reuse)
    cases = [("uniform-r%d" % r, r, None) for r in uniform_levels]
    for max_level in max_levels:
        for variant, settings in variants.items():
            adaptivity = {"interval": 2, "strategy": "fixed fraction",
                          "min level": 1, "max level": max_level}
            adaptivity.update(settings)
            if adaptivity["min level"] == "start":
                adaptivity["min level"] = coarsest
            cases.append(("adaptive-%s%s-L%d" % (variant, start, max_level),
                          coarsest,
                          adaptivity))
    grids = reference_grids(reference, reference_level) if dim == 2 else None
    rows = []
    for name, r, adaptivity in cases:
        row = {"case": name}
        row.update(errors(run(work, base, name, r, adaptivity, args.reuse),
                          reference, dim, grids))
        rows.append(row)
    table = pd.DataFrame(rows)
    fields = ["w", "sigma"] + (["wL2", "wH1"] if dim == 2 else [])
    for field in fields:
        table[field + "_mean"] = table[["%s_t%g" % (field, t)
                                        for t in TIMES]].mean(axis=1)
    uniform = table[table["case"].str.startswith("uniform")]
    for field in fields:
        table["uniform_dofs_same_" + field] = [
            uniform_dofs_for(e, uniform, field + "_mean")
            for e in table[field + "_mean"]]
        table["dof_ratio_" + field] = (table["mean_dofs"] /
                                       table["uniform_dofs_same_" + field])

    pd.set_option("display.width", 250)
    print("reference: uniform r%d; errors on Gamma_3 averaged over t = %s" %
          (reference_level, ", ".join("%g" % t for t in TIMES)))
    print(table[["case", "mean_dofs", "max_dofs"] +
                [f + "_mean" for f in fields] +
                ["dof_ratio_" + f for f in fields]].to_string(
                     index=False, float_format=lambda v: "%.3e" % v))
    print_markdown(table, fields)
    out = os.path.join(ROOT, "bench", "results", "adaptivity%s%s.csv" %
                       ("" if dim == 2 else "_3d", start))
    os.makedirs(os.path.dirname(out), exist_ok=True)
    table.to_csv(out, index=False)
    print("written to", out)


if __name__ == "__main__":
    main()
