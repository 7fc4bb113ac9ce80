#!/usr/bin/python3
"""plot_history.py RUN_DIR PNG: the file history.csv that 'step-3 block'
writes in RUN_DIR (t, the load factor P(t), u_nu and N at the right end
of the block with memory, u_nu there without memory), drawn into PNG:
the penetration at the block's free end with and without memory, the
memory pressure N and the load factor, against t. doc/history.png is
made by
  ./step-3 block && doc/plot_history.py . doc/history.png
Needs matplotlib (Debian: python3-matplotlib)."""
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

data = np.genfromtxt(sys.argv[1] + "/history.csv", delimiter=",", names=True)
fig, (left, right) = plt.subplots(1, 2, figsize=(9, 4))
left.plot(data["t"], data["u_nu_elastic"], "s-", label="without memory")
left.plot(data["t"], data["u_nu_memory"], "o-", label="with memory")
for r in (0.02, 0.15):  # the breakpoints of the normal law
    left.axhline(r, color="gray", lw=0.5, ls="--")
left.set_xlabel("load parameter t")
left.set_ylabel("u_nu at the free end x = 4")
left.set_title("penetration")
left.legend()
right.plot(data["t"], data["N_memory"], "o-", label="N at x = 4")
right.plot(data["t"], data["load_factor"], "k--", label="load factor P(t)")
right.set_xlabel("load parameter t")
right.set_title("memory pressure and load")
right.legend()
fig.tight_layout()
fig.savefig(sys.argv[2], dpi=100)
