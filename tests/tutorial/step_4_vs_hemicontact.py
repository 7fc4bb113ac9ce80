"""step_4_vs_hemicontact.py STEP_DIR HEMICONTACT_DIR CYCLES: cycle n of
tutorial/step-4's adaptive loop (displacement-NN.txt: x y u_x u_y in
%.17g, NN = n; adaptive.csv: the energy and the estimate in %.17g) and
load value n + 1 of the full program (nodal_0000M.h5 with 'output/precision
= double', M = n + 1; steps.csv with 12 significant digits) are on the
same mesh (the same nodes, hanging nodes included), with nodal
displacements that agree to 1e-10 relative to the largest displacement,
and the same energy J_h(u_h) ('minimised_energy') and error estimate
('error_estimate' and its four parts) to 1e-10 relative. The same mesh
at every cycle means that the two programs marked the same cells, from
estimates that agree."""
import csv
import sys

import h5py
import numpy as np

step_dir, full_dir, cycles = sys.argv[1], sys.argv[2], int(sys.argv[3])
with open(f"{step_dir}/adaptive.csv") as f:
    step_rows = list(csv.DictReader(f))
with open(f"{full_dir}/steps.csv") as f:
    full_rows = {int(r["step"]): r for r in csv.DictReader(f)}
assert len(step_rows) == cycles, len(step_rows)

columns = [("energy", "minimised_energy"), ("estimate", "error_estimate"),
           ("estimate_interior", "estimate_interior"),
           ("estimate_jumps", "estimate_jumps"),
           ("estimate_neumann", "estimate_neumann"),
           ("estimate_contact", "estimate_contact")]
worst_u, worst_scalar = 0.0, 0.0
for n in range(cycles):
    step = np.loadtxt(f"{step_dir}/displacement-{n:02d}.txt")
    with h5py.File(f"{full_dir}/nodal_{n + 1:05d}.h5", "r") as f:
        nodes = f["nodes"][...]
        full = f["displacement"][...]
    lookup = {tuple(np.round(x, 9)): u for x, u in zip(nodes, full)}
    keys = [tuple(np.round(row[:2], 9)) for row in step]
    assert len(step) == len(nodes) and set(keys) == set(lookup), \
        f"cycle {n}: the meshes differ ({len(step)} and {len(nodes)} nodes)"
    scale = np.abs(full).max()
    du = max(np.abs(lookup[k] - row[2:]).max() for k, row in zip(keys, step))
    worst_u = max(worst_u, du / scale)
    s, r = step_rows[n], full_rows[n + 1]
    assert int(s["dofs"]) == int(r["n_dofs"]), (n, s["dofs"], r["n_dofs"])
    differences = []
    for mine, theirs in columns:
        a, b = float(s[mine]), float(r[theirs])
        differences.append(abs(a - b) / abs(b))
    worst_scalar = max([worst_scalar] + differences)
    print(f"cycle {n:2d}: {len(step):5d} nodes, {s['dofs']:>5s} dofs, "
          f"u relative {du / scale:.1e}, J_h {differences[0]:.1e}, "
          f"eta {differences[1]:.1e}, parts "
          + " ".join(f"{d:.1e}" for d in differences[2:]))
assert worst_u <= 1e-10, worst_u
assert worst_scalar <= 1e-10, worst_scalar
print(f"the same {cycles} meshes; max relative difference: displacement "
      f"{worst_u:.3e}, energy and estimate {worst_scalar:.3e} (<= 1e-10)")
