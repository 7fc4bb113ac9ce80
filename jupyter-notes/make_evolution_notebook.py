"""Writes evolution.ipynb (kept as plain Python here so diffs stay readable).

    /usr/bin/python3 jupyter-notes/make_evolution_notebook.py
"""
from notebook_writer import write_notebook

cells = [
("markdown", """# Evolution of a run: contact branches, energies, Newton iterations

Reads `steps.csv` of one hemicontact run (one row per time step) and plots
over time: how many contact nodes are in each branch (normal: separating,
normal stick, damped; tangential: stick, slip), the energies and the
cumulative dissipations of the discrete energy identity (`doc/outputs.md`,
"Energy diagnostics"), and the Newton iterations per step. It fails if the run's
energy identity is violated (relative defect above 1e-6).

Run from the repository root after running the example:

    ./build/hemicontact prm/block_2d.prm
    jupyter nbconvert --to notebook --execute --output-dir /tmp jupyter-notes/evolution.ipynb

`HEMICONTACT_RUN=dir` reads another output directory (relative paths are
taken from the repository root; default `output-block-2d`), and
`HEMICONTACT_OUTPUT_ROOT=dir` writes the figures to `dir/doc/figures/`
instead of `doc/figures/`. Figure names start with the run directory's
name without `output-` (e.g. `block-2d-evolution-branches.png`)."""),
("code", """import os, pathlib
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
assert (run / "steps.csv").exists(), f"no {run}/steps.csv: run the example first"
steps = pd.read_csv(run / "steps.csv")
assert len(steps) > 0, "steps.csv has no rows"
print(f"{run}: {len(steps)} steps, t = {steps.time.iloc[0]:g} .. {steps.time.iloc[-1]:g}, "
      f"{steps.n_cells.iloc[-1]} cells, {steps.n_dofs.iloc[-1]} dofs")"""),
("markdown", """## Contact branches

Each contact node is in one normal branch (separating: moving away from
the foundation, no normal traction; normal stick: w_ν = 0 with −σ_ν in
[0, a]; damped: moving into the foundation against the response ∂j_ν(w_ν))
and one tangential branch (stick: w_τ = 0, |σ_τ| ≤ F_b; slip: σ_τ = −F_b w_τ/|w_τ|)."""),
("code", """n_nodes = (steps.n_separating + steps.n_normal_stick + steps.n_damped).iloc[0]
assert ((steps.n_separating + steps.n_normal_stick + steps.n_damped) == n_nodes).all()
assert ((steps.n_stick + steps.n_slip) == n_nodes).all()
fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(6.5, 5), sharex=True)
ax1.plot(steps.time, steps.n_separating, label="separating")
ax1.plot(steps.time, steps.n_normal_stick, label="normal stick")
ax1.plot(steps.time, steps.n_damped, label="damped")
ax1.set_ylabel("nodes")
ax1.set_title(f"{tag}: normal branches ({n_nodes} contact nodes)", fontsize=10)
ax1.legend(fontsize=8)
ax2.plot(steps.time, steps.n_stick, label="stick")
ax2.plot(steps.time, steps.n_slip, label="slip")
ax2.set_ylabel("nodes")
ax2.set_xlabel("t")
ax2.set_title("tangential branches", fontsize=10)
ax2.legend(fontsize=8)
for ax in (ax1, ax2):
    ax.grid(True, lw=0.3)
fig.tight_layout()
fig.savefig(figures / f"{tag}-evolution-branches.png", dpi=110)
plt.close(fig)
for name in ["n_separating", "n_normal_stick", "n_damped", "n_stick", "n_slip"]:
    active = steps.time[steps[name] > 0]
    span = f"t in [{active.min():g}, {active.max():g}]" if len(active) else "never"
    print(f"{name:15s} max {steps[name].max():4d}  occurs {span}")"""),
("markdown", """## Energies and dissipation

E_n = ρ/2 |w_n|² + ½ a_B(u_{n+1}, u_{n+1}) (kinetic + elastic). Summed over the
steps, the discrete identity reads
E_n − E_0 + viscous + friction + normal damping + numerical dissipation
= external work; `energy_defect` is what is left over."""),
("code", """energy = steps.kinetic_energy + steps.elastic_energy
fig, (ax1, ax2) = plt.subplots(2, 1, figsize=(6.5, 6), sharex=True)
ax1.plot(steps.time, steps.kinetic_energy, label="kinetic")
ax1.plot(steps.time, steps.elastic_energy, label="elastic")
ax1.plot(steps.time, energy, "k", label="kinetic + elastic")
ax1.set_ylabel("energy")
ax1.set_title(f"{tag}: energies", fontsize=10)
ax1.legend(fontsize=8)
for column, label in [("external_work", "external work"),
                      ("viscous_dissipation", "viscous dissipation"),
                      ("friction_dissipation", "friction dissipation"),
                      ("normal_damping_dissipation", "normal damping dissipation"),
                      ("numerical_dissipation", "numerical dissipation")]:
    ax2.plot(steps.time, steps[column], label=label)
ax2.set_ylabel("cumulative")
ax2.set_xlabel("t")
ax2.set_title("work and dissipation (cumulative)", fontsize=10)
ax2.legend(fontsize=8)
for ax in (ax1, ax2):
    ax.grid(True, lw=0.3)
fig.tight_layout()
fig.savefig(figures / f"{tag}-evolution-energies.png", dpi=110)
plt.close(fig)
last = steps.iloc[-1]
for column in ["kinetic_energy", "elastic_energy", "external_work", "viscous_dissipation",
               "friction_dissipation", "normal_damping_dissipation", "numerical_dissipation"]:
    print(f"{column:28s} at t = {last.time:g}: {last[column]: .4e}")
print(f"max relative energy defect: {steps.relative_energy_defect.max():.2e}")
assert steps.relative_energy_defect.max() < 1e-6, "the discrete energy identity is violated"
for column in ["viscous_dissipation", "friction_dissipation", "normal_damping_dissipation"]:
    assert (np.diff(steps[column]) >= -1e-12 * max(1.0, steps[column].abs().max())).all(), \\
        f"{column} decreases: a dissipation must not"
"""),
("markdown", "## Solver effort"),
("code", """fig, ax = plt.subplots(figsize=(6.5, 2.8))
ax.step(steps.time, steps.newton_iterations, where="mid", label="Newton iterations")
ax.step(steps.time, steps.line_search_reductions, where="mid", label="line-search reductions")
ax.set_xlabel("t")
ax.set_title(f"{tag}: nonlinear iterations per step (max residual {steps.residual.max():.1e})", fontsize=10)
ax.legend(fontsize=8)
ax.grid(True, lw=0.3)
fig.tight_layout()
fig.savefig(figures / f"{tag}-evolution-newton.png", dpi=110)
plt.close(fig)
print(f"Newton iterations per step: mean {steps.newton_iterations.mean():.2f}, max {steps.newton_iterations.max()}")
print(sorted(p.name for p in figures.glob(f"{tag}-evolution-*.png")))"""),
]

write_notebook(cells, "evolution")
