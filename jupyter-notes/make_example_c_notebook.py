"""Writes example_c.ipynb (kept as plain Python here so diffs stay readable).

    /usr/bin/python3 jupyter-notes/make_example_c_notebook.py
"""
from notebook_writer import write_notebook

cells = [
("markdown", """# Example C: the quasistatic plate held by four screws

`prm/example_c_plate_2d.prm` is Example C of Jureczka, Ochal & Bartman
(2023): a quasistatic Kelvin–Voigt plate (no inertia) with a half-disk
cut-out, held by four screws and resting on the foundation with its two
bottom segments; the normal damped response c min(v₊, 0.1) (c = 300) and
slip-rate-weakening friction with the bound 3 min(w_ν₊, 0.1) in the
step's own normal velocity (`doc/examples.md`, section 7).

This notebook reads the run's `steps.csv`, the last `contact_NNNNN.csv`
and the last VTU piece, prints the numbers `doc/examples.md` quotes, and
draws the Frobenius norm |σ| of the Kelvin–Voigt stress
σ = A ε(w) + B ε(u) (the cell averages the program writes,
`stress_xx`, `stress_xy`, `stress_yy`) on the deformed body at the final
time, on the colour range 0–30 of the paper's maps. It fails unless the
run has its 32 steps, the energy identity holds, and the realised contact
state satisfies the laws.

Run from the repository root:

    ./build/hemicontact prm/example_c_plate_2d.prm
    jupyter nbconvert --to notebook --execute --output-dir /tmp jupyter-notes/example_c.ipynb

`HEMICONTACT_RUN=dir` reads another output directory (relative paths from
the repository root; default `output-example-c`), and
`HEMICONTACT_OUTPUT_ROOT=dir` writes the figure to `dir/doc/figures/`."""),
("code", """import os, pathlib, re
import numpy as np
import pandas as pd
import meshio
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import matplotlib.tri as mtri

root = pathlib.Path.cwd()
if not (root / "prm").exists():
    root = root.parent
run = pathlib.Path(os.environ.get("HEMICONTACT_RUN", "output-example-c"))
if not run.is_absolute():
    run = root / run
out_root = pathlib.Path(os.environ.get("HEMICONTACT_OUTPUT_ROOT", root))
figures = out_root / "doc" / "figures"
figures.mkdir(parents=True, exist_ok=True)
assert (run / "steps.csv").exists(), f"no {run}/steps.csv: run prm/example_c_plate_2d.prm first"
steps = pd.read_csv(run / "steps.csv")
print(f"{run}: {len(steps)} steps, {steps.n_cells.iloc[-1]} cells, {steps.n_dofs.iloc[-1]} dofs, "
      f"t = {steps.time.iloc[-1]:g}")"""),
("markdown", """## The steps

Newton iterations, fixed-point iterations on the friction bound
(`bound_iterations`, doc/theory.md section 9.8), the branch counts of the
42 contact nodes and the relative defect of the energy identity
(doc/theory.md section 9.3)."""),
("code", """assert len(steps) == 32 and abs(steps.time.iloc[-1] - 0.25) < 1e-12, "the run is not the shipped 32 steps"
defect = steps.relative_energy_defect.abs().max()
print(f"Newton iterations per step: mean {steps.newton_iterations.mean():.2f}, max {steps.newton_iterations.max()}")
print(f"bound iterations per step: {sorted(set(steps.bound_iterations))} (total {steps.bound_iterations.sum()})")
print(f"line-search reductions: {steps.line_search_reductions.sum()}, Krylov iterations per step: "
      f"mean {steps.linear_iterations.mean():.1f}")
print(f"branches at the last step: separating {steps.n_separating.iloc[-1]}, normal stick "
      f"{steps.n_normal_stick.iloc[-1]}, damped {steps.n_damped.iloc[-1]}; stick {steps.n_stick.iloc[-1]}, "
      f"slip {steps.n_slip.iloc[-1]}")
print(f"largest relative energy defect {defect:.1e}")
last = steps.iloc[-1]
print(f"at t = {last.time:g}: external work {last.external_work:.4g}, elastic energy {last.elastic_energy:.4g}, "
      f"viscous dissipation {last.viscous_dissipation:.4g}, friction {last.friction_dissipation:.3g}, "
      f"normal damping {last.normal_damping_dissipation:.3g}, numerical {last.numerical_dissipation:.3g}")
assert defect < 1e-6, "the discrete energy identity is violated" """),
("markdown", """## The contact boundary at the final time

The realised state must satisfy the laws: where w_ν = 0 (normal stick)
the response −σ_ν lies in [0, c] = [0, 300]; the friction bound used is
3 min(w_ν₊, 0.1); on slipping nodes the friction force is
F_b (0.7 + 0.3 e^{−|w_τ|})."""),
("code", """files = sorted(run.glob("contact_*.csv"), key=lambda f: int(re.search(r"(\\d+)", f.name).group(1)))
contact = pd.read_csv(files[-1])
assert abs(contact.time.iloc[0] - 0.25) < 1e-12, f"{files[-1].name} is not the final time"
pressure = -contact.sigma_nu
print(f"{files[-1].name}: {len(contact)} nodes, w_nu in [{contact.w_nu.min():.3g}, {contact.w_nu.max():.3g}], "
      f"-sigma_nu in [{pressure.min():.3g}, {pressure.max():.3g}], |w_tau| in "
      f"[{contact.w_tau_norm.min():.3g}, {contact.w_tau_norm.max():.3g}], "
      f"friction bound in [{contact.friction_bound.min():.3g}, {contact.friction_bound.max():.3g}]")
stick = contact.normal_branch == 1
assert (pressure[stick] >= -1e-8).all() and (pressure[stick] <= 300 + 1e-8).all()
bound = 3 * np.minimum(np.maximum(contact.w_nu, 0), 0.1)
assert np.allclose(contact.friction_bound, bound, rtol=1e-6, atol=1e-9), "the bound used is not 3 min(w_nu_+, 0.1)"
slip = contact.tangential_branch == 1
law = contact.friction_bound * (0.7 + 0.3 * np.exp(-contact.w_tau_norm))
assert np.allclose(contact.sigma_tau_norm[slip], law[slip], rtol=1e-6, atol=1e-6), "the friction force is not the law's" """),
("markdown", """## The stress norm on the deformed body

Each triangle is coloured by |σ| = (σ_xx² + 2σ_xy² + σ_yy²)^{1/2} of its
cell-averaged stress, drawn at x + u(x, T). Top: the true deformation, the
paper's colour range 0–30. Bottom: the same with the displacement
magnified, to show how the plate moves."""),
("code", """pieces = sorted(run.glob("solution_*.0.vtu"))
assert pieces, f"no solution_*.0.vtu in {run}"
mesh = meshio.read(pieces[-1])
points = mesh.points[:, :2].astype(float)
u = mesh.point_data["displacement"][:, :2].astype(float)
triangles = mesh.cells_dict["triangle"]
sxx, sxy, syy = (mesh.point_data[f"stress_{c}"].ravel().astype(float) for c in ("xx", "xy", "yy"))
norm_nodes = np.sqrt(sxx**2 + 2 * sxy**2 + syy**2)
norm = norm_nodes[triangles[:, 0]]    # deal.II writes each cell value at the cell's own vertices
assert np.allclose(norm, norm_nodes[triangles[:, 1]]) and np.allclose(norm, norm_nodes[triangles[:, 2]])
umax = np.abs(u).max()
print(f"{pieces[-1].name}: {len(triangles)} triangles, max |u| {np.linalg.norm(u, axis=1).max():.3g}, "
      f"stress norm max {norm.max():.3g} (cell at x = {points[triangles[norm.argmax()]].mean(axis=0).round(3)}), "
      f"mean {norm.mean():.3g}")
assert 0 < norm.max() < 100

magnified = 20
fig, axes = plt.subplots(2, 1, figsize=(7.2, 7.6))
for ax, scale in zip(axes, (1, magnified)):
    xy = points + scale * u
    tri = mtri.Triangulation(xy[:, 0], xy[:, 1], triangles)
    image = ax.tripcolor(tri, facecolors=norm, cmap="rainbow", vmin=0, vmax=30, shading="flat")
    ax.plot([0, 1.2, 1.2, 0, 0], [0, 0, 0.6, 0.6, 0], color="0.6", lw=0.5, ls="--")
    ax.set_aspect("equal")
    ax.set_xlim(-0.15, 1.25)
    ax.set_ylim(-0.05, 0.65)
    ax.set_title(f"t = {steps.time.iloc[-1]:g}, displacement " + ("as computed" if scale == 1 else f"x {scale}"),
                 fontsize=10)
    ax.set_xlabel("x")
    ax.set_ylabel("y")
fig.colorbar(image, ax=axes, shrink=0.8, label="stress norm $|\\\\sigma|$")
fig.savefig(figures / "example-c-stress.png", dpi=110, bbox_inches="tight")
plt.close(fig)
print(sorted(p.name for p in figures.glob("example-c-*.png")))"""),
]

write_notebook(cells, "example_c")
