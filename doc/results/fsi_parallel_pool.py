#!/usr/bin/python3
"""The two-rank sets of doc/results/fsi_parallel.json pooled (log.md, "The whole shipped run on two
ranks, and a sixth set"): every round of the sets run beside two pinned one-rank copies
(two_copies.sh, removed from the tree in commit 1cbcd40; `git show
8f61d2a:doc/results/two_copies.sh` restores it: T1, T2, Tc0, Tc1), per
case (110 or 40 time steps): E = T1 / (2 T2), C = T1 / max(Tc0, Tc1), E / C, and the fastest
one-rank run over twice the fastest two-rank run.

  usage: doc/results/fsi_parallel_pool.py [doc/results/fsi_parallel.json]
"""
import json
import statistics
import sys

path = sys.argv[1] if len(sys.argv) > 1 else "doc/results/fsi_parallel.json"
sets = json.load(open(path))["sets"]


def median_quartiles(values):
    q = statistics.quantiles(values, n=4)
    return "%.0f%% (%.0f-%.0f%%)" % (100 * statistics.median(values), 100 * q[0], 100 * q[2])


print("| case | rounds | E: median (quartiles) | C: median | E / C: median (quartiles) |"
      " fastest T1 / (2 x fastest T2) |")
print("|---|---|---|---|---|---|")
for steps in sorted({s["steps"] for s in sets}, reverse=True):
    rounds = [r for s in sets if s["steps"] == steps for r in s["rounds"] if "Tc0" in r]
    if len(rounds) < 2:
        continue
    tc = [max(r["Tc0"], r["Tc1"]) for r in rounds]
    e = [r["T1"] / (2 * r["T2"]) for r in rounds]
    c = [r["T1"] / t for r, t in zip(rounds, tc)]
    ratio = [t / (2 * r["T2"]) for r, t in zip(rounds, tc)]
    t1, t2 = min(r["T1"] for r in rounds), min(r["T2"] for r in rounds)
    print("| %d steps | %d | %s | %.2f | %s | %.2f / (2 x %.2f) = %.0f%% |" % (
        steps, len(rounds), median_quartiles(e), statistics.median(c), median_quartiles(ratio),
        t1, t2, 100 * t1 / (2 * t2)))
