#!/usr/bin/python3
"""Read deal.II's 2D VTU output and compare Q1 fields exactly on a fine grid.

deal.II writes every cell as a patch of its own four vertices (lexicographic
order); meshio reads the file. A Q1 field of a
mesh that refines the same coarse mesh of axis-parallel rectangles is
bilinear on every cell of any finer uniform grid of that mesh, so its values
at the fine grid's vertices represent it exactly there: the L2 and H1
norms of a difference are then computed exactly, cell by cell, with the Q1
mass and stiffness matrices.
"""
import meshio
import numpy as np


def read_vtu(path):
    """Points (n x 3) and the named point data arrays of one VTU piece
    (read with meshio; deal.II writes every field as point data)."""
    mesh = meshio.read(path)
    arrays = dict(mesh.point_data)
    arrays["points"] = mesh.points
    return arrays


def fine_grid_values(arrays, field, lower, upper, n_cells):
    """The 2D Q1 field @p field (first two components) at the vertices of the
    uniform grid of n_cells = (nx, ny) cells on [lower, upper]:
    an array (ny + 1, nx + 1, 2)."""
    points = arrays["points"].reshape(-1, 4, 3)[:, :, :2].astype(np.float64)
    values = arrays[field].reshape(-1, 4, arrays[field].shape[-1])[:, :, :2]
    nx, ny = n_cells
    hx = (upper[0] - lower[0]) / nx
    hy = (upper[1] - lower[1]) / ny
    grid = np.zeros((ny + 1, nx + 1, 2))
    for p, v in zip(points, values.astype(np.float64)):
        i0, i1 = (np.rint((p[[0, 1], 0] - lower[0]) / hx)).astype(int)
        j0, j1 = (np.rint((p[[0, 2], 1] - lower[1]) / hy)).astype(int)
        s = np.linspace(0, 1, i1 - i0 + 1)[None, :, None]
        t = np.linspace(0, 1, j1 - j0 + 1)[:, None, None]
        grid[j0:j1 + 1, i0:i1 + 1] = ((1 - s) * (1 - t) * v[0] + s * (1 - t) * v[1]
                                      + (1 - s) * t * v[2] + s * t * v[3])
    return grid


def l2_and_h1_norms(grid, lower, upper):
    """Exact L2 norm and H1 seminorm of the Q1 field with these vertex values."""
    ny, nx = grid.shape[0] - 1, grid.shape[1] - 1
    hx = (upper[0] - lower[0]) / nx
    hy = (upper[1] - lower[1]) / ny
    a, b = grid[:-1, :-1], grid[:-1, 1:]
    c, d = grid[1:, :-1], grid[1:, 1:]
    mass = (4 * (a * a + b * b + c * c + d * d)
            + 4 * (a * b + a * c + b * d + c * d) + 2 * (a * d + b * c)) / 36
    p, q = b - a, d - c
    r, s = c - a, d - b
    stiffness = (hy / hx * (p * p + p * q + q * q)
                 + hx / hy * (r * r + r * s + s * s)) / 3
    return np.sqrt(hx * hy * mass.sum()), np.sqrt(stiffness.sum())
