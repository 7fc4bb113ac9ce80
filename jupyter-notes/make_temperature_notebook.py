"""Writes temperature.ipynb (kept as plain Python here so diffs stay readable).

    /usr/bin/python3 jupyter-notes/make_temperature_notebook.py
"""
from notebook_writer import write_notebook

cells = [
("markdown", """# Temperature: Example E and frictional heating

Two runs of the thermo-viscoelastic model (doc/theory.md, section 13;
`doc/examples.md`, sections 14 and 15):

- `prm/example_e_temperature.prm`, Example E (the conmech code's
  temperature example): a free body squeezed from both sides, pulled onto a
  damped foundation by its weight, θ_0 = 0.25, insulated, c_e = 0.5. The
  compression heats it through the heat equation's −c_e div w.
- `prm/frictional_heating_2d.prm`: a free block pressed onto a foundation
  with a wall and dragged over it against Tresca friction; half of the
  frictional power enters the block, the foundation at θ_F = 0 takes heat
  back with k_e = 0.5.

The notebook reads the solution pieces (θ is the point field
`temperature`) and the contact CSV files (`temperature`,
`exchanged_heat`, `frictional_heat`); it fails unless Example E is
symmetric about x = 1.25 and warmer than θ_0 everywhere, the contact
CSV's heat terms are the contact heat law's (γ|σ_τ||w_τ|, k_e(θ_F − θ)),
and the block's heat content equals the heat that entered through Γ3.

Run from the repository root:

    ./build/hemicontact prm/example_e_temperature.prm
    ./build/hemicontact prm/frictional_heating_2d.prm
    jupyter nbconvert --to notebook --execute --output-dir /tmp jupyter-notes/temperature.ipynb

`HEMICONTACT_EXAMPLE_E_RUN=dir` and `HEMICONTACT_HEATING_RUN=dir` read
other output directories (relative paths from the repository root;
defaults `output-example-e`, `output-frictional-heating`), and
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
example_e = run_directory("HEMICONTACT_EXAMPLE_E_RUN", "output-example-e")
heating = run_directory("HEMICONTACT_HEATING_RUN", "output-frictional-heating")
out_root = pathlib.Path(os.environ.get("HEMICONTACT_OUTPUT_ROOT", root))
figures = out_root / "doc" / "figures"
figures.mkdir(parents=True, exist_ok=True)
for run in (example_e, heating):
    assert (run / "steps.csv").exists(), f"no {run}/steps.csv: run the two parameter files first"

def written_steps(run):
    \"\"\"The steps with a solution file, from solution.pvd.\"\"\"
    return sorted(int(m) for m in re.findall(r"solution_(\\d+)\\.pvtu", (run / "solution.pvd").read_text()))

def solution(run, step):
    \"\"\"Points, quadrilaterals and point data of all pieces of a step.\"\"\"
    points, quads, data = [], [], {}
    offset = 0
    for piece in sorted(run.glob(f"solution_{step:05d}.*.vtu")):
        mesh = meshio.read(piece)
        points.append(mesh.points[:, :2].astype(float))
        quads.append(mesh.cells_dict["quad"] + offset)
        offset += len(mesh.points)
        for name, values in mesh.point_data.items():
            data.setdefault(name, []).append(np.asarray(values, dtype=float))
    return np.vstack(points), np.vstack(quads), {k: np.concatenate(v) for k, v in data.items()}

def contact(run, step):
    return pd.read_csv(run / f"contact_{step:05d}.csv")"""),
("markdown", """## Example E

θ at the last step: its range, and the symmetry of the problem about
x = 1.25 (θ at (x, y) against θ at (2.5 − x, y), matched by position).
Every point has warmed above θ_0 = 0.25: the body is compressed
everywhere, most where the side tractions squeeze it."""),
("code", """steps_e = written_steps(example_e)
s = pd.read_csv(example_e / "steps.csv")
print(f"Example E: {len(s)} steps, t = {s.time.iloc[-1]:g}, {s.n_cells.iloc[-1]} cells; "
      f"largest relative energy defect {s.relative_energy_defect.abs().max():.1e}")
assert s.relative_energy_defect.abs().max() < 1e-6
points, quads, data = solution(example_e, steps_e[-1])
theta = data["temperature"].ravel()
hottest, coldest = theta.argmax(), theta.argmin()
print(f"theta at t = {s.time.iloc[-1]:g}: {theta.min():.4f} at {points[coldest]} to {theta.max():.4f} at {points[hottest]}")
assert theta.min() > 0.25, "a point cooled below theta_0"
key = {tuple(np.round(p, 6)): t for p, t in zip(points, theta)}
mirror = max(abs(t - key[(round(2.5 - p[0], 6), round(p[1], 6))]) for p, t in zip(points, theta))
print(f"largest |theta(x, y) - theta(2.5 - x, y)|: {mirror:.1e}")
assert mirror < 1e-5 * theta.max(), "Example E is not symmetric about x = 1.25"

fig, axes = plt.subplots(1, 3, figsize=(15, 3.2))
shown = [steps_e[len(steps_e) // 4], steps_e[len(steps_e) // 2], steps_e[-1]]
for ax, step in zip(axes, shown):
    points, quads, data = solution(example_e, step)
    triangles = np.vstack([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    xy = points + data["displacement"][:, :2]
    image = ax.tripcolor(mtri.Triangulation(xy[:, 0], xy[:, 1], triangles), data["temperature"].ravel(),
                         shading="gouraud", cmap="inferno", vmin=0.25, vmax=0.41)
    ax.set_aspect("equal")
    ax.set_title(f"t = {s.time[s.step == step].iloc[0]:g}", fontsize=10)
fig.colorbar(image, ax=axes, shrink=0.8, label="theta")
fig.savefig(figures / "example-e-temperature.png", dpi=100, bbox_inches="tight")
plt.close(fig)"""),
("markdown", """## Frictional heating

In every contact CSV file the heat terms are the contact heat law's: the
frictional heat γ|σ_τ·w_τ| = 0.5 |σ_τ| |w_τ| (σ_τ opposes the slip) and
the exchanged heat k_e (θ_F − θ) = −0.5 θ. Then the balance: the heat
content ∫ c_θ θ of the block (c_θ = 1; the bilinear θ integrated exactly
on the rectangular cells) gained since t = 0 equals the heat that entered
through Γ3, Σ_n k Σ_i m_i (frictional + exchanged), when a contact file
was written at every step (`vtu interval = 1`; the reduced run of the test
suite), up to the single precision of the solution files."""),
("code", """steps_h = written_steps(heating)
s = pd.read_csv(heating / "steps.csv")
print(f"frictional heating: {len(s)} steps, t = {s.time.iloc[-1]:g}; "
      f"largest relative energy defect {s.relative_energy_defect.abs().max():.1e}")
for step in steps_h:
    c = contact(heating, step)
    power = 0.5 * c.sigma_tau_norm * c.w_tau_norm
    assert np.allclose(c.frictional_heat, power, rtol=1e-8, atol=1e-12), f"step {step}: frictional heat"
    assert np.allclose(c.exchanged_heat, -0.5 * c.temperature, rtol=1e-8, atol=1e-12), f"step {step}: exchange"

def heat_content(step):
    points, quads, data = solution(heating, step)
    theta = data["temperature"].ravel()
    corners = points[quads]
    area = np.abs((corners[:, 2, 0] - corners[:, 0, 0]) * (corners[:, 2, 1] - corners[:, 0, 1]))
    return float((area * theta[quads].mean(axis=1)).sum())

gained = heat_content(steps_h[-1]) - heat_content(0)
if steps_h == list(range(len(s) + 1)):
    k = s.time.diff().fillna(s.time.iloc[0]).to_numpy()
    entered = sum(k[n - 1] * (contact(heating, n).eval("mass * (frictional_heat + exchanged_heat)").sum())
                  for n in steps_h[1:])
    print(f"heat content gained {gained:.6g}, heat entered through Gamma_3 {entered:.6g}, "
          f"relative difference {abs(gained - entered) / entered:.1e}")
    assert abs(gained - entered) < 1e-5 * entered, "the heat booked does not close"
else:
    print(f"heat content gained {gained:.6g} (contact files not at every step: the balance is not checked)")

last = contact(heating, steps_h[-1])
points, quads, data = solution(heating, steps_h[-1])
theta = data["temperature"].ravel()
bottom, top = np.abs(points[:, 1]) < 1e-9, np.abs(points[:, 1] - 0.5) < 1e-9
print(f"theta at t = {s.time.iloc[-1]:g}: mean {theta[bottom].mean():.4f} on the contact, "
      f"{theta[top].mean():.4f} on the top")
assert theta[bottom].mean() > 5 * theta[top].mean(), "the heat is not under the contact zone"

fig, (left, right) = plt.subplots(1, 2, figsize=(13, 3.2), gridspec_kw={"width_ratios": [1.6, 1]})
triangles = np.vstack([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
xy = points + data["displacement"][:, :2] - [data["displacement"][:, 0].mean(), 0]
image = left.tripcolor(mtri.Triangulation(xy[:, 0], xy[:, 1], triangles), theta, shading="gouraud", cmap="inferno")
left.set_aspect("equal")
left.set_title(f"theta at t = {s.time.iloc[-1]:g} (block shifted back by its mean slip)", fontsize=10)
fig.colorbar(image, ax=left, shrink=0.8, label="theta")
history = pd.DataFrame([{"t": contact(heating, n).time.iloc[0],
                         "theta": contact(heating, n).temperature.mean(),
                         "frictional": contact(heating, n).eval("mass * frictional_heat").sum(),
                         "exchanged": contact(heating, n).eval("mass * exchanged_heat").sum()} for n in steps_h])
right.plot(history.t, history.theta, label="mean theta on the contact")
right.plot(history.t, history.frictional, label="frictional heat entering")
right.plot(history.t, history.exchanged, label="heat exchanged (< 0: to the foundation)")
right.axhline(0, color="0.5", lw=0.6)
right.set_xlabel("t")
right.legend(fontsize=8)
fig.savefig(figures / "frictional-heating.png", dpi=100, bbox_inches="tight")
plt.close(fig)
print(sorted(p.name for p in figures.glob("*heat*.png")) + sorted(p.name for p in figures.glob("example-e-*.png")))"""),
]

write_notebook(cells, "temperature")
