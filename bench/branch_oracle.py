#!/usr/bin/python3
"""How many Newton iterations a perfect branch prediction would save.

Builds hemicontact from the committed sources (git HEAD) with
bench/experiments/branch_oracle.patch in a scratch directory, then runs the
default 2D and 3D examples at three refinements (k = 0.01, one rank) three
times each:

  predicted   the defaults; every converged step writes its branches
  replayed    the first Newton iteration of every step uses the converged
              branches of that step (an oracle) instead of the prediction
              of the complementarity function at the extrapolated start
  replayed, exact solves
              the same with 'forcing term = fixed' (every Krylov solve to
              the relative tolerance 1e-10)

and prints the mean and maximum Newton iterations per step and the Krylov
iterations per step. The replayed runs bound from below what any better
prediction of the branches at the start of a step can achieve with the
same Newton tolerance and start.

  /usr/bin/python3 bench/branch_oracle.py            # ~12 min with the build
  /usr/bin/python3 bench/branch_oracle.py --only '^2d'

writes bench/results/branch_oracle.csv
"""
import argparse
import csv
import os
import re
import subprocess
import sys

import run_benchmarks

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
PATCH = os.path.join(ROOT, "bench", "experiments", "branch_oracle.patch")


def build(scratch):
    """The patched executable, built from git HEAD in @p scratch (one build
    per commit, so a later commit never runs an older binary)."""
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "HEAD"],
                            check=True, capture_output=True,
                            text=True).stdout.strip()
    source = os.path.join(scratch, commit, "source-tree")
    binary = os.path.join(scratch, commit, "build", "hemicontact")
    if os.path.exists(binary):
        return binary
    os.makedirs(source, exist_ok=True)
    archive = subprocess.run(["git", "-C", ROOT, "archive", commit],
                             check=True, capture_output=True).stdout
    subprocess.run(["tar", "-x", "-C", source], input=archive, check=True)
    subprocess.run(["patch", "-p1", "-d", source, "-i", PATCH], check=True,
                   stdout=subprocess.DEVNULL)
    subprocess.run(["cmake", "-S", source, "-B", os.path.dirname(binary),
                    "-DCMAKE_BUILD_TYPE=Release"], check=True,
                   stdout=subprocess.DEVNULL)
    subprocess.run(["cmake", "--build", os.path.dirname(binary), "-j2",
                    "--target", "hemicontact"], check=True,
                   stdout=subprocess.DEVNULL)
    return binary


def newton_statistics(directory):
    with open(os.path.join(directory, "steps.csv")) as f:
        rows = list(csv.DictReader(f))
    newton = [int(r["newton_iterations"]) for r in rows]
    krylov = [int(r["linear_iterations"]) for r in rows]
    return {"steps": len(rows), "newton_mean": sum(newton) / len(rows),
            "newton_max": max(newton), "krylov_per_step": sum(krylov) / len(rows)}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--only", default=None,
                        help="regular expression on the case names")
    parser.add_argument("--scratch", default="/tmp/hemicontact-branch-oracle",
                        help="build and work directory")
    args = parser.parse_args()

    binary = build(args.scratch)
    names = [("2d", "block_2d.prm", r) for r in (4, 5, 6)] + \
            [("3d", "block_3d.prm", r) for r in (2, 3, 4)]
    rows = []
    for dim, base, r in names:
        name = "%s-r%d" % (dim, r)
        if args.only and not re.search(args.only, name):
            continue
        branches = os.path.join(args.scratch, name + ".branches")
        if os.path.exists(branches):
            os.remove(branches)
        for variant, env_key, solver in (
                ("predicted", "HEMICONTACT_RECORD_BRANCHES", {}),
                ("replayed", "HEMICONTACT_REPLAY_BRANCHES", {}),
                ("replayed, exact solves", "HEMICONTACT_REPLAY_BRANCHES",
                 {"forcing term": "fixed"})):
            directory = os.path.join(args.scratch, "runs", name,
                                     variant.replace(", ", "-").replace(" ", "-"))
            os.makedirs(directory, exist_ok=True)
            c = run_benchmarks.case(name, base, r, solver=solver)
            prm = run_benchmarks.write_prm(c, directory)
            print("running %s (%s)" % (name, variant), file=sys.stderr,
                  flush=True)
            subprocess.run([binary, prm], check=True,
                           stdout=subprocess.DEVNULL,
                           env=dict(os.environ, **{env_key: branches}))
            row = {"case": name, "variant": variant}
            row.update(newton_statistics(directory))
            rows.append(row)

    print("| case | variant | Newton mean / max | Krylov per step |")
    print("|---|---|---|---|")
    for row in rows:
        print("| %s | %s | %.2f / %d | %.1f |" % (
            row["case"], row["variant"], row["newton_mean"],
            row["newton_max"], row["krylov_per_step"]))
    out = os.path.join(ROOT, "bench", "results", "branch_oracle.csv")
    with open(out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print("written to", out)


if __name__ == "__main__":
    main()
