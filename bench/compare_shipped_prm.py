#!/usr/bin/python3
"""Run every shipped parameter file of prm/ with two hemicontact binaries
and compare their double-precision nodal output (the nodal_NNNNN.h5 files
of `output/precision = double`), or, for a manufactured-solution study,
their convergence.csv.

    /usr/bin/python3 bench/compare_shipped_prm.py BEFORE AFTER WORKDIR [--steps N]

Each file runs as shipped (its mesh file taken relative to the repository
root) with `output/precision = double` and its output in WORKDIR/NAME/
{before,after}; `--steps N` ends each run after N time steps (N k).
Prints one line per file: the largest difference of a nodal value
relative to the largest value of its dataset, over every dataset and
output step, and the number of files compared. Exit status 1 if a run
fails or the two differ in the files they wrote. Needs h5py (Debian's
python3-h5py).
"""

import argparse
import csv
import os
import re
import subprocess
import sys

import h5py
import numpy

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))


def prepared(text, steps):
    """The shipped text with the settings of the comparison appended."""
    match = re.search(r"set mesh file *= *([^\n]+)", text)
    if match and not os.path.isabs(match.group(1).strip()):
        text = text.replace(match.group(0), "set mesh file = " +
                            os.path.join(ROOT, match.group(1).strip()))
    text = re.sub(r"set directory *= *[^\n]+", "set directory = out", text)
    text += "\nsubsection output\n  set precision = double\nend\n"
    k = re.search(r"set time step *= *([0-9.eE+-]+)", text)
    if steps and k:
        text += "subsection time\n  set end time = %r\nend\n" % (
            steps * float(k.group(1)))
    return text


def run(exe, prm_text, directory):
    os.makedirs(directory, exist_ok=True)
    with open(os.path.join(directory, "run.prm"), "w") as f:
        f.write(prm_text)
    result = subprocess.run([exe, "run.prm"], cwd=directory,
                            capture_output=True, text=True, timeout=3600)
    return result.returncode, result.stderr


def nodal_difference(a, b):
    """Largest relative difference over the nodal files of a and b."""
    files = sorted(f for f in os.listdir(a) if re.match(r"nodal_\d+\.h5$", f))
    if files != sorted(f for f in os.listdir(b)
                       if re.match(r"nodal_\d+\.h5$", f)):
        return None, 0
    worst = 0.0
    for name in files:
        with h5py.File(os.path.join(a, name), "r") as fa, \
                h5py.File(os.path.join(b, name), "r") as fb:
            if sorted(fa.keys()) != sorted(fb.keys()):
                return None, len(files)
            for key in fa.keys():
                x = numpy.asarray(fa[key], dtype=float)
                y = numpy.asarray(fb[key], dtype=float)
                if x.shape != y.shape:
                    return None, len(files)
                scale = max(numpy.abs(x).max(initial=0.0), 1e-300)
                worst = max(worst, numpy.abs(x - y).max(initial=0.0) / scale)
    return worst, len(files)


def csv_difference(a, b):
    """Largest relative difference of the numbers of two CSV files,
    except the columns of wall time."""
    with open(a) as fa, open(b) as fb:
        ra, rb = list(csv.DictReader(fa)), list(csv.DictReader(fb))
    if len(ra) != len(rb):
        return None
    worst = 0.0
    for x, y in zip(ra, rb):
        for key in x:
            if "seconds" in key or "wall" in key:
                continue
            try:
                u, v = float(x[key]), float(y[key])
            except (TypeError, ValueError):
                if x[key] != y.get(key):
                    return None
                continue
            worst = max(worst, abs(u - v) / max(abs(u), 1e-300))
    return worst


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("before")
    parser.add_argument("after")
    parser.add_argument("workdir")
    parser.add_argument("--steps", type=int, default=0)
    args = parser.parse_args()
    failed = False
    for dirpath, _, names in sorted(os.walk(os.path.join(ROOT, "prm"))):
        for name in sorted(n for n in names if n.endswith(".prm")):
            path = os.path.join(dirpath, name)
            label = os.path.relpath(path, os.path.join(ROOT, "prm"))
            text = prepared(open(path).read(), args.steps)
            work = os.path.join(args.workdir, label[:-4].replace("/", "_"))
            outs = []
            for which, exe in (("before", args.before), ("after", args.after)):
                rc, err = run(os.path.abspath(exe), text,
                              os.path.join(work, which))
                outs.append((rc, err, os.path.join(work, which, "out")))
            if outs[0][0] != outs[1][0]:
                print("%s: exit %d before, %d after" % (label, outs[0][0],
                                                         outs[1][0]))
                failed = True
                continue
            if outs[0][0] != 0:
                print("%s: both exit %d (%s)" % (label, outs[0][0],
                                                 outs[0][1].strip()[:120]))
                continue
            conv = [os.path.join(o[2], "convergence.csv") for o in outs]
            if os.path.exists(conv[0]):
                d = csv_difference(*conv)
                print("%s: convergence.csv max rel. difference %s" %
                      (label, "DIFFERENT ROWS" if d is None else "%.1e" % d))
                failed |= d is None
                continue
            d, n = nodal_difference(outs[0][2], outs[1][2])
            print("%s: %d nodal files, max rel. difference %s" %
                  (label, n, "DIFFERENT FILES" if d is None else "%.1e" % d))
            failed |= d is None
            sys.stdout.flush()
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
