#!/usr/bin/python3
"""Error against dofs: uniform meshes and the refinement indicators.

Runs the h-study of prm/verification/mms_2d_quad_static.prm (the static
class, a manufactured solution) with the error estimate on
('output/error estimate', doc/theory.md 12): on uniform meshes, and on
adaptive meshes (adapted after every load value, as
mms_2d_quad_exponential_adaptive.prm: 'fixed number' 0.3/0.1, 100 cells at
the first level, the limits growing with the level) with each indicator.
Prints, per study and level, the mean dofs over the load values, the energy
error E_energy, the estimate and the effectivity index, and the fitted
log-log slope of E_energy against the mean dofs (the optimal -1/2 in 2D),
as the Markdown table of doc/adaptivity.md.

  /usr/bin/python3 bench/estimator_adaptivity_study.py             # ~5 min
  /usr/bin/python3 bench/estimator_adaptivity_study.py --levels 4

Writes bench/results/estimator_adaptivity.csv; the runs go to
bench/work/estimator_adaptivity/.
"""
import argparse
import os
import subprocess
import sys

import numpy as np
import pandas as pd

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WORK = os.path.join(ROOT, "bench", "work", "estimator_adaptivity")
RESULTS = os.path.join(ROOT, "bench", "results")
PRM = os.path.join(ROOT, "prm", "verification", "mms_2d_quad_static.prm")
ADAPTIVITY = {"interval": 1, "strategy": "fixed number",
              "refine fraction": 0.3, "coarsen fraction": 0.1,
              "max cells": 100, "min level": 2, "max level": 6}
STUDIES = ["uniform", "kelly", "residual", "estimator"]


def run(name, levels, executable):
    """Run one study; return its convergence table."""
    directory = os.path.join(WORK, name)
    os.makedirs(directory, exist_ok=True)
    text = open(PRM).read()
    text += ("subsection convergence study\n  set levels = %d\nend\n"
             "subsection output\n  set directory = %s\n"
             "  set error estimate = true\nend\n" % (levels, directory))
    if name != "uniform":
        text += "subsection adaptivity\n  set indicator = %s\n" % name
        text += "".join("  set %s = %s\n" % kv for kv in ADAPTIVITY.items())
        text += "end\n"
    prm = os.path.join(directory, "study.prm")
    open(prm, "w").write(text)
    print("running", name, file=sys.stderr, flush=True)
    with open(os.path.join(directory, "log.txt"), "w") as log:
        subprocess.run([executable, prm], check=True, stdout=log,
                       stderr=subprocess.STDOUT, cwd=directory)
    return pd.read_csv(os.path.join(directory, "convergence.csv"))


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--levels", type=int, default=5)
    parser.add_argument("--executable",
                        default=os.path.join(ROOT, "build", "hemicontact"))
    args = parser.parse_args()
    rows = []
    for name in STUDIES:
        table = run(name, args.levels, args.executable)
        dofs = table["mean_dofs"]
        for i in range(len(table)):
            rows.append({"study": name, "level": int(table["level"][i]),
                         "mean_dofs": float(dofs[i]),
                         "E_energy": float(table["E_energy"][i]),
                         "estimate": float(table["estimate"][i]),
                         "effectivity": float(table["effectivity"][i])})
    result = pd.DataFrame(rows)
    os.makedirs(RESULTS, exist_ok=True)
    result.to_csv(os.path.join(RESULTS, "estimator_adaptivity.csv"),
                  index=False)

    uniform = result[result.study == "uniform"]

    def uniform_error(dofs):
        """The uniform E_energy at @p dofs (log-log interpolation)."""
        if dofs < uniform.mean_dofs.min() or dofs > uniform.mean_dofs.max():
            return np.nan
        return np.exp(np.interp(np.log(dofs), np.log(uniform.mean_dofs),
                                np.log(uniform.E_energy)))

    print("| study | mean dofs per level | E_energy per level "
          "| / uniform at the same dofs | effectivity "
          "| slope of E_energy against dofs |")
    print("|---|---|---|---|---|---|")
    for name in STUDIES:
        part = result[result.study == name]
        slope = np.polyfit(np.log(part.mean_dofs), np.log(part.E_energy), 1)[0]
        ratios = [e / uniform_error(d)
                  for d, e in zip(part.mean_dofs, part.E_energy)]
        print("| %s | %s | %s | %s | %.2f–%.2f | %.2f |" % (
            name, "/".join("{:,.0f}".format(d) for d in part.mean_dofs),
            "/".join("%.3g" % e for e in part.E_energy),
            "/".join("–" if np.isnan(r) else "%.2f" % r for r in ratios),
            part.effectivity.min(), part.effectivity.max(), slope))


if __name__ == "__main__":
    main()
