"""Writes piezoelectricity.ipynb (kept as plain Python here so diffs stay readable).

    /usr/bin/python3 jupyter-notes/make_piezoelectricity_notebook.py
"""
from notebook_writer import write_notebook

cells = [
("markdown", """# Piezoelectricity: a sensor pressed onto a conductive foundation

`prm/piezo_sensor_2d.prm` (doc/theory.md, section 14; `doc/examples.md`,
section 16): a piezoelectric layer clamped at x = 0, its top a grounded
electrode pressed down by a growing and falling traction, its bottom on a
foundation at φ_F = 0 whose conductance 50 pos(u_ν) passes current only
where the layer presses in.

The notebook reads steps.csv and the contact CSV files (`electric_potential`,
`conductance`, `current`); it fails unless the energy identity with the
electric terms closes, the contact CSV's current is the electric contact
law's p_e (φ − φ_F) at every node, and current passes only where the
conductance is positive. It draws the potential on Γ3 and the current
through the contact zone over time.

Run from the repository root:

    ./build/hemicontact prm/piezo_sensor_2d.prm
    jupyter nbconvert --to notebook --execute --output-dir /tmp jupyter-notes/piezoelectricity.ipynb

`HEMICONTACT_PIEZO_RUN=dir` reads another output directory (relative
paths from the repository root; default `output-piezo-sensor-2d`), and
`HEMICONTACT_OUTPUT_ROOT=dir` writes the figure to `dir/doc/figures/`."""),
("code", """import os, pathlib
import pandas as pd
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

root = pathlib.Path.cwd()
if not (root / "prm").exists():
    root = root.parent
run = pathlib.Path(os.environ.get("HEMICONTACT_PIEZO_RUN", "output-piezo-sensor-2d"))
run = run if run.is_absolute() else root / run
out_root = pathlib.Path(os.environ.get("HEMICONTACT_OUTPUT_ROOT", root))
figures = out_root / "doc" / "figures"
figures.mkdir(parents=True, exist_ok=True)
assert (run / "steps.csv").exists(), f"no {run}/steps.csv: run prm/piezo_sensor_2d.prm first"
s = pd.read_csv(run / "steps.csv")
print(f"{len(s)} steps, t = {s.time.iloc[-1]:g}; largest relative energy defect "
      f"{s.relative_energy_defect.abs().max():.1e}")
assert s.relative_energy_defect.abs().max() < 1e-9, "the energy identity with the electric terms does not close"
print("electric terms at the end:", {c: s[c].iloc[-1] for c in
      ["electric_cross_energy", "electric_enthalpy", "electric_supply", "electric_stress_work"]})"""),
("markdown", """## The electric contact law at the nodes

At every node of every contact file, `current` = `conductance` ×
(`electric_potential` − φ_F) with φ_F = 0, and zero where the conductance is
zero (the layer not in contact). The current through the contact zone is
Σ_i m_i p_e (φ − φ_F)_i."""),
("code", """files = sorted(run.glob("contact_*.csv"))
history = []
for f in files:
    c = pd.read_csv(f)
    law = (c.current - c.conductance * c.electric_potential).abs().max()
    # the CSV holds 10 significant digits
    assert law < 1e-8 * c.current.abs().max() + 1e-15, f"{f.name}: current is not p_e (phi - phi_F)"
    assert (c.current[c.conductance == 0] == 0).all(), f"{f.name}: current without contact"
    history.append({"t": c.time.iloc[0], "current": (c.mass * c.current).sum(),
                    "in contact": int((c.conductance > 0).sum()),
                    "largest |phi| on Gamma_3": c.electric_potential.abs().max()})
history = pd.DataFrame(history)
print(history.to_string(index=False))
assert history.current.abs().max() > 0, "no current passed"

last = pd.read_csv(files[len(files) // 2])
fig, (left, right) = plt.subplots(1, 2, figsize=(12, 3.2))
left.plot(last.x, last.electric_potential, "o-", ms=3)
left.set_xlabel("x on Gamma_3")
left.set_ylabel("phi")
left.set_title(f"potential on the contact at t = {last.time.iloc[0]:g}", fontsize=10)
right.plot(history.t, history.current, "o-", ms=3)
right.axhline(0, color="0.5", lw=0.6)
right.set_xlabel("t")
right.set_ylabel("sum m_i p_e (phi - phi_F)")
right.set_title("current through the contact zone", fontsize=10)
fig.savefig(figures / "piezo-sensor.png", dpi=100, bbox_inches="tight")
plt.close(fig)
print(sorted(p.name for p in figures.glob("piezo*.png")))"""),
]

write_notebook(cells, "piezoelectricity")
