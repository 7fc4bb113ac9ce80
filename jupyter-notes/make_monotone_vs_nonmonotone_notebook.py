"""Writes monotone_vs_nonmonotone.ipynb (kept as plain Python here so diffs stay readable).

    /usr/bin/python3 jupyter-notes/make_monotone_vs_nonmonotone_notebook.py
"""
from notebook_writer import write_notebook

cells = [
("markdown", """# Monotone vs nonmonotone normal law

`prm/compare_law_monotone.prm` and `prm/compare_law_nonmonotone.prm` are
identical except the normal law on Γ3. Both have the threshold a = 1 (the
convex jump ∂j_ν(0) = [0, 1]); beyond it, the monotone law's response rises
to 1.5 (piecewise linear, reached at w_ν = 0.1) while the nonmonotone
exponential law's response drops to b = 0.5 (β = 10). This notebook reads
both runs' `steps.csv` and `contact_*.csv` and compares the response
−σ_ν against w_ν actually realised at the damped nodes, normal velocity and
traction along Γ3, the size of the damped zone, and the energies.
It fails unless the realised response rises with w_ν in the monotone run
and falls in the nonmonotone one.

Run from the repository root after running both files:

    ./build/hemicontact prm/compare_law_monotone.prm
    ./build/hemicontact prm/compare_law_nonmonotone.prm
    jupyter nbconvert --to notebook --execute --output-dir /tmp jupyter-notes/monotone_vs_nonmonotone.ipynb

`HEMICONTACT_MONOTONE_RUN=dir` and `HEMICONTACT_NONMONOTONE_RUN=dir` read
other output directories (relative paths from the repository root;
defaults `output-compare-monotone`, `output-compare-nonmonotone`),
`HEMICONTACT_TIMES=0.2,0.4` chooses the profile times, and
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
runs = {"monotone": run_dir("HEMICONTACT_MONOTONE_RUN", "output-compare-monotone"),
        "nonmonotone": run_dir("HEMICONTACT_NONMONOTONE_RUN", "output-compare-nonmonotone")}
out_root = pathlib.Path(os.environ.get("HEMICONTACT_OUTPUT_ROOT", root))
figures = out_root / "doc" / "figures"
figures.mkdir(parents=True, exist_ok=True)
colors = {"monotone": "#4c72b0", "nonmonotone": "#c44e52"}

steps, contact = {}, {}
for law, run in runs.items():
    assert (run / "steps.csv").exists(), f"no {run}/steps.csv: run prm/compare_law_{law}.prm first"
    steps[law] = pd.read_csv(run / "steps.csv")
    files = sorted(run.glob("contact_*.csv"))
    assert len(files) >= 2, f"fewer than two contact_*.csv in {run}"
    frames = []
    for f in files:
        df = pd.read_csv(f)
        df["step"] = int(re.search(r"contact_(\\d+)\\.csv", f.name).group(1))
        frames.append(df)
    contact[law] = pd.concat(frames, ignore_index=True)
    print(f"{law:12s} {run}: {len(steps[law])} steps, {len(files)} contact files")
assert list(steps["monotone"].time) == list(steps["nonmonotone"].time), "the two runs have different time steps"
assert "z" not in contact["monotone"].columns, "this comparison plots a 2D contact line" """),
("markdown", """## The response the foundation actually gave

Every damped node at every output time is one point (w_ν, −σ_ν): the
points trace the graph of ∂j_ν for w_ν > 0."""),
("code", """fig, ax = plt.subplots(figsize=(5.5, 3.8))
trend = {}
for law, df in contact.items():
    d = df[(df.normal_branch == 2) & (df.time > 0)].sort_values("w_nu")
    assert len(d) > 10, f"{law}: too few damped nodes to compare"
    ax.plot(d.w_nu, -d.sigma_nu, ".", ms=3, color=colors[law], label=f"{law} ({len(d)} node-times)")
    # the realised response, as a function of w_nu, must rise (monotone) or fall (nonmonotone)
    steps_up = np.diff(-d.sigma_nu.to_numpy())
    trend[law] = (steps_up.min(), steps_up.max())
    print(f"{law:12s} w_nu in [{d.w_nu.min():.3g}, {d.w_nu.max():.3g}], "
          f"-sigma_nu in [{(-d.sigma_nu).min():.4f}, {(-d.sigma_nu).max():.4f}]")
ax.set_xlabel("$w_\\\\nu$ (damped nodes)")
ax.set_ylabel("$-\\\\sigma_\\\\nu$")
ax.set_title("realised normal response", fontsize=10)
ax.grid(True, lw=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(figures / "compare-law-response.png", dpi=110)
plt.close(fig)
assert trend["monotone"][0] > -1e-6, "the monotone run's response decreases somewhere"
assert trend["nonmonotone"][1] < 1e-6, "the nonmonotone run's response increases somewhere" """),
("markdown", """## Along Γ3 at a few times"""),
("code", """times = sorted(contact["monotone"].time.unique())
requested = os.environ.get("HEMICONTACT_TIMES")
wanted = [float(t) for t in requested.split(",")] if requested else [times[-1] * q for q in (0.2, 0.4, 0.6)]
chosen = sorted({min(times, key=lambda t: abs(t - w)) for w in wanted})
print("times:", ", ".join(f"{t:g}" for t in chosen))
fig, axes = plt.subplots(2, len(chosen), figsize=(3.2 * len(chosen), 5.2), sharex=True, sharey="row", squeeze=False)
for j, t in enumerate(chosen):
    for law, df in contact.items():
        snap = df[np.isclose(df.time, t)].sort_values("x")
        axes[0, j].plot(snap.x, snap.w_nu, color=colors[law], label=law)
        axes[1, j].plot(snap.x, -snap.sigma_nu, color=colors[law], label=law)
    axes[0, j].set_title(f"t = {t:g}", fontsize=10)
    axes[1, j].set_xlabel("x")
    for i in range(2):
        axes[i, j].grid(True, lw=0.3)
axes[0, 0].set_ylabel("$w_\\\\nu$")
axes[1, 0].set_ylabel("$-\\\\sigma_\\\\nu$")
axes[0, 0].legend(fontsize=8)
fig.tight_layout()
fig.savefig(figures / "compare-law-profiles.png", dpi=110)
plt.close(fig)"""),
("markdown", """## Damped zone and energies

The damped zone's size is Σ m_i over the damped nodes (its length on Γ3),
at each output time; `steps.csv` gives the number of damped nodes at every
step."""),
("code", """fig, axes = plt.subplots(2, 2, figsize=(9, 6.2))
for law in runs:
    s, df = steps[law], contact[law]
    zone = df[df.normal_branch == 2].groupby("time").mass.sum().reindex(sorted(df.time.unique()), fill_value=0)
    axes[0, 0].plot(zone.index, zone.values, "o-", ms=3, color=colors[law], label=law)
    axes[0, 1].plot(s.time, s.n_damped, color=colors[law], label=f"{law}: damped")
    axes[0, 1].plot(s.time, s.n_separating, "--", color=colors[law], label=f"{law}: separating")
    axes[1, 0].plot(s.time, s.kinetic_energy + s.elastic_energy, color=colors[law], label=f"{law}: kinetic + elastic")
    axes[1, 0].plot(s.time, s.external_work, ":", color=colors[law], label=f"{law}: external work")
    axes[1, 1].plot(s.time, s.normal_damping_dissipation, color=colors[law], label=f"{law}: normal damping")
    axes[1, 1].plot(s.time, s.friction_dissipation, "--", color=colors[law], label=f"{law}: friction")
    print(f"{law:12s} max damped length {zone.max():.3f}; at t = 1: kinetic+elastic "
          f"{(s.kinetic_energy + s.elastic_energy).iloc[-1]:.4f}, external work {s.external_work.iloc[-1]:.4f}, "
          f"normal damping {s.normal_damping_dissipation.iloc[-1]:.4f}, friction {s.friction_dissipation.iloc[-1]:.4f}, "
          f"max relative energy defect {s.relative_energy_defect.max():.1e}")
    assert s.relative_energy_defect.max() < 1e-6, f"{law}: the discrete energy identity is violated"
axes[0, 0].set_title("damped zone: length $\\\\sum m_i$", fontsize=10)
axes[0, 1].set_title("nodes per branch", fontsize=10)
axes[1, 0].set_title("energy and work", fontsize=10)
axes[1, 1].set_title("contact dissipation (cumulative)", fontsize=10)
for ax in axes.flat:
    ax.set_xlabel("t")
    ax.grid(True, lw=0.3)
    ax.legend(fontsize=7)
fig.tight_layout()
fig.savefig(figures / "compare-law-evolution.png", dpi=110)
plt.close(fig)
print(sorted(p.name for p in figures.glob("compare-law-*.png")))"""),
]

write_notebook(cells, "monotone_vs_nonmonotone")
