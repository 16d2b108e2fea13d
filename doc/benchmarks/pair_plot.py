#!/usr/bin/python3
"""Side-by-side timing pairs as a PNG: wall times of the peer and of fvfsi per pair (left) and
their ratio per pair (right). Used by openfoam_cfd2_cost.sh and openfoam_cfd3_cost.sh.

usage: pair_plot.py PNG TITLE PEER_LABEL FVFSI_LABEL RATIO_LABEL "PEER_S ..." "FVFSI_S ..." "RATIO ..."
"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt

png, title, peer_label, fvfsi_label, ratio_label = sys.argv[1:6]
peer, fvfsi, ratios = ([float(x) for x in a.split()] for a in sys.argv[6:9])
fig, (a1, a2) = plt.subplots(1, 2, figsize=(9, 3.5))
pairs = range(1, len(peer) + 1)
a1.bar([p - 0.2 for p in pairs], peer, 0.4, label=peer_label)
a1.bar([p + 0.2 for p in pairs], fvfsi, 0.4, label=fvfsi_label)
a1.set_xlabel("pair (run one after the other)")
a1.set_ylabel("wall time [s]")
a1.legend(fontsize=8)
a2.bar(pairs, ratios)
a2.set_xlabel("pair")
a2.set_ylabel(ratio_label)
fig.suptitle(title, fontsize=10)
fig.tight_layout()
fig.savefig(png, dpi=110)
print("plot:", png)
