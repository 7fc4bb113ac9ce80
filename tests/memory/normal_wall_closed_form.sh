#!/usr/bin/env bash
# normal_wall_closed_form.sh EXE WORKDIR PRM: the run of PRM (a block held
# at a wall on its face x_d = 0, d the last coordinate, normal -e_d; normal
# memory with one Prony term b(t) = B exp(-t/TAU); uniform steps k; any
# class, 2D or 3D; doc/theory.md, section 11.9) writes in its
# double-precision nodal files an N_n that equals, at every contact node,
# the rule N_n = sum_{j<n} k b(t_n - t_j) (u_nu,j)_+ from the displacements
# of the same files, and at the nodes held at the wall (u_nu = g at every
# step, u_0 included) the geometric sum g B k q (1 - q^n)/(1 - q),
# q = exp(-k/TAU); both to 1e-12 relative to the largest N. B, TAU, g, k,
# the end time and the dimension are read from PRM.
set -euo pipefail
exe=$1; work=$2; prm=$3
rm -rf "$work"; mkdir -p "$work"; cd "$work"
sed 's/set directory *=.*/set directory = out/' "$prm" > run.prm
"$exe" run.prm > run.log
/usr/bin/python3 - <<'PY'
import glob, math, re, h5py, numpy as np
text = open("run.prm").read()
def value(name):
    return re.search(r"set " + name + r" *= *([^\n#]+)", text).group(1).strip()
B, tau = float(value("amplitudes")), float(value("relaxation times"))
g, k = float(value("penetration limit")), float(value("time step"))
dim, n_steps = int(value("dimension")), round(float(value("end time")) / k)
files = sorted(glob.glob("out/nodal_*.h5"))
assert len(files) == n_steps + 1, files
d = dim - 1
u, N = [], []
for f in files:
    with h5py.File(f, "r") as h:
        x = h["nodes"][:]
        bottom = np.abs(x[:, d]) < 1e-12
        u.append(-h["displacement"][:][bottom, d])   # u_nu, nu = -e_d
        N.append(-h["normal_memory"][:][bottom, d])  # N_i nu_i . nu
u, N = np.array(u), np.array(N)
b = lambda s: B * math.exp(-s / tau)
scale = np.abs(N).max()
rule = 0.0
for n in range(1, len(files)):
    expected = sum(k * b((n - j) * k) * np.maximum(u[j], 0) for j in range(n))
    rule = max(rule, np.abs(N[n] - expected).max() / scale)
held = np.all(np.abs(u - g) < 1e-14, axis=0)
q = math.exp(-k / tau)
closed = max(np.abs(N[n][held] - g * B * k * q * (1 - q**n) / (1 - q)).max()
             / scale for n in range(1, len(files)))
print(f"nodes {u.shape[1]}, held at the wall throughout {held.sum()}, "
      f"largest N {scale:.6g}")
print(f"rule from the nodal files: {rule:.3g}, closed form at the wall: "
      f"{closed:.3g}")
assert held.sum() >= 5, "too few nodes held at the wall"
assert rule < 1e-12 and closed < 1e-12, "FAIL"
print("PASS")
PY
