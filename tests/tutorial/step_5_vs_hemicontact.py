"""step_5_vs_hemicontact.py STEP_DIR HEMICONTACT_DIR: the nodal
displacements of tutorial/step-5 (displacement-NN.txt: x y u_x u_y in
%.17g) and of the full program (nodal_0000N.h5, 'output/precision =
double') at the four load values, matched by the node coordinates, agree
to 1e-10 relative to the largest displacement; the fixed-point iterations
on the friction bound and the branch counts of each load value (the step's
log, the full program's steps.csv: its n_at_wall are the step's nodes in
contact) agree; and the problem exercises separation, contact, and stick
and slip in contact (the step's contact-NN.csv)."""
import csv
import re
import sys

import h5py
import numpy as np

step_dir, full_dir = sys.argv[1], sys.argv[2]

worst = 0.0
for n in range(1, 5):
    step = np.loadtxt(f"{step_dir}/displacement-{n:02d}.txt")
    with h5py.File(f"{full_dir}/nodal_{n:05d}.h5", "r") as f:
        nodes = f["nodes"][...]
        full = f["displacement"][...]
        assert abs(f.attrs["time"] - 0.25 * n) < 1e-12, f.attrs["time"]
    assert len(step) == len(nodes), (len(step), len(nodes))
    lookup = {tuple(np.round(x, 9)): u for x, u in zip(nodes, full)}
    scale = np.abs(full).max()
    difference = max(np.abs(lookup[tuple(np.round(row[:2], 9))] - row[2:]).max()
                     for row in step)
    worst = max(worst, difference / scale)
    print(f"t = {0.25 * n:.2f}: {len(step)} nodes, max |u_step - u_full| = "
          f"{difference:.3e}, relative {difference / scale:.3e}")
assert worst <= 1e-10, worst

# the fixed point and the branches, load value by load value
mine = {}
for line in open(f"{step_dir}/step-5.log"):
    m = re.match(r"\s*t = ([0-9.]+): (\d+) bound iterations, \d+ Newton "
                 r"iterations, normal separating/stick/penetrating "
                 r"(\d+)/(\d+)/(\d+), tangential stick/slip (\d+)/(\d+)$", line)
    if m:
        mine[round(float(m.group(1)) / 0.25)] = [int(g) for g in m.groups()[1:]]
full = {}
for row in csv.DictReader(open(f"{full_dir}/steps.csv")):
    full[int(row["step"])] = [int(row[k]) for k in
                              ("bound_iterations", "n_separating", "n_at_wall",
                               "n_damped", "n_stick", "n_slip")]
assert mine == full, (mine, full)

seen = set()
for n in range(1, 5):
    table = np.genfromtxt(f"{step_dir}/contact-{n:02d}.csv", delimiter=",",
                          names=True)
    for row in table:
        if row["normal_branch"] == 0:
            seen.add("separating")
        else:
            seen.add(["contact, stick", "contact, slip"]
                     [int(row["tangential_branch"])])
assert seen == {"separating", "contact, stick", "contact, slip"}, seen
print(f"max relative difference {worst:.3e} <= 1e-10; the same bound "
      f"iterations and branch counts at every load value; branches visited: "
      + ", ".join(sorted(seen)))
