#!/usr/bin/python3
"""Performance benchmark of hemicontact (not part of CI's pass/fail).

Runs fixed cases -- the default 2D example and its 3D version at three
successive refinements, once at the examples' time step and once with the
time step halved with h, the non-default solver choices on the middle
levels, the static and quasistatic classes on the finest levels, and a large
3D case (811,923 dofs) on 1 and 2 MPI ranks and the largest block the
machine holds (2,193,075 dofs, 1 rank) -- with 'performance summary =
true', reads each run's performance.csv and prints one table plus the growth
exponents of the time per step against the number of dofs. Every figure is
also written to bench/results/benchmark.csv (or --output).

  /usr/bin/python3 bench/run_benchmarks.py            # everything (~50 min)
  /usr/bin/python3 bench/run_benchmarks.py --large-steps 5   # shorter large case
  /usr/bin/python3 bench/run_benchmarks.py --quick    # small levels only
  /usr/bin/python3 bench/run_benchmarks.py --only '^3d-r[234]' --repeat 3
                                    # chosen cases, fastest of 3 runs each
  /usr/bin/python3 bench/run_benchmarks.py --levels-3d 3,4,5 --only '^3d-r[345]$'
                                    # the 3D levels one finer (r5: 421k dofs)
  /usr/bin/python3 bench/run_benchmarks.py --quick --skip-large --baseline /tmp/old/build/hemicontact --repeat 3
                                    # against another build, ratios in one run

Needs a Release build in build/ (cmake -S . -B build -DCMAKE_BUILD_TYPE=Release).
"""
import argparse
import csv
import math
import os
import re
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "hemicontact")


def case(name, base, refinements, end_time=1.0, ranks=1, subdivisions=None,
         solver=None, time_step=None, group=None, nonlinear=None,
         keep_probes=False, output=None, extra=""):
    return dict(name=name, base=base, refinements=refinements,
                end_time=end_time, ranks=ranks, subdivisions=subdivisions,
                solver=solver or {}, time_step=time_step, group=group,
                nonlinear=nonlinear or {}, keep_probes=keep_probes,
                output=output or {"output interval": "0"}, extra=extra)


