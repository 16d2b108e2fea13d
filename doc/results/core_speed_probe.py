#!/usr/bin/env python3
"""Summarise doc/results/core_speed_probe.sh's two chunk logs (core 0, core 1).

Per WINDOW seconds, each core's speed is the chunks it finished in the window over the most any
window of either core finished (1.00: the best WINDOW seconds of this probe, ten by default).
Printed: one line per window, then the quantiles of the slower core's speed (what a two-rank run,
which waits for its slower rank, can reach), how many windows had one core more than 5% behind the
other, and the longest stretch of consecutive windows in which the same core was that far behind
(how long an imbalance lasts: a partition that follows the cores' speeds needs it to last).
usage: core_speed_probe.py CORE0_LOG CORE1_LOG [WINDOW]"""
import statistics
import sys


def chunks_per_window(path, window):
    counts = {}
    with open(path) as f:
        for line in f:
            fields = line.split()
            if len(fields) == 2:
                k = int(float(fields[0]) // window)
                counts[k] = counts.get(k, 0) + 1
    return counts


def main():
    window = float(sys.argv[3]) if len(sys.argv) > 3 else 10.0
    c0, c1 = (chunks_per_window(p, window) for p in sys.argv[1:3])
    n = min(max(c0), max(c1))  # complete windows of both (the last one may be partial)
    best = max(max(c0.values()), max(c1.values()))
    slower, behind, longest, stretch, side = [], 0, 0, 0, None
    print("window [s]  core 0  core 1  slower  core 0 / core 1")
    for k in range(n):
        s0, s1 = c0.get(k, 0) / best, c1.get(k, 0) / best
        slower.append(min(s0, s1))
        lag = None if min(s0, s1) >= 0.95 * max(s0, s1) else (0 if s0 < s1 else 1)  # who is behind
        behind += lag is not None
        stretch = 0 if lag is None else (stretch + 1 if lag == side else 1)
        side = lag
        longest = max(longest, stretch)
        ratio = s0 / s1 if s1 else 0
        print(f"{k * window:10.0f}  {s0:6.2f}  {s1:6.2f}  {min(s0, s1):6.2f}  {ratio:15.2f}")
    q1, median, q3 = statistics.quantiles(slower, n=4)
    print(f"{n} windows of {window:g} s; the slower core's speed: median {median:.2f}, "
          f"quartiles {q1:.2f}-{q3:.2f}, "
          f"lowest {min(slower):.2f}; one core more than 5% behind in {behind} windows, "
          f"the same core for at most {longest} in a row")


main()
