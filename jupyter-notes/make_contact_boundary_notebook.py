"""Writes contact_boundary.ipynb (kept as plain Python here so diffs stay readable).

    /usr/bin/python3 jupyter-notes/make_contact_boundary_notebook.py
"""
from notebook_writer import write_notebook

cells = [
("markdown", """# The contact boundary Γ3: tractions and velocities

Reads the `contact_NNNNN.csv` files of one hemicontact run (one file per
VTU output, one row per contact node; columns in
`doc/outputs.md`) and plots along Γ3, at a few times, the normal velocity w_ν, the
normal traction −σ_ν (the foundation's response ξ_ν ∈ ∂j_ν(w_ν)), the
tangential (slip) velocity w_τ and the tangential traction σ_τ; then the
branch of every node over space and time.

It also checks, node by node, that the written values satisfy the contact
conditions of their branch (and fails otherwise): separating nodes move
away from the foundation with σ_ν = 0, normal-stick nodes have w_ν = 0,
damped nodes move into it with −σ_ν > 0, stick nodes have w_τ = 0, and on
slipping nodes σ_τ points against w_τ.

Run from the repository root after running the example:

    ./build/hemicontact prm/block_2d.prm
    jupyter nbconvert --to notebook --execute --output-dir /tmp jupyter-notes/contact_boundary.ipynb

`HEMICONTACT_RUN=dir` reads another output directory (relative paths are
taken from the repository root; default `output-block-2d`),
`HEMICONTACT_TIMES=0.25,0.5` chooses the times (the nearest written ones
are used; default: about a quarter, half, three quarters and the end of
the run), and `HEMICONTACT_OUTPUT_ROOT=dir` writes the figures to
`dir/doc/figures/` instead of `doc/figures/`."""),
("code", """import os, pathlib, re
import numpy as np
import pandas as pd
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

root = pathlib.Path.cwd()
if not (root / "prm").exists():
    root = root.parent
run = pathlib.Path(os.environ.get("HEMICONTACT_RUN", "output-block-2d"))
if not run.is_absolute():
    run = root / run
tag = run.name[len("output-"):] if run.name.startswith("output-") else run.name
out_root = pathlib.Path(os.environ.get("HEMICONTACT_OUTPUT_ROOT", root))
figures = out_root / "doc" / "figures"
figures.mkdir(parents=True, exist_ok=True)

files = sorted(run.glob("contact_*.csv"))
assert len(files) >= 2, f"fewer than two contact_*.csv in {run}: run the example (output interval > 0) first"
frames = []
for f in files:
    df = pd.read_csv(f)
    df["step"] = int(re.search(r"contact_(\\d+)\\.csv", f.name).group(1))
    frames.append(df)
data = pd.concat(frames, ignore_index=True)
xyz = [c for c in ["x", "y", "z"] if c in data.columns]
dim = len(xyz)
times = sorted(data.time.unique())
print(f"{run}: {len(files)} contact files, {dim}D, {data.groupby('step').size().iloc[0]} nodes, "
      f"t = {times[0]:g} .. {times[-1]:g}")"""),
("markdown", """## Node-wise checks of the contact conditions"""),
("code", """scale_w = max(data.w_nu.abs().max(), data.w_tau_norm.abs().max(), 1e-300)
scale_s = max(data.sigma_nu.abs().max(), data.sigma_tau_norm.abs().max(), 1e-300)
tol_w, tol_s = 1e-7 * scale_w, 1e-7 * scale_s
later = data[data.time > 0]          # step 0 holds the initial state
sep = later[later.normal_branch == 0]
nstick = later[later.normal_branch == 1]
damped = later[later.normal_branch == 2]
held = later[later.normal_branch == 3]     # at a breakpoint of the law
wall = later[later.normal_branch == 4]     # at the wall
tstick = later[later.tangential_branch == 0]
slip = later[later.tangential_branch == 1]
w_tau = later[[f"w_tau_{c}" for c in xyz]].to_numpy()
s_tau = later[[f"sigma_tau_{c}" for c in xyz]].to_numpy()
checks = {
    "separating: w_nu <= 0": (sep.w_nu <= tol_w).all(),
    "separating: sigma_nu = 0": (sep.sigma_nu.abs() <= tol_s).all(),
    "normal stick: w_nu = 0": (nstick.w_nu.abs() <= tol_w).all(),
    "normal stick: -sigma_nu >= 0": (-nstick.sigma_nu >= -tol_s).all(),
    "damped: w_nu >= 0": (damped.w_nu >= -tol_w).all(),
    "damped: -sigma_nu > 0": (-damped.sigma_nu > 0).all(),
    "at a breakpoint: -sigma_nu > 0": (-held.sigma_nu > 0).all(),
    "at the wall: reaction >= 0": ("wall_pressure" not in wall.columns or (wall.wall_pressure >= -tol_s).all()),
    "tangential stick: w_tau = 0": (tstick.w_tau_norm <= tol_w).all(),
    "|w_tau| is the norm of w_tau": np.allclose(np.linalg.norm(w_tau, axis=1), later.w_tau_norm, atol=tol_w),
}
# on slipping nodes sigma_tau = -F(|w_tau|) w_tau/|w_tau|: antiparallel to w_tau
moving = (later.tangential_branch == 1).to_numpy() & (later.w_tau_norm > 1e3 * tol_w).to_numpy()
dots = np.einsum("ij,ij->i", w_tau[moving], s_tau[moving])
norms = later.w_tau_norm.to_numpy()[moving] * later.sigma_tau_norm.to_numpy()[moving]
checks["slip: sigma_tau antiparallel to w_tau"] = np.allclose(dots, -norms, atol=1e-6 * max(norms.max(initial=0), 1e-300))
# the friction law itself: |sigma_tau| is the law's force F(|w_tau|) on
# slipping nodes and inside the disk of radius F_b on sticking ones
if "friction_response" in later.columns:
    slipping = later[moving]
    checks["slip: |sigma_tau| = friction law's F(|w_tau|)"] = np.allclose(
        slipping.sigma_tau_norm, slipping.friction_response, rtol=1e-6, atol=tol_s)
    checks["stick: |sigma_tau| <= friction_bound"] = (
        tstick.sigma_tau_norm <= tstick.friction_bound * (1 + 1e-6) + tol_s).all()
elif len(slip):
    checks["stick: |sigma_tau| <= max slip |sigma_tau|"] = (
        tstick.sigma_tau_norm <= slip.sigma_tau_norm.max() * (1 + 1e-6) + tol_s).all()
for name, ok in checks.items():
    print(f"{'ok ' if ok else 'FAIL'} {name}")
print(f"(node, time) pairs: separating {len(sep)}, normal stick {len(nstick)}, damped {len(damped)}, "
      + (f"at a breakpoint {len(held)}, at the wall {len(wall)}, " if len(held) + len(wall) else "")
      + f"stick {len(tstick)}, slip {len(slip)}")
assert all(checks.values()), "a contact condition is violated in the contact CSV files" """),
("markdown", """## Along Γ3 at a few times

The abscissa is the coordinate along which Γ3 extends most; in 3D the
nodes on the line through the middle of Γ3 in the other direction are
shown. The tangential quantities are the components along that abscissa."""),
("code", """first = data[data.step == data.step.min()]
spread = {c: first[c].max() - first[c].min() for c in xyz}
along = max(spread, key=spread.get)
line = data
for c in xyz:
    if c != along and spread[c] > 1e-12 * max(spread.values()):
        values = np.sort(first[c].unique())
        middle = values[np.argmin(np.abs(values - np.median(values)))]
        line = line[np.isclose(line[c], middle)]
        print(f"3D: the nodes with {c} = {middle:g}")

requested = os.environ.get("HEMICONTACT_TIMES")
if requested:
    wanted = [float(t) for t in requested.split(",")]
else:
    wanted = [times[-1] * q for q in (0.25, 0.5, 0.75, 1.0)]
chosen = sorted({min(times, key=lambda t: abs(t - w)) for w in wanted})
print("times:", ", ".join(f"{t:g}" for t in chosen))

panels = [("w_nu", "normal velocity $w_\\\\nu$"),
          ("minus_sigma_nu", "normal traction $-\\\\sigma_\\\\nu$"),
          (f"w_tau_{along}", f"slip velocity $w_{{\\\\tau,{along}}}$"),
          (f"sigma_tau_{along}", f"tangential traction $\\\\sigma_{{\\\\tau,{along}}}$")]
line = line.assign(minus_sigma_nu=-line.sigma_nu)
fig, axes = plt.subplots(len(panels), 1, figsize=(6.5, 8.5), sharex=True)
for t in chosen:
    snap = line[np.isclose(line.time, t)].sort_values(along)
    for ax, (column, label) in zip(axes, panels):
        ax.plot(snap[along], snap[column], marker=".", ms=4, label=f"t = {t:g}")
for ax, (column, label) in zip(axes, panels):
    ax.set_ylabel(label)
    ax.grid(True, lw=0.3)
axes[0].set_title(f"{tag}: contact boundary", fontsize=10)
axes[0].legend(fontsize=8, ncol=len(chosen))
axes[-1].set_xlabel(along)
fig.tight_layout()
fig.savefig(figures / f"{tag}-contact-profiles.png", dpi=110)
plt.close(fig)"""),
("markdown", """## Branches over space and time

Each column is one contact node (along the abscissa), each row one output
time after the initial one (the initial state has no branches yet)."""),
("code", """from matplotlib.colors import ListedColormap, BoundaryNorm
steps_sorted = sorted(line[line.time > 0].step.unique())
positions = np.sort(line[line.step == steps_sorted[0]][along].to_numpy())
def edges(v):
    mid = 0.5 * (v[1:] + v[:-1])
    return np.concatenate([[v[0] - (mid[0] - v[0])], mid, [v[-1] + (v[-1] - mid[-1])]])
t_values = np.array([line[line.step == s].time.iloc[0] for s in steps_sorted])
fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(9, 4), sharey=True)
for ax, column, names, colors in [
        (ax1, "normal_branch",
         ["separating", "normal stick", "damped", "at a breakpoint", "at the wall"][:max(3, int(line.normal_branch.max()) + 1)],
         ["#4c72b0", "#dd8452", "#55a868", "#937860", "#222222"][:max(3, int(line.normal_branch.max()) + 1)]),
        (ax2, "tangential_branch", ["stick", "slip"], ["#c44e52", "#8172b3"])]:
    grid = np.array([line[line.step == s].sort_values(along)[column].to_numpy() for s in steps_sorted])
    cmap = ListedColormap(colors)
    norm = BoundaryNorm(np.arange(len(names) + 1) - 0.5, len(names))
    mesh = ax.pcolormesh(edges(positions), edges(t_values) if len(t_values) > 1 else [0, 1], grid,
                         cmap=cmap, norm=norm, shading="flat")
    bar = fig.colorbar(mesh, ax=ax, ticks=range(len(names)), orientation="horizontal", pad=0.15)
    bar.ax.set_xticklabels(names, fontsize=8)
    ax.set_xlabel(along)
    ax.set_title(column.replace("_", " "), fontsize=10)
ax1.set_ylabel("t")
fig.suptitle(f"{tag}: contact branches on Γ3", fontsize=10)
fig.tight_layout()
fig.savefig(figures / f"{tag}-contact-branches.png", dpi=110)
plt.close(fig)
print(sorted(p.name for p in figures.glob(f"{tag}-contact-*.png")))"""),
]

write_notebook(cells, "contact_boundary")
