#!/usr/bin/python3
"""plot_convergence.py TABLE PNG: the errors Ew_H, Ew_V, E_V of the table
that 'step-2 convergence L' prints (saved to TABLE) against h, log-log,
with a slope-1 line; written to PNG (doc/convergence.png is made by
  ./step-2 convergence 4 > table.txt && doc/plot_convergence.py table.txt doc/convergence.png).
Needs matplotlib (Debian: python3-matplotlib)."""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

lines = open(sys.argv[1]).read().splitlines()
header = next(i for i, l in enumerate(lines) if l.split()[:2] == ["1/h", "dofs"])
rows = [l.split() for l in lines[header + 1:] if l.strip()]
h = np.array([1 / float(r[0]) for r in rows])
# columns: 1/h dofs Newton lambda_1 Ew_H [rate] Ew_V [rate] E_V [rate]; the
# first row has '-' in place of each rate
errors = {"Ew_H": [], "Ew_V": [], "E_V": []}
for r in rows:
    for name, column in zip(errors, (4, 6, 8)):
        errors[name].append(float(r[column]))
fig, ax = plt.subplots(figsize=(5, 4))
for name, values in errors.items():
    ax.loglog(h, values, "o-", label=name)
ax.loglog(h, errors["Ew_V"][0] * h / h[0], "k--", label="order 1")
ax.set_xlabel("h (k = h)")
ax.set_ylabel("error")
ax.set_title("step-2: coupled refinement")
ax.legend()
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=100)
