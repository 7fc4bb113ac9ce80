#!/usr/bin/python3
"""Uniform against adaptive meshes on a manufactured solution.

Runs the coupled convergence study of
prm/verification/mms_2d_quad_exponential.prm (uniform meshes) and of
prm/verification/mms_2d_quad_exponential_adaptive.prm (the same case and
k sequence on adaptive meshes) with the same number of levels, and compares
the errors E_H, E_V, E_u (doc/theory.md section 5) against the mean number of
dofs over the steps: the observed rate between consecutive levels,
-log(E ratio) / log(dofs ratio), and the fitted log-log slope over all levels
and over the last three. In 2D the uniform rate O(h) is 1/2 against dofs.
It also gives the adaptive error over the uniform one at the same dofs
(log-log interpolation of the uniform errors, where the dofs lie in their
range).

  /usr/bin/python3 bench/adaptive_mms_study.py             # ~6 min on 2 cores
  /usr/bin/python3 bench/adaptive_mms_study.py --levels 4  # ~2 min
  /usr/bin/python3 bench/adaptive_mms_study.py --name fn160 \\
      --set "max cells=160"                                # a variant

Writes bench/results/adaptive_mms.csv (one row per study and level) and
bench/results/adaptive_mms_rates.csv (the fitted slopes), with "-NAME"
before ".csv" for a --name other than "adaptive"; the runs go to
bench/work/adaptive_mms/NAME.
"""
import argparse
import os
import subprocess
import sys

import numpy as np
import pandas as pd

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "hemicontact")
WORK = os.path.join(ROOT, "bench", "work", "adaptive_mms")
RESULTS = os.path.join(ROOT, "bench", "results")
CASES = {"uniform": "mms_2d_quad_exponential.prm",
         "adaptive": "mms_2d_quad_exponential_adaptive.prm"}
ERRORS = ["E_H", "E_V", "E_u"]


def run(name, case, levels, adaptivity, skip):
    """Run one study (unless @p skip and it exists); return its table."""
    directory = os.path.join(WORK, name)
    csv = os.path.join(directory, "convergence.csv")
    if skip and os.path.exists(csv):
        return pd.read_csv(csv)
    os.makedirs(directory, exist_ok=True)
    text = open(os.path.join(ROOT, "prm", "verification", CASES[case])).read()
    text += ("subsection convergence study\n  set levels = %d\nend\n"
             "subsection output\n  set directory = %s\nend\n"
             % (levels, directory))
    if adaptivity:
        text += "subsection adaptivity\n"
        text += "".join("  set %s = %s\n" % kv for kv in adaptivity.items())
        text += "end\n"
    prm = os.path.join(directory, "study.prm")
    open(prm, "w").write(text)
    print("running", name, file=sys.stderr, flush=True)
    with open(os.path.join(directory, "study.log"), "w") as log:
        subprocess.run([EXE, prm], check=True, stdout=log)
    return pd.read_csv(csv)


def slope(dofs, error):
    """Minus the least-squares slope of log(error) against log(dofs)."""
    return -np.polyfit(np.log(dofs), np.log(error), 1)[0]


def with_rates(df):
    out = df.copy()
    for e in ERRORS:
        out["rate_" + e] = [np.nan] + [
            -np.log(b / a) / np.log(m / n) for a, b, n, m in
            zip(df[e][:-1], df[e][1:], df.mean_dofs[:-1], df.mean_dofs[1:])]
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--levels", type=int, default=5)
    parser.add_argument("--name", default="adaptive",
                        help="name of the adaptive run (default: adaptive)")
    parser.add_argument("--set", action="append", default=[],
                        metavar="KEY=VALUE",
                        help="override an 'adaptivity' parameter of the "
                             "adaptive study")
    parser.add_argument("--skip-existing", action="store_true",
                        help="reuse the convergence.csv of earlier runs")
    args = parser.parse_args()
    adaptivity = dict(s.split("=", 1) for s in args.set)

    studies = {
        "uniform": run("uniform-L%d" % args.levels, "uniform", args.levels,
                       None, args.skip_existing),
        args.name: run("%s-L%d" % (args.name, args.levels), "adaptive",
                       args.levels, adaptivity, args.skip_existing)}

    rows, fits = [], []
    uniform = studies["uniform"]
    for name, df in studies.items():
        df = with_rates(df)
        for e in ERRORS:
            # the adaptive error over the uniform one at the same dofs
            inside = ((df.mean_dofs >= uniform.mean_dofs.min()) &
                      (df.mean_dofs <= uniform.mean_dofs.max()))
            at_dofs = np.exp(np.interp(np.log(df.mean_dofs),
                                       np.log(uniform.mean_dofs),
                                       np.log(uniform[e])))
            df["vs_uniform_" + e] = np.where(inside, df[e] / at_dofs, np.nan)
        df.insert(0, "study", name)
        rows.append(df)
        fit = {"study": name, "levels": len(df)}
        for e in ERRORS:
            fit["slope_" + e] = slope(df.mean_dofs, df[e])
            fit["slope_last3_" + e] = slope(df.mean_dofs[-3:], df[e][-3:])
        fits.append(fit)

    table = pd.concat(rows, ignore_index=True)
    columns = (["study", "level", "k", "mean_dofs", "max_dofs", "n_steps"] +
               [c for e in ERRORS for c in (e, "rate_" + e)] +
               ["vs_uniform_" + e for e in ERRORS] + ["wall_seconds"])
    os.makedirs(RESULTS, exist_ok=True)
    suffix = "" if args.name == "adaptive" else "-" + args.name
    table[columns].to_csv(
        os.path.join(RESULTS, "adaptive_mms%s.csv" % suffix), index=False,
        float_format="%.6g")
    fits = pd.DataFrame(fits)
    fits.to_csv(os.path.join(RESULTS, "adaptive_mms_rates%s.csv" % suffix),
                index=False, float_format="%.4f")

    pd.set_option("display.width", 200)
    print("errors and rates against the mean dofs (rate: -log(E ratio) / "
          "log(dofs ratio) between levels; O(h) = 0.5)")
    print(table[columns].to_string(index=False, float_format="%.4g"))
    print("\nfitted log-log slopes against the mean dofs (all levels; last 3)")
    print(fits.to_string(index=False, float_format="%.3f"))
    adaptive, uniform_fit = fits.iloc[1], fits.iloc[0]
    for e in ERRORS:
        d = adaptive["slope_" + e] - uniform_fit["slope_" + e]
        verdict = ("at least the uniform rate" if d >= 0 else
                   "below the uniform rate by less than 0.005" if d > -0.005
                   else "below the uniform rate")
        print("%s: adaptive slope %.4f, uniform %.4f (difference %+.4f): %s"
              % (e, adaptive["slope_" + e], uniform_fit["slope_" + e], d,
                 verdict))

if __name__ == "__main__":
    main()
