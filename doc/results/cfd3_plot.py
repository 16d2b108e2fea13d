#!/usr/bin/python3
"""Drag and lift over time of Turek-Hron CFD3 runs (fluid_history.txt: t drag lift ...).
usage: cfd3_plot.py OUT.png HISTORY [HISTORY...]"""
import sys
import numpy as np
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt

fig, (ax_d, ax_l) = plt.subplots(2, 1, figsize=(10, 6), sharex=True)
for path in sys.argv[2:]:
    h = np.loadtxt(path, comments="#", ndmin=2)
    label = path.split("/")[-2]
    ax_d.plot(h[:, 0], h[:, 1], lw=0.8, label=label)
    ax_l.plot(h[:, 0], h[:, 2], lw=0.8, label=label)
for ax, ref, amp, name in ((ax_d, 439.45, 5.6183, "drag"), (ax_l, -11.893, 437.81, "lift")):
    for v in (ref - amp, ref + amp):
        ax.axhline(v, color="k", ls=":", lw=0.8)
    ax.set_ylabel(name + " [N/m]")
ax_d.set_ylim(380, 500)
ax_l.set_xlabel("t [s]")
ax_d.legend(fontsize=8)
ax_d.set_title("Turek-Hron CFD3 (dotted: reference mean +- amplitude)")
plt.tight_layout()
plt.savefig(sys.argv[1], dpi=120)
