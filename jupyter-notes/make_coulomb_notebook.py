"""Writes coulomb.ipynb (kept as plain Python here so diffs stay readable).

    /usr/bin/python3 jupyter-notes/make_coulomb_notebook.py
"""
from notebook_writer import write_notebook

cells = [
("markdown", """# Coulomb friction: the block pressed and dragged

`prm/coulomb_block_2d.prm` is a static-class block [0,4]×[0,1], held on
its left side, pressed onto a normal-compliance foundation
(−σ_ν = 200 u_ν₊) by a pressure on its top that rises to the right and
dragged to the right by a shear S t that grows with the load parameter t.
The friction bound is Coulomb's, F_b = μ (−σ_ν)₊ with μ = 0.3, written
`mu*pos(p_nu)`; every load value is solved with fixed-point iterations
on the bound (`doc/theory.md`, section 9.9).

This notebook reads the run's `steps.csv` and every `contact_NNNNN.csv`,
prints the numbers `doc/examples.md` quotes, checks that every load value
satisfies Coulomb's law at every contact node (F_b = μ p with
p = −σ_ν, |σ_τ| = μ p where the node slips, |σ_τ| ≤ μ p where it sticks)
and draws the pressure, |σ_τ| against μ p and the stick and slip zones
along the contact boundary.

Run from the repository root:

    ./build/hemicontact prm/coulomb_block_2d.prm
    jupyter nbconvert --to notebook --execute --output-dir /tmp jupyter-notes/coulomb.ipynb

`HEMICONTACT_RUN=dir` reads another output directory (relative paths from
the repository root; default `output-coulomb-block-2d`), and
`HEMICONTACT_OUTPUT_ROOT=dir` writes the figure to `dir/doc/figures/`."""),
("code", """import os, pathlib, re
import numpy as np
import pandas as pd
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

MU = 0.3
root = pathlib.Path.cwd()
if not (root / "prm").exists():
    root = root.parent
run = pathlib.Path(os.environ.get("HEMICONTACT_RUN", "output-coulomb-block-2d"))
if not run.is_absolute():
    run = root / run
out_root = pathlib.Path(os.environ.get("HEMICONTACT_OUTPUT_ROOT", root))
figures = out_root / "doc" / "figures"
figures.mkdir(parents=True, exist_ok=True)
assert (run / "steps.csv").exists(), f"no {run}/steps.csv: run prm/coulomb_block_2d.prm first"
steps = pd.read_csv(run / "steps.csv")
files = sorted(run.glob("contact_*.csv"), key=lambda f: int(re.search(r"(\\d+)", f.name).group(1)))
contact = {int(re.search(r"(\\d+)", f.name).group(1)): pd.read_csv(f) for f in files}
print(f"{run}: {len(steps)} load values, {steps.n_cells.iloc[-1]} cells, {steps.n_dofs.iloc[-1]} dofs, "
      f"{len(contact[0])} contact nodes")"""),
("markdown", """## The load values

Newton iterations (over all fixed-point iterations of the load value),
fixed-point iterations on the bound and the stick and slip counts."""),
("code", """print(steps[["step", "time", "newton_iterations", "bound_iterations", "n_stick", "n_slip"]].to_string(index=False))
print(f"bound iterations per load value: {steps.bound_iterations.min()} to {steps.bound_iterations.max()} "
      f"(total {steps.bound_iterations.sum()}); Newton iterations in all: {steps.newton_iterations.sum()}")
assert (steps.bound_iterations >= 2).all(), "a load value without the fixed point"
assert steps.relative_energy_defect.abs().max() < 1e-6, "Clapeyron's identity is violated" """),
("markdown", """## Coulomb's law at every node

With p = (−σ_ν)₊ of the same load value (the fixed point): the bound used
is μ p, and |σ_τ| equals it where the node slips and does not exceed it
where the node sticks; the tolerance is 10⁻⁶ of the largest bound."""),
("code", """worst_bound = worst_slip = worst_stick = 0.0
for n, c in contact.items():
    if n == 0:
        continue
    p = np.maximum(-c.sigma_nu, 0)
    scale = max((MU * p).max(), 1e-12)
    slip = c.tangential_branch == 1
    worst_bound = max(worst_bound, (c.friction_bound - MU * p).abs().max() / scale)
    if slip.any():
        worst_slip = max(worst_slip, (c.sigma_tau_norm[slip] - MU * p[slip]).abs().max() / scale)
    if (~slip).any():
        worst_stick = max(worst_stick, (c.sigma_tau_norm[~slip] - MU * p[~slip]).max() / scale)
print(f"largest |F_b - mu p| {worst_bound:.1e}, slip: largest ||sigma_tau| - mu p| {worst_slip:.1e}, "
      f"stick: largest |sigma_tau| - mu p {worst_stick:.1e} (relative to the largest bound)")
assert worst_bound < 1e-6 and worst_slip < 1e-6 and worst_stick < 1e-6, "Coulomb's law is violated" """),
("markdown", """## Along the contact boundary

Left: the pressure −σ_ν at three load values. Middle: |σ_τ| (markers:
filled where the node slips, open where it sticks) against μ p (lines).
Right: the stick (light) and slip (dark) zones along the boundary at
every load value."""),
("code", """shown = [n for n in (3, 8, 10) if n in contact]
fig, axes = plt.subplots(1, 3, figsize=(13, 3.8))
colours = plt.cm.viridis(np.linspace(0, 0.85, len(shown)))
for n, colour in zip(shown, colours):
    c = contact[n]
    t = c.time.iloc[0]
    p = -c.sigma_nu
    slip = c.tangential_branch == 1
    axes[0].plot(c.x, p, color=colour, label=f"t = {t:g}")
    axes[1].plot(c.x, MU * np.maximum(p, 0), color=colour, lw=1, label=f"$\\\\mu p$, t = {t:g}")
    axes[1].plot(c.x[slip], c.sigma_tau_norm[slip], "o", ms=3.5, color=colour)
    axes[1].plot(c.x[~slip], c.sigma_tau_norm[~slip], "o", ms=3.5, mfc="none", color=colour)
axes[0].set_xlabel("x"); axes[0].set_ylabel("pressure $-\\\\sigma_\\\\nu$"); axes[0].legend(fontsize=8)
axes[1].set_xlabel("x"); axes[1].set_ylabel("$|\\\\sigma_\\\\tau|$ (o) and $\\\\mu p$ (lines)"); axes[1].legend(fontsize=8)
loads = [n for n in sorted(contact) if n > 0]
x = contact[loads[0]].x.to_numpy()
zones = np.array([contact[n].tangential_branch.to_numpy() for n in loads])
times = [contact[n].time.iloc[0] for n in loads]
dx, dt = x[1] - x[0], times[1] - times[0]
axes[2].imshow(zones, aspect="auto", origin="lower", cmap="Greys", vmin=-0.6, vmax=1.3,
               extent=[x[0] - dx / 2, x[-1] + dx / 2, times[0] - dt / 2, times[-1] + dt / 2])
axes[2].set_xlabel("x"); axes[2].set_ylabel("load parameter t")
axes[2].set_title("stick (light), slip (dark)", fontsize=10)
fig.tight_layout()
fig.savefig(figures / "coulomb-block-2d.png", dpi=110, bbox_inches="tight")
plt.close(fig)
for n in loads:
    c = contact[n]
    s = c.x[c.tangential_branch == 1]
    print(f"t = {c.time.iloc[0]:g}: {len(s)} of {len(c)} nodes slip; pressure {(-c.sigma_nu).min():.3g} to "
          f"{(-c.sigma_nu).max():.3g}; stick on x in "
          f"[{c.x[c.tangential_branch == 0].min():.3g}, {c.x[c.tangential_branch == 0].max():.3g}]")
print(sorted(p.name for p in figures.glob("coulomb-*.png")))"""),
]

write_notebook(cells, "coulomb")
