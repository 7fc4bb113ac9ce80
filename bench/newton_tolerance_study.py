#!/usr/bin/python3
"""What the Newton tolerance costs and buys on the default examples.

Runs prm/block_2d.prm at 4, 5, 6 and prm/block_3d.prm at 2, 3, 4 global
refinements (k = 0.01, 100 steps, one rank) with 'nonlinear solver/
tolerance' = 1e-9, 1e-8 (the default) and looser values. It prints per run the Newton iterations
per step (mean / max), the Krylov iterations per step, the wall time per
step, how far the probe velocities moved against the 1e-9 run (max over
steps and probes of |w - w_1e-9|, relative to max |w_1e-9|) and the largest
relative energy defect of steps.csv. For scale, the same difference between
the 1e-9 runs of two successive levels (the discretisation's own change) is
printed too. Iteration counts are deterministic; wall times are one run each.

  /usr/bin/python3 bench/newton_tolerance_study.py     # ~8 min; writes bench/results/newton_tolerance.csv
  /usr/bin/python3 bench/newton_tolerance_study.py --reuse   # re-read the runs in bench/work

Needs a Release build in build/ (see bench/run_benchmarks.py).
"""
import argparse
import csv
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import run_benchmarks as rb  # noqa: E402  (the case/prm/run helpers)

TOLERANCES = ["1e-9", "1e-8", "1e-7", "1e-6"]
LEVELS = {2: [4, 5, 6], 3: [2, 3, 4]}


def probe_velocities(directory):
    """{(step, point): [w components]} from a run's probes.csv."""
    result = {}
    with open(os.path.join(directory, "probes.csv")) as f:
        for row in csv.DictReader(f):
            w = [float(v) for k, v in row.items() if k.startswith("w_")]
            result[(int(row["step"]), int(row["point"]))] = w
    return result


def relative_difference(a, b):
    """max |a - b| over the common (step, point) keys, over max |b|."""
    keys = sorted(set(a) & set(b))
    diff = max(max(abs(x - y) for x, y in zip(a[k], b[k])) for k in keys)
    scale = max(max(abs(y) for y in b[k]) for k in keys)
    return diff / scale


def max_relative_energy_defect(directory):
    """max over the steps of |relative_energy_defect| in steps.csv."""
    with open(os.path.join(directory, "steps.csv")) as f:
        return max(abs(float(row["relative_energy_defect"]))
                   for row in csv.DictReader(f))


def run_case(dim, level, tolerance, work, reuse):
    name = f"{dim}d-r{level}-tol{tolerance}"
    c = rb.case(name, f"block_{dim}d.prm", level,
                nonlinear={"tolerance": tolerance}, keep_probes=True)
    row = rb.run(c, work, reuse)
    directory = os.path.join(work, name)
    return dict(case=f"{dim}D r{level}", tolerance=tolerance,
                dofs=int(row["n_dofs"]),
                newton_mean=row["newton_mean"],
                newton_max=int(row["newton_max"]),
                krylov_per_step=row["linear_per_solve"] * row["newton_mean"],
                wall_per_step=row["wall_per_step"],
                energy_defect=max_relative_energy_defect(directory),
                probes=probe_velocities(directory))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--work", default=os.path.join(
        rb.ROOT, "bench", "work", "newton_tolerance"))
    parser.add_argument("--output", default=os.path.join(
        rb.ROOT, "bench", "results", "newton_tolerance.csv"))
    parser.add_argument("--reuse", action="store_true",
                        help="re-read the runs already in --work")
    args = parser.parse_args()
    if not os.access(rb.EXE, os.X_OK):
        sys.exit("bench: build/hemicontact not found; build it first")

    rows = []
    for dim, levels in LEVELS.items():
        previous_default = None
        for level in levels:
            default = None
            for tolerance in TOLERANCES:
                row = run_case(dim, level, tolerance, args.work, args.reuse)
                if default is None:
                    default = row
                row["w_change"] = relative_difference(row["probes"],
                                                      default["probes"])
                row["level_change"] = (
                    relative_difference(default["probes"],
                                        previous_default["probes"])
                    if previous_default else float("nan"))
                rows.append(row)
            previous_default = default

    columns = ["case", "dofs", "tolerance", "newton_mean", "newton_max",
               "krylov_per_step", "wall_per_step", "w_change", "level_change",
               "energy_defect"]
    print("| " + " | ".join(columns) + " |")
    print("|" + "---|" * len(columns))
    for r in rows:
        print("| %s | %d | %s | %.2f | %d | %.1f | %.4f | %.1e | %.1e | %.1e |" % tuple(
            r[c] for c in columns))
    os.makedirs(os.path.dirname(args.output), exist_ok=True)
    with open(args.output, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=columns, extrasaction="ignore")
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    main()
