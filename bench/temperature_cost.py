#!/usr/bin/python3
"""What the temperature costs a step: Example E (prm/example_e_temperature.prm)
with and without 'temperature/enabled' on the same meshes, each run REPEAT
times (the fastest kept), the timer sections of one step.

    /usr/bin/python3 bench/temperature_cost.py [EXE] [--levels 3 4 5] [--repeat 3]

Writes bench/results/temperature_cost.csv: per level and variant the cells,
the run's wall time and, per step, the heat step, the mechanical step's
linear solves and its load assembly (which holds the thermal stress load),
and the ratio of the heat step to the linear solves (below 1: the heat
step is the cheaper).
"""
import argparse
import csv
import pathlib
import re
import subprocess
import tempfile

root = pathlib.Path(__file__).resolve().parent.parent
parser = argparse.ArgumentParser()
parser.add_argument("exe", nargs="?", default=str(root / "build" / "hemicontact"))
parser.add_argument("--levels", type=int, nargs="+", default=[3, 4, 5])
parser.add_argument("--repeat", type=int, default=3)
args = parser.parse_args()

shipped = (root / "prm" / "example_e_temperature.prm").read_text()


def sections(text):
    """The timer table's sections: name -> (calls, wall seconds)."""
    table = {}
    for line in text.splitlines():
        m = re.match(r"\|\s*([a-z][a-z :]+?)\s*\|\s*(\d+)\s*\|\s*([0-9.e+-]+)s", line)
        if m:
            table[m.group(1)] = (int(m.group(2)), float(m.group(3)))
        m = re.match(r"\|\s*Total wallclock time elapsed\s*\|\s*([0-9.e+-]+)s", line)
        if m:
            table["total"] = (1, float(m.group(1)))
    return table


rows = []
with tempfile.TemporaryDirectory() as work:
    for level in args.levels:
        for enabled in (True, False):
            text = shipped + (
                f"\nsubsection geometry\n  set global refinements = {level}\nend\n"
                "subsection output\n  set directory = out\n  set vtu interval = 0\nend\n"
                f"subsection temperature\n  set enabled = {'true' if enabled else 'false'}\nend\n")
            prm = pathlib.Path(work) / "run.prm"
            prm.write_text(text)
            best = None
            for _ in range(args.repeat):
                out = subprocess.run([args.exe, str(prm)], cwd=work, capture_output=True,
                                     text=True, check=True).stdout
                table = sections(out)
                if best is None or table["total"][1] < best["total"][1]:
                    best = table
                cells = int(re.search(r"(\d+) cells", out).group(1))
            steps = best["assembly: load"][0]
            heat = best.get("heat step", (0, 0.0))[1] / steps
            solve = best["linear solve"][1] / steps
            rows.append({"level": level, "cells": cells, "temperature": enabled,
                         "run_seconds": best["total"][1],
                         "heat_step_per_step": heat,
                         "linear_solve_per_step": solve,
                         "load_assembly_per_step": best["assembly: load"][1] / steps,
                         "heat_over_linear_solve": heat / solve if enabled else ""})
            print(", ".join(f"{k} {v:.4g}" if isinstance(v, float) else f"{k} {v}"
                            for k, v in rows[-1].items()), flush=True)

out = root / "bench" / "results" / "temperature_cost.csv"
with open(out, "w", newline="") as f:
    writer = csv.DictWriter(f, fieldnames=list(rows[0]))
    writer.writeheader()
    writer.writerows(rows)
print("wrote", out)
