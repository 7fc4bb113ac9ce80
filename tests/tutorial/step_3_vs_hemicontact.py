"""step_3_vs_hemicontact.py STEP_DIR HEMICONTACT_DIR STEP_LOG: the nodal
displacements of tutorial/step-3 (displacement-NN.txt: x y u_x u_y in
%.17g) and of the full program (nodal_NNNNN.h5, 'output/precision =
double') at the 17 load values t_n = n/8, n = 0..16, of the block with
memory (step_3_block.prm), matched by the node coordinates, agree to 1e-10
relative to the largest displacement of the load value; the branch counts
of load values 1..16 (the full program's steps.csv, the step's log) agree;
and the problem
exercises every branch (read from the step's contact-NN.csv: separating,
stick and penetrating on each of the three segments of the normal law,
tangential stick and slip) and both memories (N > 0 at the contact, and
the penetration falling under the held load)."""
import csv
import re
import sys

import h5py
import numpy as np

step_dir, full_dir, step_log = sys.argv[1:4]
n_values, k = 17, 0.125
breakpoints = [0.02, 0.15]  # the law's kinks between its three segments

worst = 0.0
for n in range(n_values):
    step = np.loadtxt(f"{step_dir}/displacement-{n:02d}.txt")
    with h5py.File(f"{full_dir}/nodal_{n:05d}.h5", "r") as f:
        nodes = f["nodes"][...]
        full = f["displacement"][...]
        assert abs(f.attrs["time"] - k * n) < 1e-12, (n, f.attrs["time"])
    assert len(step) == len(nodes), (len(step), len(nodes))
    lookup = {tuple(np.round(x, 9)): u for x, u in zip(nodes, full)}
    scale = np.abs(full).max()
    difference = max(np.abs(lookup[tuple(np.round(row[:2], 9))] - row[2:]).max()
                     for row in step)
    worst = max(worst, difference / scale)
    print(f"t = {k * n:.3f}: {len(step)} nodes, max |u_step - u_full| = "
          f"{difference:.3e}, relative {difference / scale:.3e}")
assert worst <= 1e-10, worst

# the branch counts per load value n >= 1 (steps.csv has no row for the
# load value 0, which the full program solves before its first step)
branches = ["n_separating", "n_normal_stick", "n_damped", "n_stick", "n_slip"]
full_counts = {int(r["step"]): [int(r[b]) for b in branches]
               for r in csv.DictReader(open(full_dir + "/steps.csv"))}
step_counts = {}
for line in open(step_log):
    m = re.match(r"\s*t = ([0-9.]+): \d+ Newton, normal sep/stick/pen "
                 r"(\d+)/(\d+)/(\d+), tangential stick/slip (\d+)/(\d+)", line)
    if m and float(m.group(1)) > 0:
        step_counts[round(float(m.group(1)) / k)] = [int(g) for g in m.groups()[1:]]
assert len(full_counts) == n_values - 1 and step_counts == full_counts, \
    (full_counts, step_counts)

# every branch is visited at some load value, and the memory acts
seen = set()
largest = []
for n in range(n_values):
    table = np.genfromtxt(f"{step_dir}/contact-{n:02d}.csv", delimiter=",",
                          names=True)
    largest.append(table["u_nu"].max())
    for row in table:
        if row["normal_branch"] == 2:
            seen.add("penetrating on segment %d"
                     % (1 + np.searchsorted(breakpoints, row["u_nu"])))
        else:
            seen.add(["separating", "normal stick"][int(row["normal_branch"])])
        seen.add(["tangential stick", "slip"][int(row["tangential_branch"])])
expected = {"separating", "normal stick", "penetrating on segment 1",
            "penetrating on segment 2", "penetrating on segment 3",
            "tangential stick", "slip"}
assert seen == expected, sorted(seen)
assert table["N"].max() > 0, "no memory pressure at t = 2"
# the full load from t = 0.75 (n = 6) on: the penetration falls under it
assert largest[-1] < largest[6], (largest[6], largest[-1])
print(f"max relative difference {worst:.3e} <= 1e-10; the same branch counts "
      f"at the {len(full_counts)} load values after the first; branches visited: "
      + ", ".join(sorted(seen)) + f"; largest u_nu {largest[6]:.4f} at "
      f"t = 0.75, {largest[-1]:.4f} at t = 2 under the same load")
