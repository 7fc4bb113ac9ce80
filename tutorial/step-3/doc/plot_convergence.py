#!/usr/bin/python3
"""plot_convergence.py TABLE PNG: the two tables that 'step-3 convergence
LEVELS' prints (saved to TABLE), drawn log-log into PNG: left, E_H and E_V
of the manufactured solution against h (k = h), with lines of slope 1 and
2; right, the order in k alone, D_H and D_V against k on one mesh, with a
line of slope 1. doc/convergence.png is made by
  ./step-3 convergence 5 > table.txt && doc/plot_convergence.py table.txt doc/convergence.png
Needs matplotlib (Debian: python3-matplotlib)."""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def table(lines, first_column):
    """The rows of the table whose header starts with first_column, as
    lists of numbers ('-', the first row's missing rate, becomes nan)."""
    start = next(i for i, l in enumerate(lines)
                 if l.split()[:1] == [first_column])
    rows = []
    for line in lines[start + 1:]:
        if not line.strip() or not line.split()[0].isdigit():
            break
        rows.append([float("nan") if x == "-" else float(x)
                     for x in line.split()])
    return np.array(rows)


lines = open(sys.argv[1]).read().splitlines()
# 1/h dofs loads Newton E_H rate E_V rate
coupled = table(lines, "1/h")
# 1/k D_H rate D_V rate
in_k = table(lines, "1/k")

fig, (left, right) = plt.subplots(1, 2, figsize=(9, 4))
h = 1 / coupled[:, 0]
left.loglog(h, coupled[:, 4], "o-", label="E_H")
left.loglog(h, coupled[:, 6], "s-", label="E_V")
left.loglog(h, coupled[0, 6] * h / h[0], "k--", label="order 1")
left.loglog(h, coupled[0, 4] * (h / h[0]) ** 2, "k:", label="order 2")
left.set_xlabel("h (k = h)")
left.set_ylabel("largest error over the load values")
left.set_title("h and k refined together")
left.legend()
k = 1 / in_k[:, 0]
right.loglog(k, in_k[:, 1], "o-", label="D_H")
right.loglog(k, in_k[:, 3], "s-", label="D_V")
right.loglog(k, in_k[0, 3] * k / k[0], "k--", label="order 1")
right.set_xlabel("k (h = 1/16)")
right.set_ylabel("change of u(T) from k to k/2")
right.set_title("the memory rule alone")
right.legend()
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=100)
