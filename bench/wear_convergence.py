#!/usr/bin/python3
"""Convergence of the wear depth of prm/wear_block_2d.prm (doc/theory.md,
section 11.12) in h and k together, at first order expected.

Level l runs the example with 'global refinements' = R0 + l and 'time
step' = K0 / 2^l (h and k halved together); the reference is the level two
finer than the finest. The error of level l is the wear depth at the end
time t = 1 against the reference's at the contact nodes of level l (the
meshes are nested, so the reference has every one of them):
E_max = max_i |omega_i - omega_ref,i| and E_2 = (sum_i m_i (omega_i -
omega_ref,i)^2)^(1/2), m_i the nodal weights of the coarse level's CSV;
the orders are log2 of the ratios of successive errors.

  /usr/bin/python3 bench/wear_convergence.py                # levels 0..3, reference 5
  /usr/bin/python3 bench/wear_convergence.py --levels 3     # levels 0..2, reference 4

Writes bench/results/wear_convergence.csv. Needs a Release build in build/.
"""
import argparse
import glob
import math
import os
import subprocess
import tempfile

import numpy as np
import pandas as pd

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "hemicontact")
PRM = os.path.join(ROOT, "prm", "wear_block_2d.prm")
R0, K0 = 1, 0.1


def run(level, work):
    """The last contact CSV of level @p level, as a table."""
    directory = os.path.join(work, f"level-{level}")
    k = K0 / 2 ** level
    steps = round(1 / k)
    with open(PRM) as f:
        text = f.read()
    text += (f"subsection geometry\n  set global refinements = {R0 + level}\nend\n"
             f"subsection time\n  set time step = {k!r}\nend\n"
             f"subsection output\n  set directory = {directory}\n"
             f"  set output interval = {steps}\n"
             "  set probe points =\n  set terminal = quiet\nend\n")
    prm = directory + ".prm"
    with open(prm, "w") as f:
        f.write(text)
    subprocess.run([EXE, prm], cwd=work, check=True, stdout=subprocess.DEVNULL)
    last = sorted(glob.glob(os.path.join(directory, "contact_*.csv")))[-1]
    table = pd.read_csv(last)
    assert abs(table["time"].iloc[0] - 1) < 1e-12, last
    return table


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--levels", type=int, default=4)
    args = parser.parse_args()
    with tempfile.TemporaryDirectory() as work:
        reference = run(args.levels + 1, work)
        ref = dict(zip(np.round(reference["x"].values, 9), reference["wear"].values))
        rows = []
        for level in range(args.levels):
            table = run(level, work)
            omega = table["wear"].values
            exact = np.array([ref[x] for x in np.round(table["x"].values, 9)])
            e = omega - exact
            rows.append({"level": level, "h": 0.5 / 2 ** level if R0 == 1 else None,
                         "k": K0 / 2 ** level,
                         "E_max": np.abs(e).max(),
                         "E_2": math.sqrt((table["mass"].values * e ** 2).sum()),
                         "largest_wear": omega.max()})
    results = pd.DataFrame(rows)
    for name in ("E_max", "E_2"):
        results[f"order_{name}"] = np.concatenate(
            [[np.nan], np.log2(results[name].values[:-1] / results[name].values[1:])])
    os.makedirs(os.path.join(ROOT, "bench", "results"), exist_ok=True)
    results.to_csv(os.path.join(ROOT, "bench", "results", "wear_convergence.csv"), index=False)
    print(f"reference: level {args.levels + 1} (h = {0.5 / 2 ** (args.levels + 1)}, "
          f"k = {K0 / 2 ** (args.levels + 1)}), largest wear {reference['wear'].max():.6g}")
    print("| level | h | k | E_max | order | E_2 | order |")
    print("|---|---|---|---|---|---|---|")
    for r in results.itertuples():
        o1 = "" if math.isnan(r.order_E_max) else f"{r.order_E_max:.2f}"
        o2 = "" if math.isnan(r.order_E_2) else f"{r.order_E_2:.2f}"
        print(f"| {r.level} | {r.h:g} | {r.k:g} | {r.E_max:.3e} | {o1} | {r.E_2:.3e} | {o2} |")


if __name__ == "__main__":
    main()
