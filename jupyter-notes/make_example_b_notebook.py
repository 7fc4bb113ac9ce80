"""Writes example_b.ipynb (kept as plain Python here so diffs stay readable).

    /usr/bin/python3 jupyter-notes/make_example_b_notebook.py
"""
from notebook_writer import write_notebook

cells = [
("markdown", """# Example B: penalised compliance converging to the Signorini condition

`prm/example_b_penalised.prm` is Example B of Bartman-Szwarc, Ochal,
Sofonea & Tarzia: a static elastic body on a polygon, clamped on x = 0,
loaded by its weight and resting with the segment y = 0, 0.8 ≤ x ≤ 1.2
on a foundation with the penalised normal compliance λ⁻¹ j(u_ν)
(`penalised softening compliance`, a = b = 0.1) and Tresca friction
F_b = 1 (`doc/examples.md`, section 9). As λ⁻¹ → ∞ the compliance
becomes the Signorini condition u_ν ≤ 0 (the normal law `signorini`).

This notebook runs the program itself: the shipped file with the penalty
λ⁻¹ = 2^{i/2}, i = 0 … 47, and the limit, each a static problem (one load
value). It reads the displacement in double precision
(`nodal_00001.h5`), computes ‖u^λ − u^∞‖ in L²(Ω) and the H¹ seminorm
|u^λ − u^∞|₁ on the Q1 mesh (2×2 Gauss points per cell, exact for Q1),
plots both against λ⁻¹ on log–log axes with the rate of a least-squares
fit of the last points, and draws the deformed body at
λ⁻¹ ∈ {1, 1024, 2048, 5931641, ∞}. If the program has no normal law
`signorini`, the limit is extrapolated from the two largest penalties
(2 u^λ(2^{23.5}) − u^λ(2^{22.5}), exact up to O(λ²) on the linear branch
of the law) and these two are left out of the fit; the notebook says
which limit it used.

Run from the repository root (about two and a half minutes on one core):

    jupyter nbconvert --to notebook --execute --output-dir /tmp jupyter-notes/example_b.ipynb

Environment: `HEMICONTACT_EXE` (default `build/hemicontact`),
`HEMICONTACT_EXAMPLE_B_REFINEMENTS` (global refinements of the committed
mesh of size 1/16; default 1, the paper's 1/32; the test suite runs 0),
`HEMICONTACT_EXAMPLE_B_STRIDE` (run every stride-th i, default 1; the
test suite runs 2), `HEMICONTACT_RUN` (the directory for the runs, default
`output-example-b-sequence`), `HEMICONTACT_OUTPUT_ROOT=dir` (figures to
`dir/doc/figures/`)."""),
("code", """import os, pathlib, subprocess, time
import numpy as np
import pandas as pd
import h5py
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection

root = pathlib.Path.cwd()
if not (root / "prm").exists():
    root = root.parent
exe = pathlib.Path(os.environ.get("HEMICONTACT_EXE", "build/hemicontact"))
if not exe.is_absolute():
    exe = root / exe
refinements = int(os.environ.get("HEMICONTACT_EXAMPLE_B_REFINEMENTS", "1"))
stride = int(os.environ.get("HEMICONTACT_EXAMPLE_B_STRIDE", "1"))
runs = pathlib.Path(os.environ.get("HEMICONTACT_RUN", "output-example-b-sequence"))
if not runs.is_absolute():
    runs = root / runs
out_root = pathlib.Path(os.environ.get("HEMICONTACT_OUTPUT_ROOT", root))
figures = out_root / "doc" / "figures"
figures.mkdir(parents=True, exist_ok=True)
runs.mkdir(parents=True, exist_ok=True)
assert exe.exists(), f"no executable {exe}: build hemicontact first"
shipped = (root / "prm" / "example_b_penalised.prm").read_text()
mesh = root / "prm" / "gmsh" / "example_b_polygon.msh"
reference = subprocess.run([exe, "--print-parameters"], capture_output=True, text=True).stdout
has_signorini = "subsection signorini" in reference
print(f"{exe}: normal law 'signorini' {'available' if has_signorini else 'NOT available'}; "
      f"mesh {mesh.name} with {refinements} global refinement(s); every {stride}. penalty")"""),
("markdown", """## The runs

Each run is the shipped file with second subsections appended (the
parameter reader applies the last value): the mesh file, the global
refinements, the output directory and the normal law. `steps.csv` gives
Newton's iterations, the branch counts and the relative defect of
Clapeyron's identity (doc/theory.md section 9.4)."""),
("code", """def run(name, law_text):
    directory = runs / name
    text = shipped + f\"\"\"
subsection geometry
  set mesh file          = {mesh}
  set global refinements = {refinements}
end
subsection output
  set directory       = {directory}
  set terminal        = quiet
  set timing summary  = false
end
subsection normal law
{law_text}
end
\"\"\"
    prm = runs / f"{name}.prm"
    prm.write_text(text)
    done = subprocess.run([exe, prm], capture_output=True, text=True, cwd=root)
    assert done.returncode == 0, f"{name} failed (exit {done.returncode}):\\n{done.stderr}"
    steps = pd.read_csv(directory / "steps.csv")
    with h5py.File(directory / "nodal_00001.h5") as f:
        nodes, cells, u = f["nodes"][:], f["cells"][:], f["displacement"][:]
    contact = pd.read_csv(directory / "contact_00001.csv")
    return dict(steps=steps, nodes=nodes, cells=cells, u=u, contact=contact)

# every stride-th i, and always the penalties drawn below and the largest
exponents = sorted(set(range(0, 48, stride)) | {0, 20, 22, 45, 47})
penalties = {i: 2 ** (i / 2) for i in exponents}
start = time.time()
results = {}
for i, penalty in penalties.items():
    results[i] = run(f"penalty-{i:02d}", f\"\"\"  set law = penalised softening compliance
  subsection penalised softening compliance
    set penalty = {penalty!r}
  end\"\"\")
if has_signorini:
    limit = run("signorini", \"\"\"  set law = signorini
  subsection signorini
    set penetration limit = 0
  end\"\"\")
    limit_name = "Signorini (the law 'signorini')"
    fitted = exponents
else:
    # stand-in: on the linear branch u^lambda = u^inf + c/lambda^-1 + O(lambda^2), so the two
    # largest penalties 2^22.5 and 2^23.5 (a factor 2) extrapolate to 2 u(2^23.5) - u(2^22.5)
    limit = dict(results[47], u=2 * results[47]["u"] - results[45]["u"])
    limit_name = "2 u(2^23.5) - u(2^22.5), extrapolated from the two largest penalties (no law 'signorini')"
    fitted = [i for i in exponents if i not in (45, 47)]
print(f"{len(results) + has_signorini} runs in {time.time() - start:.0f} s; the limit u^inf: {limit_name}")

table = pd.DataFrame(dict(
    i=exponents, penalty=[penalties[i] for i in exponents],
    newton=[results[i]["steps"].newton_iterations.iloc[-1] for i in exponents],
    max_penetration=[results[i]["contact"].u_nu.max() for i in exponents],
    max_pressure=[(-results[i]["contact"].sigma_nu).max() for i in exponents],
    compliant=[results[i]["steps"].n_damped.iloc[-1] for i in exponents],
    slip=[results[i]["steps"].n_slip.iloc[-1] for i in exponents],
    defect=[results[i]["steps"].relative_energy_defect.abs().max() for i in exponents]))
print(table.to_string(index=False, float_format=lambda v: f"{v:.4g}"))
assert (table.defect < 1e-6).all(), "Clapeyron's identity is violated"
if has_signorini:
    wall = limit["contact"]
    at_wall = wall.normal_branch == 4
    print(f"limit: Newton {limit['steps'].newton_iterations.iloc[-1]}, {at_wall.sum()} of {len(wall)} nodes "
          f"at the wall, max u_nu {wall.u_nu.max():.3g}, wall pressure in "
          f"[{wall.wall_pressure.min():.4g}, {wall.wall_pressure.max():.4g}], "
          f"relative defect {limit['steps'].relative_energy_defect.abs().max():.1e}")
    assert wall.u_nu.max() <= 1e-12, "the Signorini limit penetrates"
    assert (wall.wall_pressure >= -1e-8).all() and (wall.wall_pressure[~at_wall].abs() <= 1e-8).all()
    assert limit["steps"].relative_energy_defect.abs().max() < 1e-6
for r in list(results.values()) + [limit]:
    assert np.array_equal(r["nodes"], limit["nodes"]) and np.array_equal(r["cells"], limit["cells"])"""),
("markdown", """## ‖u^λ − u^∞‖ against λ⁻¹

Norms on the Q1 mesh: for each quadrilateral (vertices counterclockwise,
the XDMF order of `nodal_00001.h5`) the bilinear map from [0,1]², 2×2
Gauss points. The rate is the slope of a least-squares line through
(log λ⁻¹, log ‖·‖) over the last ten penalties of the fit."""),
("code", """def norms(d, nodes, cells):
    g = np.array([0.5 - 0.5 / np.sqrt(3), 0.5 + 0.5 / np.sqrt(3)])
    X, D = nodes[cells], d[cells]                      # (cells, 4, 2)
    l2, h1 = 0.0, 0.0
    for s in g:
        for t in g:
            N = np.array([(1 - s) * (1 - t), s * (1 - t), s * t, (1 - s) * t])
            dN = np.array([[-(1 - t), -(1 - s)], [1 - t, -s], [t, s], [-t, 1 - s]])
            J = np.einsum("cka,kb->cab", X, dN)         # dx_a/dxi_b
            det = J[:, 0, 0] * J[:, 1, 1] - J[:, 0, 1] * J[:, 1, 0]
            assert (det > 0).all()
            grad = np.einsum("cka,kb,cbe->cae", D, dN, np.linalg.inv(J))
            value = np.einsum("k,cka->ca", N, D)
            l2 += 0.25 * np.sum(det * np.sum(value**2, axis=1))
            h1 += 0.25 * np.sum(det * np.sum(grad**2, axis=(1, 2)))
    return np.sqrt(l2), np.sqrt(h1)

nodes, cells = limit["nodes"], limit["cells"]
area = norms(np.ones_like(nodes), nodes, cells)[0] ** 2 / 2
print(f"area of the polygon on the mesh: {area:.6f} (exact 0.88)")
assert abs(area - 0.88) < 1e-12
u_inf_l2, u_inf_h1 = norms(limit["u"], nodes, cells)
errors = np.array([norms(results[i]["u"] - limit["u"], nodes, cells) for i in fitted])
lam = np.array([penalties[i] for i in fitted])
table_err = pd.DataFrame(dict(penalty=lam, L2=errors[:, 0], H1_seminorm=errors[:, 1],
                              L2_relative=errors[:, 0] / u_inf_l2))
print(f"|u^inf|: L2 {u_inf_l2:.5g}, H1 seminorm {u_inf_h1:.5g}")
print(table_err.to_string(index=False, float_format=lambda v: f"{v:.4g}"))

last = slice(-10, None)
rate_l2 = -np.polyfit(np.log(lam[last]), np.log(errors[last, 0]), 1)[0]
rate_h1 = -np.polyfit(np.log(lam[last]), np.log(errors[last, 1]), 1)[0]
print(f"observed rate over lambda^-1 in [{lam[last][0]:.4g}, {lam[last][-1]:.4g}]: "
      f"L2 {rate_l2:.3f}, H1 seminorm {rate_h1:.3f}")
jump = np.argmax(errors[:-1, 0] / errors[1:, 0])
print(f"largest drop of the L2 error between lambda^-1 = {lam[jump]:.4g} and {lam[jump + 1]:.4g}: "
      f"{errors[jump, 0]:.3g} -> {errors[jump + 1, 0]:.3g}")
tail = errors[jump + 1:, 0]
assert (np.diff(tail) < 0).all(), "the error does not decrease beyond the drop"
assert rate_l2 > 0.8, "the error does not decrease like 1/penalty"

fig, ax = plt.subplots(figsize=(6.4, 4.6))
ax.loglog(lam, errors[:, 0], "o-", ms=3, label=r"$\\|u^\\lambda - u^\\infty\\|_{L^2(\\Omega)}$")
ax.loglog(lam, errors[:, 1], "s-", ms=3, label=r"$|u^\\lambda - u^\\infty|_{H^1(\\Omega)}$")
ref = errors[last, 0][0] * (lam[last][0] / lam[last]) ** 1
ax.loglog(lam[last], ref * 0.5, "k--", lw=0.8, label="slope −1")
ax.set_xlabel(r"$\\lambda^{-1}$")
ax.set_ylabel("error")
ax.set_title(f"Example B: limit {'Signorini' if has_signorini else 'extrapolated from the largest penalties'}; "
             f"fitted rate L2 {rate_l2:.2f}, H1 {rate_h1:.2f}", fontsize=9)
ax.grid(True, which="both", lw=0.3)
ax.legend(fontsize=8)
fig.savefig(figures / "example-b-convergence.png", dpi=110, bbox_inches="tight")
plt.close(fig)"""),
("markdown", """## The deformed shapes

The body at x + u(x) (the displacement as computed, not magnified),
coloured by |u|, at the penalties of the paper's figure and the limit;
the foundation is the line y = 0, the undeformed outline is dashed."""),
("code", """outline = np.array([(0, 0.2), (0.2, 0.4), (0.6, 0.4), (0.8, 0.2), (0.8, 0), (1.2, 0), (1.2, 1.2),
                    (0.8, 1.2), (0.8, 1), (0.6, 0.8), (0.2, 0.8), (0, 1), (0, 0.2)])
shown = [(0, "1"), (20, "1024"), (22, "2048"), (45, "5931641")]
panels = [(results[i]["u"], rf"$\\lambda^{{-1}} = {label}$", results[i]["contact"]) for i, label in shown]
panels.append((limit["u"], r"$\\lambda^{-1} = \\infty$" if has_signorini else
               r"$\\lambda^{-1} = \\infty$ (extrapolated)", limit["contact"]))
on_contact = nodes[:, 1] == 0                       # the segment y = 0, normal (0, -1)
vmax = max(np.linalg.norm(u, axis=1).max() for u, _, _ in panels)
low = np.min([(nodes + u).min(axis=0) for u, _, _ in panels], axis=0)
high = np.max([(nodes + u).max(axis=0) for u, _, _ in panels], axis=0)
fig, axes = plt.subplots(1, len(panels), figsize=(3.1 * len(panels), 4.4), sharey=True)
for ax, (u, title, contact) in zip(axes, panels):
    moved = nodes + u
    polys = PolyCollection(moved[cells], array=np.linalg.norm(u[cells], axis=2).mean(axis=1),
                           cmap="viridis", clim=(0, vmax), edgecolors="face", linewidths=0.2)
    ax.add_collection(polys)
    ax.plot(outline[:, 0], outline[:, 1], "k--", lw=0.6)
    ax.axhline(0, color="0.3", lw=1.2)
    ax.set_xlim(min(low[0], 0) - 0.05, max(high[0], 1.2) + 0.05)
    ax.set_ylim(min(low[1], 0) - 0.05, max(high[1], 1.2) + 0.05)
    ax.set_aspect("equal")
    ax.set_title(title + f"\\nmax $u_\\\\nu$ = {(-u[on_contact, 1]).max() + 0.0:.2g}", fontsize=9)
    ax.set_xlabel("x")
axes[0].set_ylabel("y")
fig.colorbar(polys, ax=axes, shrink=0.8, label="|u|")
fig.savefig(figures / "example-b-shapes.png", dpi=110, bbox_inches="tight")
plt.close(fig)
print(sorted(p.name for p in figures.glob("example-b-*.png")))"""),
]

write_notebook(cells, "example_b")
