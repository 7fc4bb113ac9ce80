#!/usr/bin/python3
"""plot_body.py RUN_DIR OUTPUT.png [NAME ...]: the pictures of the body in
results.md, from the files body-NAME.csv that step-5 writes in RUN_DIR
(each cell's four vertices in counterclockwise order with their
displacement u and, at a contact node, its normal and tangential branch;
-1 elsewhere). NAME is the number of a load value of the block (t = 0.25
NAME) and defaults to 04, the full load. This is step-1's script with
step-5's branches: a normal "stick" node touches the wall.
Each panel shows the mesh deformed by s*u, with s = 1, 2 or 5 times a
power of ten chosen so that the panel's largest displacement is drawn as
at most 0.3, but never below 1 (the panel names s),
the undeformed outline in grey, the foundation below y = 0, and the contact
nodes coloured by normal branch (separating, stick, penetrating) and
marked by tangential branch (dot: stick, triangle: slip).
Needs matplotlib (Debian: python3-matplotlib)."""
import math
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
from matplotlib.collections import PolyCollection
import numpy as np

NORMAL = {0: ("separating (u_nu < 0)", "0.55"),
          1: ("on the wall (u_nu = 0)", "tab:blue"),
          2: ("penetrating (never)", "tab:red")}
TANGENTIAL = {0: ("o", "stick"), 1: ("^", "slip")}


def read_body(run_dir, name):
    """The rows of body-NAME.csv as a structured array."""
    return np.genfromtxt(f"{run_dir}/body-{name}.csv", delimiter=",",
                         names=True)


def nice_scale(body, drawn=0.3):
    """1, 2 or 5 times a power of ten, the largest with which the largest
    displacement of the body is drawn at most as long as drawn; 1 if the
    displacement is that long already (a body is never drawn shrunk)."""
    largest = np.hypot(body["u_x"], body["u_y"]).max()
    if largest <= 0 or largest >= drawn:
        return 1.0
    target = drawn / largest
    power = 10.0 ** math.floor(math.log10(target))
    return max(m * power for m in (1, 2, 5) if m * power <= target)


def draw_body(ax, body, scale, title):
    """One panel: the deformed mesh, the outline before, the branches."""
    x = body["x"] + scale * body["u_x"]
    y = body["y"] + scale * body["u_y"]
    cells = np.stack([x, y], axis=1).reshape(-1, 4, 2)
    before = np.stack([body["x"], body["y"]], axis=1).reshape(-1, 4, 2)
    ax.add_collection(PolyCollection(before, facecolors="none",
                                     edgecolors="0.8", linewidths=0.4))
    ax.add_collection(PolyCollection(cells, facecolors="#dbe6f2",
                                     edgecolors="k", linewidths=0.4))
    left, right = body["x"].min(), body["x"].max()
    bottom = min(y.min(), 0.0)
    ax.axhspan(bottom - 0.3, 0, color="#efe3c8", zorder=0)
    ax.axhline(0, color="#a08040", lw=0.8, zorder=0)
    contact = body["normal_branch"] >= 0
    seen = set()
    for i in np.flatnonzero(contact):
        key = (int(body["normal_branch"][i]), int(body["tangential_branch"][i]))
        if (x[i], y[i]) in seen:
            continue
        seen.add((x[i], y[i]))
        label, colour = NORMAL[key[0]]
        marker, slip = TANGENTIAL[key[1]]
        ax.plot(x[i], y[i], marker, color=colour, ms=4.5, zorder=3)
    ax.set_xlim(left - 0.1, right + 0.1)
    ax.set_ylim(bottom - 0.25, max(y.max(), body["y"].max()) + 0.15)
    ax.set_aspect("equal")
    ax.set_xticks([])
    ax.set_yticks([])
    ax.set_title(title + (f" (displacement x {scale:g})" if scale != 1
                          else " (true scale)"), fontsize=9)


def legend(fig):
    """The branches' colours and markers, once for the whole figure."""
    handles = [plt.Line2D([], [], ls="", marker="o", color=c, label=l)
               for l, c in NORMAL.values()]
    handles += [plt.Line2D([], [], ls="", marker=m, color="k",
                           label=f"tangential {l}")
                for m, l in TANGENTIAL.values()]
    fig.legend(handles=handles, loc="lower center", ncol=5, fontsize=8,
               frameon=False)


def save(fig, output, dpi=90):
    """Save the figure as a PNG of at most 128 colours, which keeps the
    picture of a fine mesh small (matplotlib needs Pillow, so it is there)."""
    import io
    from PIL import Image
    buffer = io.BytesIO()
    fig.savefig(buffer, dpi=dpi, format="png")
    buffer.seek(0)
    image = Image.open(buffer).convert("RGB")
    image.quantize(colors=128).save(output, optimize=True)


def main():
    run_dir, output = sys.argv[1], sys.argv[2]
    names = sys.argv[3:] or ["04"]
    bodies = [read_body(run_dir, name) for name in names]
    rows = (len(bodies) + 1) // 2
    fig, axes = plt.subplots(rows, 2 if len(bodies) > 1 else 1,
                             figsize=(10, 1.9 * rows + 0.5), squeeze=False)
    for ax, name, body in zip(axes.flat, names, bodies):
        title = f"t = {0.25 * int(name):.2f}" if name.isdigit() else name
        draw_body(ax, body, nice_scale(body), title)
    for ax in list(axes.flat)[len(bodies):]:
        ax.axis("off")
    legend(fig)
    fig.tight_layout(rect=(0, 0.07, 1, 1))
    save(fig, output)


if __name__ == "__main__":
    main()
