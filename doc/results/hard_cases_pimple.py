#!/usr/bin/env python3
"""PIMPLE outer loops with under-relaxation on the hard-case matrix (doc/results/hard_cases.md):
the rows of hard_cases.json at largest Courant numbers of 4 and more, run again by fvfsi with
Fluid/Outer correctors = 20, Outer tolerance = 1e-3 and Outer relaxation = ALPHA, at the same
time steps. Each row: status, drag at t = 0.5 s, its change against the finest PISO run of its
kind (as in hard_cases.json), outer loops and correctors per step, wall time.

usage (from the project root, after building):
  python3 doc/results/hard_cases_pimple.py FVFSI [WORK]
Environment: ALPHA (default 0.7), ASPECT="4 15", R="1 2 3". Appends its rows to
doc/results/hard_cases_pimple.jsonl.
"""
import json
import os
import subprocess
import sys

import hard_cases

HERE = os.path.dirname(os.path.abspath(__file__))


def main():
    alpha = float(os.environ.get("ALPHA", "0.7"))
    aspects = [int(x) for x in os.environ.get("ASPECT", "4 15").split()]
    rs = [int(x) for x in os.environ.get("R", "1 2 3").split()]
    cpu = subprocess.run("grep -m1 'model name' /proc/cpuinfo | cut -d: -f2", shell=True,
                         capture_output=True, text=True).stdout.strip()
    matrix = json.load(open(os.path.join(HERE, "hard_cases.json")))["rows"]
    extra = ["Fluid/Outer correctors=20", "Fluid/Outer tolerance=1e-3",
             "Fluid/Outer relaxation=%g" % alpha]
    with open(os.path.join(HERE, "hard_cases_pimple.jsonl"), "a") as out:
        for row in matrix:
            if row["code"] != "fvfsi" or row["courant_target"] < 4 or \
                    row["aspect"] not in aspects or row["r"] not in rs:
                continue
            name = "pimple%g_r%d_a%d_co%g_%s" % (alpha, row["r"], row["aspect"],
                                                 row["courant_target"], row["inflow"])
            res = hard_cases.run_fvfsi(name, row["r"], row["aspect"], row["inflow"], row["dt"],
                                       extra)
            hist = os.path.join(hard_cases.WORK, "fvfsi", name, "fluid_history.txt")
            outer = []
            if os.path.exists(hist):
                with open(hist) as f:
                    names = f.readline().lstrip("#").split()
                    outer = [float(line.split()[names.index("outer")]) for line in f if line.strip()]
            result = {k: row[k] for k in ("r", "aspect", "courant_target", "inflow", "dt", "cells")}
            result.update(res)
            result.update({"cpu": cpu, "alpha": alpha, "settings": extra,
                           "outer_mean": sum(outer) / len(outer) if outer else None,
                           "outer_max": max(outer) if outer else None,
                           "piso_status": row["status"], "piso_drag": row["drag"],
                           "piso_wall_s": row["wall_s"]})
            out.write(json.dumps(result) + "\n")
            out.flush()
            print(json.dumps(result), flush=True)


if __name__ == "__main__":
    main()
