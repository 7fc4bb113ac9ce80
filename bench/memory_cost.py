#!/usr/bin/python3
"""What long memory (doc/theory.md, section 11) costs per step.

Runs prm/block_2d.prm (dynamic class) and prm/static_block_2d.prm (static
class) at 5 global refinements, one rank, with no output files, in three
forms each: without memory ('relaxation/kernel = none'), with a two-term
Prony series, and with the same kernel written as expressions (every past
state kept). The three forms run interleaved REPEATS times; per form the
median over the repeats of the summed per-step wall time (steps.csv
`wall_seconds`) is compared, so that the ratios come from one run of the
script. For the expression form the extra time per step against the run
without memory is fitted as a + b n over the step index n (the sum over the
stored states grows with n, section 11.5). The time spent in the memory
itself (the timer section `memory`: the history update and the memory's
part of the right-hand side) is reported against the time of the rest of
the step: what memory adds to a step, apart from the change of the
solution it causes (Newton iterations differ between the forms, as the
solutions do).

  /usr/bin/python3 bench/memory_cost.py            # ~5 min; writes bench/results/memory_cost.csv
  /usr/bin/python3 bench/memory_cost.py --repeats 1 --refinements 4   # quicker

Needs a Release build in build/.
"""
import argparse
import csv
import os
import statistics
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EXE = os.path.join(ROOT, "build", "hemicontact")
CASES = {"dynamic": "prm/block_2d.prm", "static": "prm/static_block_2d.prm"}
KERNELS = {
    "none": "subsection relaxation\n  set kernel = none\nend\n",
    "prony": ("subsection relaxation\n  set kernel = prony\n"
              "  set mu amplitudes = 1, 0.5\n  set lambda amplitudes = 0.5, 0\n"
              "  set relaxation times = 0.5, 2\nend\n"),
    "expression": ("subsection relaxation\n  set kernel = expression\n"
                   "  set mu = exp(-t/0.5) + 0.5*exp(-t/2)\n"
                   "  set lambda = 0.5*exp(-t/0.5)\nend\n"),
}


def run(case, kernel, refinements, work):
    """(per-step wall seconds, seconds in the timer section 'memory',
    Newton iterations) of one run."""
    directory = os.path.join(work, f"{case}-{kernel}")
    with open(os.path.join(ROOT, CASES[case])) as f:
        text = f.read()
    text += (f"subsection geometry\n  set global refinements = {refinements}\nend\n"
             + KERNELS[kernel]
             + f"subsection output\n  set directory = {directory}\n"
               "  set output interval = 0\nend\n")
    prm = directory + ".prm"
    with open(prm, "w") as f:
        f.write(text)
    printed = subprocess.run([EXE, prm], cwd=ROOT, check=True, stdout=subprocess.PIPE,
                             stderr=subprocess.DEVNULL, text=True).stdout
    memory = 0.0
    for line in printed.splitlines():
        cells = [c.strip() for c in line.split("|")]
        if len(cells) > 3 and cells[1] == "memory":
            memory = float(cells[3].split()[0].rstrip("s"))
    with open(os.path.join(directory, "steps.csv")) as f:
        rows = list(csv.DictReader(f))
    return ([float(row["wall_seconds"]) for row in rows], memory,
            sum(int(row["newton_iterations"]) for row in rows))


def linear_fit(xs, ys):
    """(a, b) of the least-squares line a + b x."""
    mx, my = statistics.fmean(xs), statistics.fmean(ys)
    b = sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)
    return my - b * mx, b


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--refinements", type=int, default=5)
    args = parser.parse_args()
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for case in CASES:
            per_step = {k: [] for k in KERNELS}
            memory = {k: [] for k in KERNELS}
            newton = {}
            for _ in range(args.repeats):
                for kernel in KERNELS:
                    seconds, in_memory, newton[kernel] = run(case, kernel, args.refinements, work)
                    per_step[kernel].append(seconds)
                    memory[kernel].append((in_memory, sum(seconds)))
            total = {k: statistics.median(sum(r) for r in runs) for k, runs in per_step.items()}
            # the memory's own time against the rest of the step, per repeat
            share = {k: statistics.median(m / (t - m) for m, t in memory[k]) for k in KERNELS}
            n_steps = len(per_step["none"][0])
            # the expression form's extra time per step against n
            extra = [statistics.median(r[n] for r in per_step["expression"])
                     - statistics.median(r[n] for r in per_step["none"]) for n in range(n_steps)]
            a, b = linear_fit(range(1, n_steps + 1), extra)
            for kernel in KERNELS:
                rows.append({"case": case, "refinements": args.refinements, "steps": n_steps,
                             "kernel": kernel, "seconds_in_steps": f"{total[kernel]:.4f}",
                             "seconds_per_step": f"{total[kernel] / n_steps:.6f}",
                             "ratio_to_none": f"{total[kernel] / total['none']:.4f}",
                             "newton_iterations": newton[kernel],
                             "memory_section_over_rest": f"{share[kernel]:.4f}",
                             "extra_per_step_fit": (f"{a:.3e} + {b:.3e} n" if kernel == "expression" else "")})
    out = os.path.join(ROOT, "bench", "results", "memory_cost.csv")
    with open(out, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    for row in rows:
        print(", ".join(f"{k} {v}" for k, v in row.items() if v != ""))
    print("wrote", out)


if __name__ == "__main__":
    main()
