"""Writes example_d.ipynb (kept as plain Python here so diffs stay readable).

    /usr/bin/python3 jupyter-notes/make_example_d_notebook.py
"""
from notebook_writer import write_notebook

cells = [
("markdown", """# Example D: an arch on two pillars with long memory

`prm/example_d_arch_memory.prm` is Example D (Sofonea, Ochal &
Bartman-Szwarc 2024, as the conmech code sets it up; `doc/examples.md`,
section 12): the static class with a relaxation kernel,
σ(t) = Bε(u(t)) + ∫_0^t R ε(u(s)) ds with R ε = 2 μ_R ε, μ_R = 10⁴
constant in time (doc/theory.md, section 11). The left pillar's base is
clamped, the right pillar's base rests on a rigid foundation with a
constant resistance −σ_ν ∈ 10 ∂(u_ν)₊, frictionless, and the vertical
traction (0, 5 sin t) on the outer arc lifts the right pillar off for
t ∈ (0, π) and pushes it in later. `prm/example_d_arch_elastic.prm` is the
same arch without memory (μ_R = 0).

This notebook reads both runs' `steps.csv`, `probes.csv` (u at the 21
nodes of the right pillar's base, every step), the contact CSV files and
the VTU pieces; prints the lift history's landmarks beside those the
conmech code reports; draws the history of min u_y over the base and the
deformed arch at t = 1.5, 2.75, 4, 5, 6. It fails unless both runs have
their 768 load values, Clapeyron's identity holds, the constant resistance
holds at every node, and the landmarks are near the published ones.

Run from the repository root:

    ./build/hemicontact prm/example_d_arch_memory.prm
    ./build/hemicontact prm/example_d_arch_elastic.prm
    jupyter nbconvert --to notebook --execute --output-dir /tmp jupyter-notes/example_d.ipynb

`HEMICONTACT_MEMORY_RUN=dir` and `HEMICONTACT_ELASTIC_RUN=dir` read other
output directories (relative paths from the repository root; defaults
`output-example-d-memory`, `output-example-d-elastic`), and
`HEMICONTACT_OUTPUT_ROOT=dir` writes the figures to `dir/doc/figures/`."""),
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
def run_directory(variable, default):
    path = pathlib.Path(os.environ.get(variable, default))
    return path if path.is_absolute() else root / path
runs = {"with memory": run_directory("HEMICONTACT_MEMORY_RUN", "output-example-d-memory"),
        "without memory": run_directory("HEMICONTACT_ELASTIC_RUN", "output-example-d-elastic")}
out_root = pathlib.Path(os.environ.get("HEMICONTACT_OUTPUT_ROOT", root))
figures = out_root / "doc" / "figures"
figures.mkdir(parents=True, exist_ok=True)
steps = {}
for name, run in runs.items():
    assert (run / "steps.csv").exists(), f"no {run}/steps.csv: run prm/example_d_arch_*.prm first"
    steps[name] = pd.read_csv(run / "steps.csv")
    s = steps[name]
    print(f"{name}: {run.name}, {len(s)} load values, {s.n_cells.iloc[-1]} cells, {s.n_dofs.iloc[-1]} dofs, "
          f"t = {s.time.iloc[-1]:g}")"""),
("markdown", """## The load values

Newton iterations, halved load steps (`time_step_halvings`), and the
relative defect of Clapeyron's identity of each load value with the
memory's work booked in `memory_work` (doc/theory.md, sections 9.4 and
11.7)."""),
("code", """for name, s in steps.items():
    assert len(s) == 768 and abs(s.time.iloc[-1] - 6) < 1e-12, f"{name}: the run is not the shipped 768 load values"
    defect = s.relative_energy_defect.abs().max()
    print(f"{name}: Newton iterations per load value mean {s.newton_iterations.mean():.2f}, "
          f"max {s.newton_iterations.max()}; halved load steps {int((s.time_step_halvings > 0).sum())}; "
          f"largest relative energy defect {defect:.1e}; memory work at T {s.memory_work.iloc[-1]:.4g}")
    assert defect < 1e-6, f"{name}: Clapeyron's identity is violated"
assert (steps["without memory"].memory_work == 0).all()
assert (steps["with memory"].memory_work != 0).any()"""),
("markdown", """## The lift of the right pillar

min u_y over the 21 nodes of the right pillar's base at every load value
(positive: lifted off the foundation): the largest lift and when it
happens, the first time the base is back on the foundation, the deepest
penetration. The conmech code's numbers (`doc/examples.md`, section 12)
come from another memory rule (the right rectangle, implicit), another
contact law (a lagged compliance) and k = 1/32: the same shape and nearby
times are expected, not equal digits."""),
("code", """published = {"with memory": (0.2985, 1.06, 2.34, -0.472, 4.03),
             "without memory": (0.619, 1.66, 3.19, -0.598, 4.75)}
