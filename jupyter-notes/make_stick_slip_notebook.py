"""Writes stick_slip.ipynb (kept as plain Python here so diffs stay readable).

    /usr/bin/python3 jupyter-notes/make_stick_slip_notebook.py
"""
from notebook_writer import write_notebook

cells = [
("markdown", """# Stick-slip under rate-weakening friction

`prm/stick_slip_rate_weakening.prm` and `prm/stick_slip_tresca.prm` are
identical except the friction law on Γ3: a block clamped on its left side,
pressed onto the foundation by a constant pressure and dragged on its right
side by a traction that grows linearly in time. Under the slip-rate
weakening law F(s) = F_b (μ_d + (μ_s − μ_d) e^{−s/v0})/μ_s friction drops
once the block slips, the block overshoots and sticks again: the contact
line goes through repeated stick-slip cycles. Under Tresca friction
(F = F_b at every slip speed) the same loading gives steady sliding.

This notebook reads both runs' `steps.csv`, `probes.csv` (the bottom right
corner, every step) and `contact_*.csv` and plots the slip speed and the
friction force over time, and the friction force against slip speed (the
law itself, as the program realised it). It fails unless the rate-weakening
run sticks completely at least three times after sliding has started, the
Tresca run never does, the realised friction force is the law's value on
slipping nodes, and the energy identity holds in both runs.

Run from the repository root:

    ./build/hemicontact prm/stick_slip_rate_weakening.prm
    ./build/hemicontact prm/stick_slip_tresca.prm
    jupyter nbconvert --to notebook --execute --output-dir /tmp jupyter-notes/stick_slip.ipynb

`HEMICONTACT_WEAKENING_RUN=dir` and `HEMICONTACT_TRESCA_RUN=dir` read other
output directories (relative paths from the repository root; defaults
`output-stick-slip-rate-weakening`, `output-stick-slip-tresca`), and
`HEMICONTACT_OUTPUT_ROOT=dir` writes the figures to `dir/doc/figures/`."""),
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
    p = pathlib.Path(os.environ.get(variable, default))
    return p if p.is_absolute() else root / p
runs = {"rate weakening": run_dir("HEMICONTACT_WEAKENING_RUN", "output-stick-slip-rate-weakening"),
        "Tresca": run_dir("HEMICONTACT_TRESCA_RUN", "output-stick-slip-tresca")}
out_root = pathlib.Path(os.environ.get("HEMICONTACT_OUTPUT_ROOT", root))
figures = out_root / "doc" / "figures"
figures.mkdir(parents=True, exist_ok=True)
colors = {"rate weakening": "#c44e52", "Tresca": "#4c72b0"}

steps, probes, contact = {}, {}, {}
for law, run in runs.items():
    assert (run / "steps.csv").exists(), f"no {run}/steps.csv: run the stick_slip .prm files first"
    steps[law] = pd.read_csv(run / "steps.csv")
    probes[law] = pd.read_csv(run / "probes.csv")
    files = sorted(run.glob("contact_*.csv"))
    assert len(files) >= 10, f"fewer than ten contact_*.csv in {run}"
    contact[law] = pd.concat([pd.read_csv(f).assign(step=int(re.search(r"contact_(\\d+)\\.csv", f.name).group(1)))
                              for f in files], ignore_index=True)
    print(f"{law:15s} {run}: {len(steps[law])} steps, {len(files)} contact files")
assert np.allclose(steps["rate weakening"].time, steps["Tresca"].time), "the two runs have different time steps" """),
("markdown", """## Stick and slip of the whole contact line

A complete stick is a step with no slipping node (`n_slip = 0`). Counted
after the first step in which every node slips (sliding has started)."""),
("code", """stick_episodes = {}
for law, s in steps.items():
    all_stick = (s.n_slip == 0).to_numpy()
    started = np.argmax((s.n_stick == 0).to_numpy())
    assert (s.n_stick.iloc[started] == 0), f"{law}: the contact line never slips as a whole"
    after = all_stick[started:]
    stick_episodes[law] = int(np.sum(after[1:] & ~after[:-1]))
    print(f"{law:15s} sliding starts at t = {s.time.iloc[started]:.3f}; "
          f"complete sticks after that: {stick_episodes[law]}; "
          f"max relative energy defect {s.relative_energy_defect.abs().max():.1e}")
    assert s.relative_energy_defect.abs().max() < 1e-6, f"{law}: the discrete energy identity is violated"
assert stick_episodes["rate weakening"] >= 3, "rate weakening: no stick-slip cycles"
assert stick_episodes["Tresca"] == 0, "Tresca: the block sticks again after sliding started" """),
("markdown", """## Slip speed and friction force over time

Top: the slip speed |w_τ| at the bottom right corner (`probes.csv`, every
step). Bottom: the friction force |σ_τ| at the same node (`contact_*.csv`,
every output step) and the static bound F_b."""),
("code", """fig, axes = plt.subplots(2, 1, figsize=(7, 5.2), sharex=True)
for law in runs:
    p = probes[law]
    corner = p[p.point == 0]
    axes[0].plot(corner.time, np.abs(corner.w_x), color=colors[law], lw=1, label=law)
    c = contact[law]
    node = c[np.isclose(c.x, c.x.max())].sort_values("time")
    axes[1].plot(node.time, node.sigma_tau_norm, color=colors[law], lw=1, label=law)
axes[1].plot(node.time, node.friction_bound, "k--", lw=0.8, label="static bound $F_b$")
axes[0].set_ylabel("slip speed $|w_\\\\tau|$ at x = 2")
axes[1].set_ylabel("friction force $|\\\\sigma_\\\\tau|$ at x = 2")
axes[1].set_xlabel("t")
for ax in axes:
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(figures / "stick-slip-evolution.png", dpi=110)
plt.close(fig)"""),
("markdown", """## The law as realised

Every slipping node at every output time is one point (|w_τ|, |σ_τ|); the
line is the law's friction force F(s) the program reports in the
`friction_response` column. Sticking nodes lie on the vertical axis, below
F_b."""),
("code", """fig, ax = plt.subplots(figsize=(5.5, 3.8))
for law, c in contact.items():
    slip = c[(c.tangential_branch == 1) & (c.time > 0)]
    assert len(slip) > 20, f"{law}: too few slipping nodes"
    deviation = np.abs(slip.sigma_tau_norm - slip.friction_response).max()
    print(f"{law:15s} slipping node-times {len(slip)}, slip speeds up to {slip.w_tau_norm.max():.3f}, "
          f"friction force in [{slip.sigma_tau_norm.min():.3f}, {slip.sigma_tau_norm.max():.3f}], "
          f"max | |sigma_tau| - F(s) | = {deviation:.1e}")
    assert deviation < 1e-6 * max(1.0, slip.friction_bound.max()), f"{law}: the friction force is not the law's"
    ax.plot(slip.w_tau_norm, slip.sigma_tau_norm, ".", ms=3, color=colors[law], label=f"{law} (slipping nodes)")
    order = slip.sort_values("w_tau_norm")
    ax.plot(order.w_tau_norm, order.friction_response, "-", lw=0.8, color=colors[law])
ax.set_xscale("symlog", linthresh=1e-3)
ax.set_xlabel("slip speed $|w_\\\\tau|$")
ax.set_ylabel("friction force $|\\\\sigma_\\\\tau|$")
ax.grid(True, lw=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(figures / "stick-slip-law.png", dpi=110)
plt.close(fig)
print(sorted(p.name for p in figures.glob("stick-slip-*.png")))"""),
]

write_notebook(cells, "stick_slip")
