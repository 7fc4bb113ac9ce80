#!/usr/bin/python3
"""Uniform against adapted meshes on a problem of reduced regularity.

prm/l_shape_signorini.prm (static class): an L-shaped body on a Signorini
foundation with Tresca friction, whose re-entrant corner and contact zone
make u less regular than H^2. Runs
  - uniform meshes, global refinements 1 .. 7 (one load value each);
  - adapted meshes: the shipped file (indicator 'estimator') and the same
    with 'kelly', 13 cycles each (each load value is the same problem,
    solved on the mesh adapted after the one before; fixed number 0.2,
    no coarsening, so the meshes are nested);
  - the reference: the estimator's meshes continued to 19 cycles (about 16
    times the dofs of the 13th).
The problem is convex and each solve minimises the step energy J, so for
the discrete solution u_N, J(u_N) - J(u) >= 1/2 |||u - u_N|||^2 (the
energy norm of B); the error is measured as E_J = (2 (J(u_N) - J_ref))^(1/2)
with J_ref the reference's J (`minimised_energy` of steps.csv), and the
effectivity index as eta / E_J. The slopes are least-squares fits of
log E_J against log N over the last four points of each family.

  /usr/bin/python3 bench/reduced_regularity_study.py    # ~3 min; writes bench/results/reduced_regularity.csv
"""
import csv
import math
import os
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "hemicontact")
PRM = os.path.join(ROOT, "prm", "l_shape_signorini.prm")


def run(work, name, overrides):
    """The rows (n_dofs, J, eta) of steps.csv of one run."""
    directory = os.path.join(work, name)
    with open(PRM) as f:
        text = f.read()
    text += overrides + (f"subsection output\n  set directory = {directory}\n"
                         "  set output interval = 0\nend\n")
    prm = directory + ".prm"
    with open(prm, "w") as f:
        f.write(text)
    subprocess.run([EXE, prm], cwd=ROOT, check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(directory, "steps.csv")) as f:
        return [(int(r["n_dofs"]), float(r["minimised_energy"]), float(r["error_estimate"]))
                for r in csv.DictReader(f)]


def slope(points):
    """Least-squares slope of log E against log N."""
    xs = [math.log(n) for n, _ in points]
    ys = [math.log(e) for _, e in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def main():
    families = {}
    with tempfile.TemporaryDirectory() as work:
        families["uniform"] = [
            run(work, f"uniform-{r}", f"subsection geometry\n  set global refinements = {r}\nend\n"
                "subsection time\n  set end time = 1\nend\n"
                "subsection adaptivity\n  set interval = 0\nend\n")[0]
            for r in range(1, 8)]
        families["kelly"] = run(work, "kelly", "subsection time\n  set end time = 13\nend\n"
                                "subsection adaptivity\n  set indicator = kelly\nend\n")
        families["estimator"] = run(work, "estimator", "subsection time\n  set end time = 13\nend\n")
        reference = run(work, "reference", "subsection time\n  set end time = 19\nend\n")
    n_ref, j_ref, _ = reference[-1]
    rows = []
    for family, points in families.items():
        errors = []
        for n, j, eta in points:
            e = math.sqrt(2 * max(j - j_ref, 0.0))
            errors.append((n, e))
            rows.append({"family": family, "dofs": n, "J": f"{j:.12e}", "E_J": f"{e:.4e}",
                         "estimate": f"{eta:.4e}", "effectivity": f"{eta / e:.3f}"})
        last = slope(errors[-4:])
        for row in rows:
            if row["family"] == family:
                row["slope_last_four"] = f"{last:.3f}"
        print(f"{family}: dofs {points[0][0]} .. {points[-1][0]}, E_J {errors[0][1]:.3e} .. {errors[-1][1]:.3e}, "
              f"slope of E_J against N over the last four {last:.3f}, effectivity "
              f"{min(p[2] / e for p, (_, e) in zip(points, errors)):.2f} .. "
              f"{max(p[2] / e for p, (_, e) in zip(points, errors)):.2f}")
    print(f"reference: {n_ref} dofs, J_ref = {j_ref:.12e}")
    out = os.path.join(ROOT, "bench", "results", "reduced_regularity.csv")
    with open(out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print("wrote", out)


if __name__ == "__main__":
    main()
