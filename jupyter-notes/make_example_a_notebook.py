"""Writes example_a.ipynb (kept as plain Python here so diffs stay readable).

    /usr/bin/python3 jupyter-notes/make_example_a_notebook.py
"""
from notebook_writer import write_notebook

cells = [
("markdown", """# Example A: nonmonotone compliance and a friction bound from u_ν (static)

`prm/example_a_static_2d.prm` is Example A of Jureczka & Ochal (2019): a
static body on (0, 2) × (0, 1), clamped at x = 0, pushed by the body force
(−1.2, −0.9) onto the foundation at y = 0, with the compliance p = 20 u_ν
up to u_ν = 0.1 and then 0, and friction with the potential
h(u_ν) ln(1 + |u_τ|), h = 8 u_ν up to 0.1 and then 0.8. The bound h(u_ν)
is found by fixed-point iterations at every load value
(`doc/examples.md`, section 8). `prm/example_a_frictionless_2d.prm` is the
same body without friction.

This notebook reads both runs, prints the displacements at the points the
reference implementation reports, checks the laws on the contact
boundary, and draws u_ν, |u_τ| and the friction bound along y = 0.

Run from the repository root:

    ./build/hemicontact prm/example_a_static_2d.prm
    ./build/hemicontact prm/example_a_frictionless_2d.prm
    jupyter nbconvert --to notebook --execute --output-dir /tmp jupyter-notes/example_a.ipynb

`HEMICONTACT_RUN=dir` and `HEMICONTACT_FRICTIONLESS_RUN=dir` read other
output directories (default `output-example-a` and
`output-example-a-frictionless`), and `HEMICONTACT_OUTPUT_ROOT=dir`
writes the figure to `dir/doc/figures/`."""),
("code", """import os, pathlib, re
import numpy as np
import pandas as pd
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

root = pathlib.Path.cwd()
if not (root / "prm").exists():
    root = root.parent
def run_dir(variable, default):
    path = pathlib.Path(os.environ.get(variable, default))
    return path if path.is_absolute() else root / path
runs = {"friction bound iterated": run_dir("HEMICONTACT_RUN", "output-example-a"),
        "frictionless": run_dir("HEMICONTACT_FRICTIONLESS_RUN", "output-example-a-frictionless")}
out_root = pathlib.Path(os.environ.get("HEMICONTACT_OUTPUT_ROOT", root))
figures = out_root / "doc" / "figures"
figures.mkdir(parents=True, exist_ok=True)
for name, run in runs.items():
    assert (run / "steps.csv").exists(), f"no {run}/steps.csv: run the example first"
    steps = pd.read_csv(run / "steps.csv")
    assert steps.relative_energy_defect.abs().max() < 1e-7
    print(f"{name}: {len(steps)} load values, {steps.n_dofs.iloc[-1]} dofs, Newton iterations "
          f"{steps.newton_iterations.sum()}, bound iterations per load value {list(steps.bound_iterations)}")"""),
("markdown", """## The displacements at the reported points

The reference implementation reports u(1, 0) ≈ (−0.1657, −0.0423),
u(2, 0) ≈ (−0.1979, −0.0427) and u(2, 1) ≈ (−0.1927, −0.0829), with the
friction bound frozen at its initial guess, that is close to the
frictionless answer."""),
("code", """published = {(1, 0): (-0.1657, -0.0423), (2, 0): (-0.1979, -0.0427), (2, 1): (-0.1927, -0.0829)}
table = []
for name, run in runs.items():
    probes = pd.read_csv(run / "probes.csv")
    final = probes[probes.step == probes.step.max()]
    for _, p in final.iterrows():
        ref = published[(round(p.x), round(p.y))]
        table.append((name, f"({p.x:g}, {p.y:g})", p.u_x, p.u_y, ref[0], ref[1]))
table = pd.DataFrame(table, columns=["run", "point", "u_x", "u_y", "published u_x", "published u_y"])
print(table.to_string(index=False, float_format=lambda v: f"{v:.4f}"))
free = table[table.run == "frictionless"]
assert (abs(free.u_x - free["published u_x"]) < 0.01).all() and (abs(free.u_y - free["published u_y"]) < 0.01).all(), \\
    "the frictionless run is not within 0.01 of the published numbers" """),
("markdown", """## The laws on the contact boundary

On slipping nodes the friction force is h(u_ν)/(1 + |u_τ|), with the bound
of the solution's own u_ν (the fixed point); the normal traction is
20 u_ν where 0 < u_ν < 0.1."""),
("code", """def last_contact(run):
    files = sorted(run.glob("contact_*.csv"), key=lambda f: int(re.search(r"(\\d+)", f.name).group(1)))
    return pd.read_csv(files[-1]).sort_values("x")
contact = {name: last_contact(run) for name, run in runs.items()}
c = contact["friction bound iterated"]
h = np.where(c.u_nu < 0.1, 8 * np.maximum(c.u_nu, 0), 0.8)
assert np.allclose(c.friction_bound, h, rtol=1e-6, atol=1e-8), "the bound is not h(u_nu) of the solution"
slip = c.tangential_branch == 1
assert np.allclose(c.sigma_tau_norm[slip], (h / (1 + c.u_tau_norm))[slip], rtol=1e-5, atol=1e-7)
compliant = (c.u_nu > 1e-9) & (c.u_nu < 0.1)
assert np.allclose(-c.sigma_nu[compliant], 20 * c.u_nu[compliant], rtol=1e-5, atol=1e-7)
print(f"{len(c)} contact nodes: {int(slip.sum())} slipping, u_nu in [{c.u_nu.min():.4f}, {c.u_nu.max():.4f}], "
      f"friction bound in [{c.friction_bound.min():.3f}, {c.friction_bound.max():.3f}]")"""),
("code", """fig, axes = plt.subplots(1, 3, figsize=(11, 3.2))
for name, c in contact.items():
    axes[0].plot(c.x, c.u_nu, label=name)
    axes[1].plot(c.x, c.u_tau_norm, label=name)
    axes[2].plot(c.x, c.friction_bound, label=name)
for ax, label in zip(axes, ["$u_\\\\nu$", "$|u_\\\\tau|$", "friction bound $h(u_\\\\nu)$"]):
    ax.set_xlabel("x on y = 0")
    ax.set_title(label, fontsize=10)
axes[0].legend(fontsize=8)
fig.tight_layout()
fig.savefig(figures / "example-a-profiles.png", dpi=110)
plt.close(fig)
print(sorted(p.name for p in figures.glob("example-a-*.png")))"""),
]

write_notebook(cells, "example_a")
