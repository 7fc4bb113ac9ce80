#!/usr/bin/python3
"""Time of writing the output and its size at each 'output/compression'
level, on one example (default prm/block_2d.prm), in one run of this script:

    /usr/bin/python3 bench/output_compression.py [PRM] [--repeat N]

Prints, per level, the fastest over N runs of the 'output' timer and of the
whole run (TimerOutput summary) and the size of the output directory.
"""
import argparse
import os
import re
import shutil
import subprocess
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
LEVELS = ["best compression", "default", "best speed", "none"]


def run(prm, level, directory):
    shutil.rmtree(directory, ignore_errors=True)
    text = open(prm).read() + ("\nsubsection output\n  set directory = %s\n"
                               "  set compression = %s\nend\n"
                               % (directory, level))
    path = directory + ".prm"
    open(path, "w").write(text)
    log = subprocess.run([os.path.join(ROOT, "build", "hemicontact"), path],
                         check=True, capture_output=True, text=True).stdout
    seconds = lambda name: float(re.search(r"\| %s\s*\|[^|]*\|\s*([0-9.]+)s" % name, log).group(1))
    size = sum(os.path.getsize(os.path.join(d, f)) for d, _, fs in os.walk(directory) for f in fs)
    return seconds("output"), seconds("Total wallclock time elapsed"), size


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("prm", nargs="?", default=os.path.join(ROOT, "prm", "block_2d.prm"))
    parser.add_argument("--repeat", type=int, default=3)
    args = parser.parse_args()
    work = tempfile.mkdtemp()
    print("%-17s %10s %10s %10s" % ("compression", "output s", "run s", "size MB"))
    for level in LEVELS:
        runs = [run(args.prm, level, os.path.join(work, "out")) for _ in range(args.repeat)]
        print("%-17s %10.3f %10.3f %10.2f" % (level, min(r[0] for r in runs),
                                               min(r[1] for r in runs), runs[0][2] / 1e6))
    shutil.rmtree(work)


if __name__ == "__main__":
    main()
