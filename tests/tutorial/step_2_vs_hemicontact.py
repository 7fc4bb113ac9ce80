"""step_2_vs_hemicontact.py HEMICONTACT_DIR STEP_2_DIR STEP_2_LOG: the
nodal velocity and displacement of every step of the full program
(nodal_NNNNN.h5, output/precision = double) and of tutorial/step-2
(displacement-NN.txt: x, y, u_x, u_y, w_x, w_y in %.17g), matched by node
coordinates, agree to 1e-10 relative to the largest value of the field at
that step; the branch counts per step (steps.csv, the step-2 log, whose
'penetrating' is the full program's 'damped') agree, and every branch
occurs."""
import csv
import re
import sys

import h5py
import numpy as np

full_dir, step2_dir, step2_log = sys.argv[1:4]
TOLERANCE = 1e-10

rows = list(csv.DictReader(open(full_dir + "/steps.csv")))
branches = ["n_separating", "n_normal_stick", "n_damped", "n_stick", "n_slip"]
full_counts = {int(r["step"]): [int(r[b]) for b in branches] for r in rows}
step2_counts = {}
for line in open(step2_log):
    m = re.match(r"\s*t = ([0-9.]+): \d+ Newton iterations, normal "
                 r"separating/stick/penetrating (\d+)/(\d+)/(\d+), "
                 r"tangential stick/slip (\d+)/(\d+)$", line)
    if m:
        step = round(float(m.group(1)) / 0.04)
        step2_counts[step] = [int(g) for g in m.groups()[1:]]
assert len(full_counts) == 25 and step2_counts == full_counts, \
    (full_counts, step2_counts)
totals = np.sum(list(full_counts.values()), axis=0)
assert np.all(totals > 0), dict(zip(branches, totals))

worst = {"velocity": 0.0, "displacement": 0.0}
for step in range(1, 26):
    with h5py.File(f"{full_dir}/nodal_{step:05d}.h5", "r") as f:
        nodes = f["nodes"][...]
        full = {k: f[k][...] for k in worst}
    table = np.loadtxt(f"{step2_dir}/displacement-{step:02d}.txt")
    assert len(table) == len(nodes), (len(table), len(nodes))
    index = {tuple(np.round(x, 9)): i for i, x in enumerate(table[:, :2])}
    order = [index[tuple(np.round(x, 9))] for x in nodes]
    mine = {"displacement": table[order, 2:4], "velocity": table[order, 4:6]}
    for k in worst:
        scale = np.abs(full[k]).max()
        if scale > 0:
            worst[k] = max(worst[k], np.abs(mine[k] - full[k]).max() / scale)
print(f"25 steps, {len(nodes)} nodes; branches over the run "
      f"{dict(zip(branches, totals.tolist()))}, the same in both; largest "
      f"relative difference: velocity {worst['velocity']:.2e}, "
      f"displacement {worst['displacement']:.2e}")
assert max(worst.values()) <= TOLERANCE, worst
