#!/usr/bin/python3
"""How much could any h-adaptive mesh gain for w on the 2D example?

An estimate from the error maps of the uniform runs of
bench/adaptivity_study.py (run it first): at t = 0.3, 0.5, 0.7, 0.9 the
error of w of uniform r5 and r6 against the r8 reference, cell by cell of
the r5/r6 mesh (exact Q1 norms on the reference grid, bench/vtu_fields.py).
If a cell c with the squared error e_c is split into n_c cells, its squared
error becomes e_c / n_c (H1 seminorm, error ~ h) or e_c / n_c^2 (L2,
error ~ h^2). The n_c that give the uniform error with the fewest cells
(n_c ~ sqrt(e_c) for H1, n_c ~ e_c^(1/3) for L2) need this fraction of the
uniform cells:

    H1: (sum sqrt(e_c))^2 / (N sum e_c)
    L2: (sum e_c^(1/3))^(3/2) / (N sqrt(sum e_c))

per time (a mesh made for that time, moved without transfer errors) and for
the mean of the four squared error maps (one mesh for all four times, as a
run without coarsening ends with). The estimate is optimistic: it assumes
the asymptotic rates in every cell (not at the corners), no 2:1 balance and
no errors carried from earlier steps.

  /usr/bin/python3 bench/adaptivity_oracle.py
"""
import os

import numpy as np

import vtu_fields

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
WORK = os.path.join(ROOT, "bench", "work", "adaptivity")
TIMES = [0.3, 0.5, 0.7, 0.9]
LOWER, UPPER = (0., 0.), (4., 1.)
REFERENCE = 8


def cell_errors(grid):
    """Squared L2 norm and H1 seminorm of the Q1 field per reference cell."""
    ny, nx = grid.shape[0] - 1, grid.shape[1] - 1
    hx, hy = (UPPER[0] - LOWER[0]) / nx, (UPPER[1] - LOWER[1]) / ny
    a, b = grid[:-1, :-1], grid[:-1, 1:]
    c, d = grid[1:, :-1], grid[1:, 1:]
    mass = hx * hy * (4 * (a * a + b * b + c * c + d * d) + 4 * (
        a * b + a * c + b * d + c * d) + 2 * (a * d + b * c)) / 36
    p, q, r, s = b - a, d - c, c - a, d - b
    stiffness = (hy / hx * (p * p + p * q + q * q) +
                 hx / hy * (r * r + r * s + s * s)) / 3
    return mass.sum(axis=2), stiffness.sum(axis=2)


def main():
    n_cells = (4 * 2 ** REFERENCE, 2 ** REFERENCE)
    vtu = lambda name, t: os.path.join(
        WORK, name, "solution_%05d.0.vtu" % round(t / 0.01))
    references = {t: vtu_fields.fine_grid_values(
        vtu_fields.read_vtu(vtu("reference-r%d" % REFERENCE, t)), "velocity",
        LOWER, UPPER, n_cells) for t in TIMES}
    print("| uniform mesh | norm | " + " | ".join("t = %g" % t for t in TIMES)
          + " | one mesh for all four |")
    print("|---|---|" + "---|" * (len(TIMES) + 1))
    for level in (5, 6):
        f = 2 ** (REFERENCE - level)
        maps = {"L2": [], "H1": []}
        for t in TIMES:
            grid = vtu_fields.fine_grid_values(
                vtu_fields.read_vtu(vtu("uniform-r%d" % level, t)),
                "velocity", LOWER, UPPER, n_cells)
            for norm, e in zip(("L2", "H1"), cell_errors(grid - references[t])):
                ny, nx = e.shape
                maps[norm].append(
                    e.reshape(ny // f, f, nx // f, f).sum(axis=(1, 3)).ravel())
        for norm, fraction in (
                ("H1", lambda e: np.sqrt(e).sum() ** 2 / (e.size * e.sum())),
                ("L2", lambda e: np.cbrt(e).sum() ** 1.5 /
                 (e.size * np.sqrt(e.sum())))):
            values = [fraction(e) for e in maps[norm]]
            values.append(fraction(np.mean(maps[norm], axis=0)))
            print("| r%d | %s | " % (level, norm) +
                  " | ".join("%.2f" % v for v in values) + " |")


if __name__ == "__main__":
    main()