history, rows = {}, []
for name, run in runs.items():
    probes = pd.read_csv(run / "probes.csv")
    assert probes.point.nunique() == 21 and (probes.y == 0).all()
    lift = probes.groupby("time").u_y.min()
    history[name] = lift
    t, v = lift.index.to_numpy(), lift.to_numpy()
    top = v.argmax()
    back = np.flatnonzero((t > t[top]) & (v <= 0))[0]
    deep = v.argmin()
    rows.append([name, v[top], t[top], t[back], v[deep], t[deep], *published[name]])
table = pd.DataFrame(rows, columns=["run", "largest lift", "at t", "back in contact at t", "deepest",
                                    "at t ", "conmech: lift", "at t  ", "back at t", "deepest ", "at t   "])
print(table.to_string(index=False, float_format=lambda x: f"{x:.4g}"))
ours = {r[0]: r for r in rows}
for name, (lift, lift_t, back_t, deep, deep_t) in published.items():
    r = ours[name]
    assert abs(r[1] - lift) < 0.1 * lift, f"{name}: largest lift {r[1]:.4g} is not near {lift}"
    assert abs(r[2] - lift_t) < 0.2 and abs(r[3] - back_t) < 0.2, f"{name}: the lift's times moved"
    assert r[4] < 0 and abs(r[5] - deep_t) < 0.2, f"{name}: no penetration near t = {deep_t}"
assert ours["with memory"][1] < 0.6 * ours["without memory"][1], "the memory does not stiffen the arch" """),
("markdown", """## The constant resistance at the base

In every contact CSV file: a separated node (u_ν < 0) carries no
pressure, a node on the foundation (u_ν = 0) a pressure in [0, 10], a
penetrating node (u_ν > 0) exactly 10, and with no friction the
tangential traction vanishes (to the solver's tolerance: the nodal
tractions are read from the residual, below 2e-4 of the resistance)."""),
("code", """for name, run in runs.items():
    files = sorted(run.glob("contact_*.csv"), key=lambda f: int(re.search(r"(\\d+)", f.name).group(1)))
    contact = pd.concat(pd.read_csv(f) for f in files)
    pressure = -contact.sigma_nu
    separated, pressed = contact.u_nu < -1e-10, contact.u_nu > 1e-10
    on = ~separated & ~pressed
    assert (pressure[separated].abs() < 1e-8).all()
    assert (pressure[on] > -1e-8).all() and (pressure[on] < 10 + 1e-8).all()
    assert np.allclose(pressure[pressed], 10, atol=1e-8)
    assert contact.sigma_tau_norm.abs().max() < 2e-4 * 10, "friction where there is none"
    print(f"{name}: {len(files)} contact files, node states separated/on/penetrating "
          f"{separated.sum()}/{on.sum()}/{pressed.sum()}, pressure in [{pressure.min():.3g}, {pressure.max():.3g}]")"""),
("markdown", """## Figures

Left: the history of min u_y over the base with and without memory.
Right: the deformed arch (displacement as computed) at t = 1.5, 2.75, 4,
5, 6 with memory, coloured by the von Mises stress of the instantaneous
part B ε(u) (the solution files' `von_mises`), the foundation y = 0 as a
line."""),
("code", """fig, ax = plt.subplots(figsize=(6.4, 3.6))
for name, lift in history.items():
    ax.plot(lift.index, lift.to_numpy(), label=name)
ax.axhline(0, color="0.5", lw=0.6)
ax.set_xlabel("t")
ax.set_ylabel("min u_y on the right base")
ax.set_title("Example D: lift (> 0) and penetration (< 0) of the right pillar", fontsize=10)
ax.legend()
fig.savefig(figures / "example-d-lift.png", dpi=110, bbox_inches="tight")
plt.close(fig)

run = runs["with memory"]
times = (1.5, 2.75, 4, 5, 6)
fig, axes = plt.subplots(1, len(times), figsize=(15, 3.4))
for ax, t in zip(axes, times):
    piece = run / f"solution_{round(t / 0.0078125):05d}.0.vtu"
    assert piece.exists(), f"no {piece.name}: the shipped output interval writes every 32 load values"
    mesh = meshio.read(piece)
    points = mesh.points[:, :2].astype(float)
    u = mesh.point_data["displacement"][:, :2].astype(float)
    triangles = mesh.cells_dict["triangle"]
    stress = mesh.point_data["von_mises"].ravel().astype(float)[triangles[:, 0]]
    xy = points + u
    image = ax.tripcolor(mtri.Triangulation(xy[:, 0], xy[:, 1], triangles), facecolors=stress,
                         cmap="viridis", vmin=0, vmax=60, shading="flat")
    ax.axhline(0, color="k", lw=0.8)
    ax.set_aspect("equal")
    ax.set_xlim(-0.6, 5.6)
    ax.set_ylim(-0.8, 5.2)
    ax.set_title(f"t = {t:g}", fontsize=10)
fig.colorbar(image, ax=axes, shrink=0.8, label="von Mises stress of B eps(u)")
fig.savefig(figures / "example-d-arch.png", dpi=100, bbox_inches="tight")
plt.close(fig)
print(sorted(p.name for p in figures.glob("example-d-*.png")))"""),
]

write_notebook(cells, "example_d")