def cases(quick, skip_large, large_steps, levels_2d=None, levels_3d=None):
    result = []
    levels_2d = levels_2d or ([3, 4, 5] if quick else [4, 5, 6])
    levels_3d = levels_3d or ([1, 2, 3] if quick else [2, 3, 4])
    # h refined at the examples' k = 0.01 ...
    for r in levels_2d:
        result.append(case(f"2d-r{r}", "block_2d.prm", r, group="2D, fixed k"))
    for r in levels_3d:
        result.append(case(f"3d-r{r}", "block_3d.prm", r, group="3D, fixed k"))
    # ... and h and k refined together (k = 0.01 on the first level, halved
    # with h, as the O(k + h) scheme is refined): a stick-slip front then
    # crosses the same number of nodes per step on every level
    for dim, levels in ((2, levels_2d), (3, levels_3d)):
        for r in levels[1:]:
            result.append(case(f"{dim}d-r{r}-k{r - levels[0]}", f"block_{dim}d.prm",
                               r, time_step=0.01 / 2 ** (r - levels[0]),
                               group=f"{dim}D, k ~ h"))
        # the first level (k = 0.01) is the fixed-k run's, not run again
        first = next(c for c in result if c["name"] == f"{dim}d-r{levels[0]}")
        result.append(dict(first, group=f"{dim}D, k ~ h", shared=True))
    # inexact Newton against fixed Krylov tolerances, and Newton from
    # w_{n-1} instead of the extrapolated guess, on the middle levels
    middle = levels_3d[1]
    result.append(case(f"3d-r{middle}-fixed-forcing", "block_3d.prm", middle,
                       solver={"forcing term": "fixed"}))
    for name, base, r in (("2d", "block_2d.prm", levels_2d[1]),
                          ("3d", "block_3d.prm", middle)):
        result.append(case(f"{name}-r{r}-previous-guess", base, r,
                           nonlinear={"initial guess": "previous"}))
    # the cost of writing the solution: every step written, on the finest
    # levels, in both formats
    for name, base, r in (("2d", "block_2d.prm", levels_2d[-1]),
                          ("3d", "block_3d.prm", levels_3d[-1])):
        for format in ("vtu", "hdf5"):
            result.append(case(f"{name}-r{r}-write-{format}", base, r,
                               end_time=0.2,
                               output={"output interval": "1",
                                       "format": format}))
        # every fifth step written (a VTU write then overlaps whole steps)
        result.append(case(f"{name}-r{r}-write-vtu-every-5", base, r,
                           end_time=0.2, output={"output interval": "5"}))
        # the same steps without output: a write costs the difference
        result.append(case(f"{name}-r{r}-write-none", base, r, end_time=0.2))
    # a manufactured-solution step against a physical step on a mesh of the
    # same cells (unit square refined r + 1 times, unit cube of 2 x 2 x 1
    # cells refined r times), at the examples' k = 0.01
    for name, base, r, geometry in (
            ("2d", "verification/mms_2d_quad_exponential.prm", levels_2d[1],
             "  set subdivisions = 1, 1\n  set global refinements = %d\n"
             % (levels_2d[1] + 1)),
            ("3d", "verification/mms_3d_hex_exponential.prm", levels_3d[1],
             "  set subdivisions = 2, 2, 1\n  set global refinements = %d\n"
             % levels_3d[1])):
        result.append(case(f"{name}-r{r}-mms", base, r, end_time=1.0,
                           time_step=0.01,
                           extra="subsection geometry\n" + geometry + "end\n"
                           "subsection convergence study\n"
                           "  set type = single\nend\n"))
    # the other problem classes on the finest levels, 20 steps: a static
    # load step and a quasistatic step, each against one solve of its own
    # step matrix (B, A) in the same run (the 'ratio' column)
    for problem_class in ("static", "quasistatic"):
        for name, base, r in (("2d", "block_2d.prm", levels_2d[-1]),
                              ("3d", "block_3d.prm", levels_3d[-1])):
            result.append(case(f"{name}-r{r}-{problem_class}", base, r,
                               end_time=0.2,
                               extra="subsection problem\n  set class = %s\n"
                               "end\n" % problem_class))
    if not skip_large and not quick:
        # tetrahedra against hexahedra on the same vertices (421,443 dofs),
        # the first steps, on 1 and 2 ranks
        for cells, extra in (("hex", ""), ("tet", "subsection geometry\n"
                                           "  set cell type = simplex\nend\n")):
            for ranks in (1, 2):
                result.append(case(f"3d-{cells}-r5-np{ranks}", "block_3d.prm",
                                   5, end_time=0.01 * max(large_steps // 4, 1),
                                   ranks=ranks, extra=extra))

        # 160 x 40 x 40 hexahedra: 811,923 dofs; the first steps
        for ranks in (1, 2):
            result.append(case(f"3d-large-np{ranks}", "block_3d.prm", 3,
                               end_time=0.01 * large_steps, ranks=ranks,
                               subdivisions="20, 5, 5"))
        # the largest block a 24 GB workstation holds with room to spare:
        # 224 x 56 x 56 hexahedra, 2,193,075 dofs, 3 steps on 1 rank
        result.append(case("3d-largest-np1", "block_3d.prm", 2,
                           end_time=0.03, subdivisions="56, 14, 14"))
    return result


def write_prm(c, directory):
    lines = [open(os.path.join(ROOT, "prm", c["base"])).read()]
    lines.append("subsection geometry\n  set global refinements = %d\n" %
                 c["refinements"])
    if c["subdivisions"]:
        lines.append("  set subdivisions = %s\n" % c["subdivisions"])
    lines.append("end\nsubsection time\n  set end time = %g\n" %
                 c["end_time"])
    if c["time_step"]:
        lines.append("  set time step = %g\n" % c["time_step"])
    lines.append("end\n")
    lines.append("subsection nonlinear solver\n")
    for key, value in c["nonlinear"].items():
        lines.append("  set %s = %s\n" % (key, value))
    lines.append("end\nsubsection linear solver\n")
    for key, value in c["solver"].items():
        lines.append("  set %s = %s\n" % (key, value))
    lines.append("end\nsubsection output\n  set directory = %s\n" % directory)
    for key, value in c["output"].items():
        lines.append("  set %s = %s\n" % (key, value))
    if not c["keep_probes"]:
        lines.append("  set probe points =\n")
    lines.append("  set terminal = quiet\n  set timing summary = false\n"
                 "  set performance summary = true\nend\n")
    lines.append(c["extra"])
    path = os.path.join(directory, "run.prm")
    with open(path, "w") as f:
        f.write("".join(lines))
    return path


def run(c, work, reuse=False, executable=EXE, suffix=""):
    directory = os.path.join(work, c["name"] + suffix)
    result = os.path.join(directory, "performance.csv")
    if reuse and os.path.exists(result) and os.path.getsize(result) > 0:
        print(f"reusing {c['name']}", file=sys.stderr, flush=True)
        return read_performance(result, c["name"] + suffix)
    os.makedirs(directory, exist_ok=True)
    prm = write_prm(c, directory)
    command = [executable, prm]
    if c["ranks"] > 1:
        command = ["mpirun", "-np", str(c["ranks"])] + command
    env = dict(os.environ, OMPI_ALLOW_RUN_AS_ROOT="1",
               OMPI_ALLOW_RUN_AS_ROOT_CONFIRM="1")
    print(f"running {c['name']}{suffix} ...", file=sys.stderr, flush=True)
    subprocess.run(command, check=True, env=env, stdout=subprocess.DEVNULL)
    return read_performance(result, c["name"] + suffix)


def read_performance(path, name):
    study = os.path.join(os.path.dirname(path), "convergence.csv")
    if not os.path.exists(path) and os.path.exists(study):
        # a manufactured-solution run: its level's time loop (the steps and
        # the error evaluation of every step, as a physical run's steps
        # without the set-up) per step
        with open(study) as f:
            level = next(csv.DictReader(f))
        return {"case": name, "n_dofs": float(level["n_dofs"]),
                "steps": float(level["n_steps"]), "mpi_ranks": 1,
                "newton_mean": float(level["mean_newton_iterations"]),
                "newton_max": float(level["max_newton_iterations"]),
                "wall_per_step": float(level.get("step_wall_seconds") or
                                       level["wall_seconds"]) /
                float(level["n_steps"]),
                "peak_memory_bytes": 0, "time_output": 0}
    with open(path) as f:
        values = {row["quantity"]: float(row["value"])
                  for row in csv.DictReader(f)}
    values["case"] = name
    return values


def growth_exponent(rows):
    """Least-squares slope of log(wall per step) against log(dofs)."""
    x = [math.log(r["n_dofs"]) for r in rows]
    y = [math.log(r["wall_per_step"]) for r in rows]
    mx, my = sum(x) / len(x), sum(y) / len(y)
    return (sum((a - mx) * (b - my) for a, b in zip(x, y)) /
            sum((a - mx) ** 2 for a in x))


COLUMNS = [
    ("case", "case", "%-34s"),
    ("n_dofs", "dofs", "%9d"),
    ("mpi_ranks", "np", "%2d"),
    ("steps", "steps", "%5d"),
    ("newton_mean", "Nwt", "%5.2f"),
    ("newton_max", "max", "%3d"),
    ("linear_per_solve", "lin/slv", "%7.1f"),
    ("wall_per_step", "s/step", "%8.4f"),
    ("reference_solve_wall", "1 solve", "%8.4f"),
    ("reference_cg_wall", "(CG)", "%8.4f"),
    ("ratio_step_to_reference", "ratio", "%6.2f"),
    ("time_assembly_load", "load", "%7.2f"),
    ("time_active_set_update", "act.set", "%7.2f"),
    ("time_preconditioner_setup", "AMG", "%7.2f"),
    ("time_linear_solve_without_setup", "Krylov", "%7.2f"),
    ("time_energy", "energy", "%7.2f"),
    ("time_output", "output", "%6.2f"),
    ("write_to_step", "wr/stp", "%6.2f"),
    ("write_added_to_step", "wr+/stp", "%7.2f"),
    ("peak_memory_bytes", "MiB", "%7.0f"),
    ("bytes_per_dof", "B/dof", "%7.0f"),
]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--quick", action="store_true",
                        help="small levels only (a few seconds per case)")
    parser.add_argument("--skip-large", action="store_true",
                        help="leave out the ~0.8M-dof 3D case")
    parser.add_argument("--large-steps", type=int, default=20,
                        help="time steps of the large case (default 20)")
    parser.add_argument("--levels-2d", default=None,
                        help="the three 2D refinements, e.g. 4,5,6 (default; "
                        "3,4,5 with --quick)")
    parser.add_argument("--levels-3d", default=None,
                        help="the three 3D refinements, e.g. 2,3,4 (default; "
                        "1,2,3 with --quick); 3,4,5 takes ~15 min more")
    parser.add_argument("--baseline", default=None,
                        help="another hemicontact executable (e.g. a build "
                        "of an older commit): every case also runs with it, "
                        "round-robin with build/hemicontact, and the table "
                        "adds its rows ('@baseline') and the ratios of "
                        "s/step and iterations")
    parser.add_argument("--reuse", action="store_true",
                        help="reuse the results of cases already in --work")
    parser.add_argument("--repeat", type=int, default=1,
                        help="run every case this many times, round-robin, "
                        "and keep the fastest run of each (wall times on a "
                        "shared machine vary by tens of percent; the "
                        "iteration counts do not)")
    parser.add_argument("--only", default=None,
                        help="run only the cases whose name matches this "
                        "regular expression")
    parser.add_argument("--work", default=os.path.join(ROOT, "bench", "work"),
                        help="where the runs write (default bench/work)")
    parser.add_argument("--output", default=os.path.join(
        ROOT, "bench", "results", "benchmark.csv"))
    args = parser.parse_args()
    if not os.access(EXE, os.X_OK):
        sys.exit("bench: build/hemicontact not found; build it first "
                 "(cmake -S . -B build -DCMAKE_BUILD_TYPE=Release && "
                 "cmake --build build -j2)")

    def levels(text):
        return [int(x) for x in text.split(",")] if text else None
    all_cases = cases(args.quick, args.skip_large, args.large_steps,
                      levels(args.levels_2d), levels(args.levels_3d))
    if args.only:
        all_cases = [c for c in all_cases if re.search(args.only, c["name"])]
    to_run = [c for c in all_cases if not c.get("shared")]
    builds = [(EXE, "")]
    if args.baseline:
        builds.append((os.path.abspath(args.baseline), "@baseline"))
    fastest = {}
    for round in range(max(args.repeat, 1)):
        for c in to_run:
            for executable, suffix in builds:
                row = run(c, args.work, args.reuse and args.repeat <= 1,
                          executable, suffix)
                best = fastest.get(row["case"])
                if best is None or row["wall_per_step"] < best["wall_per_step"]:
                    fastest[row["case"]] = row
    rows = [fastest[c["name"] + suffix] for c in to_run
            for _, suffix in builds]
    for r in rows:
        r["peak_memory_bytes"] /= 2 ** 20
        # one solution write against one step (0 when nothing was written):
        # the time the run waited for the write ...
        r["write_to_step"] = (r["time_output"] / r["solution_writes"] /
                              r["wall_per_step"]
                              if r.get("solution_writes", 0) > 0 else 0.)
        # ... and, against the same run without output, what the writes
        # added to the whole run (writes overlap the steps on a free core)
        twin = re.sub(r"-write-(vtu|hdf5)(-every-5)?", "-write-none",
                      r["case"])
        if twin != r["case"] and r.get("solution_writes", 0) > 0:
            base = next((t for t in rows if t["case"] == twin), None)
            if base is not None and "run_wall" in r and "run_wall" in base:
                r["write_added_to_step"] = (
                    (r["run_wall"] - base["run_wall"]) /
                    r["solution_writes"] / base["wall_per_step"])
    by_name = {r["case"]: r for r in rows}
    groups = {}
    for c in all_cases:
        if c["group"] and c["name"] in by_name:
            groups.setdefault(c["group"], []).append(by_name[c["name"]])

    print("\nTime split columns are seconds summed over the run; 'ratio' is "
          "s/step over one solve\nof the step matrix (AMG set-up + CG) "
          "measured in the same run.\n")
    print(" ".join((fmt.replace("d", "s").replace(".2f", "s")
                    .replace(".4f", "s").replace(".1f", "s")
                    .replace(".0f", "s")) % title
                   for _, title, fmt in COLUMNS))
    for r in rows:
        print(" ".join(fmt % r.get(key, 0) for key, _, fmt in COLUMNS))

    summary = []
    for group, levels in groups.items():
        if len(levels) >= 2:
            levels = sorted(levels, key=lambda r: r["n_dofs"])
            p = growth_exponent(levels)
            summary.append((f"growth exponent p of s/step ~ dofs^p ({group})", p))
            means = [r["newton_mean"] for r in levels]
            summary.append((f"Newton mean per level ({group})",
                            " / ".join("%.2f" % m for m in means)))
            summary.append((f"Newton mean spread max-min ({group})",
                            max(means) - min(means)))
    if args.baseline:
        for c in to_run:
            new, old = by_name[c["name"]], fastest[c["name"] + "@baseline"]
            summary.append((f"{c['name']}: s/step, Newton, Krylov per solve "
                            "against the baseline",
                            "%.3f / %.3f / %.3f" % (
                                new["wall_per_step"] / old["wall_per_step"],
                                new["newton_mean"] / old["newton_mean"],
                                new.get("linear_per_solve", 0) /
                                max(old.get("linear_per_solve", 0), 1e-300))))
    for r in rows:
        match = re.fullmatch(r"(\dd-r\d+)-mms", r["case"])
        if match and match.group(1) in by_name:
            physical = by_name[match.group(1)]
            summary.append((f"{r['case']}: s/step against {match.group(1)} "
                            f"({r['n_dofs']:.0f} and {physical['n_dofs']:.0f} "
                            "dofs)",
                            r["wall_per_step"] / physical["wall_per_step"]))
    large = {r["mpi_ranks"]: r for r in rows
             if re.fullmatch(r"3d-large-np\d", r["case"])}
    if 1 in large and 2 in large:
        summary.append(("speed-up 2 ranks vs 1 (large case, s/step)",
                        large[1]["wall_per_step"] / large[2]["wall_per_step"]))
    print()
    def text(value, digits):
        return value if isinstance(value, str) else f"{value:.{digits}f}"
    for name, value in summary:
        print(f"{name}: {text(value, 3)}")

    os.makedirs(os.path.dirname(args.output), exist_ok=True)
    with open(args.output, "w", newline="") as f:
        keys = ["case"] + sorted({k for r in rows for k in r} - {"case"})
        writer = csv.DictWriter(f, fieldnames=keys, restval="")
        writer.writeheader()
        writer.writerows(rows)
        for name, value in summary:
            f.write(f"# {name}: {text(value, 4)}\n")
    print(f"\nwritten to {args.output}")


if __name__ == "__main__":
    main()
