#!/usr/bin/env python3
"""The Markdown tables of doc/results/hard_cases.md from hard_cases.json (hard_cases.py) and
hard_cases_benchmarks.jsonl (hard_cases_benchmarks.sh).

usage: python3 doc/results/hard_cases_table.py [hard_cases.json] [hard_cases_benchmarks.jsonl]
"""
import json
import os
import statistics
import sys

HERE = os.path.dirname(os.path.abspath(__file__))


def status(row, end):
    """The row's status; pimpleFoam rows of runs made before hard_cases.py recorded t_end are
    judged from their step count (pimpleFoam prints one Courant line before its first step)."""
    if row["code"] == "pimpleFoam" and "t_end" not in row and row["status"] == "silent failure" \
            and not row["message"] and row["drag"] is not None and abs(row["drag"]) < 1000:
        t_end = (row["steps"] - 1) * row["dt"]
        return "stable" if t_end >= end - 0.5 * row["dt"] - 1e-9 else row["status"]
    return row["status"]


def matrix(path):
    data = json.load(open(path))
    end = data["end_time"]
    rows = data["rows"]
    print("CPU: %s; command: `%s`\n" % (data["cpu"], data["command"]))
    print("| aspect | r | cells | inflow | Courant (target / max) | code | status | drag at t = 0.5 s "
          "[N/m] | vs finest fvfsi | correctors per step (mean / max) | wall [s] |")
    print("|---|---:|---:|---|---|---|---|---:|---:|---|---:|")
    for row in rows:
        st = status(row, end)
        refs = [x for x in rows if x["code"] == "fvfsi" and x["aspect"] == row["aspect"] and
                x["inflow"] == row["inflow"] and x["r"] == max(y["r"] for y in rows) and
                x["courant_target"] == min(y["courant_target"] for y in rows) and
                x["status"] == "stable"]
        err = ("%+.2f%%" % (100 * (row["drag"] / refs[0]["drag"] - 1))
               if refs and st == "stable" and row["drag"] is not None else "-")
        corr = ("%.2f / %d" % (row["correctors_mean"], row["correctors_max"])
                if row.get("correctors_mean") is not None else "4 (fixed)")
        drag = "%.2f" % row["drag"] if st == "stable" and row["drag"] is not None else "-"
        what = st
        if st == "stopped with a message":
            m = row["message"].replace("fvfsi: error: Fluid: the solution ", "")
            what = "stopped: " + (m.split(" (t =")[0] if "diverges" in m else m)
        print("| %d | %d | %d | %s | %g / %s | %s | %s | %s | %s | %s | %.1f |" % (
            row["aspect"], row["r"], row["cells"], row["inflow"], row["courant_target"],
            "%.3g" % row["max_courant"] if row["max_courant"] is not None else "-", row["code"],
            what, drag, err, corr if row["code"] == "fvfsi" else "4 (fixed)", row["wall_s"]))
    silent = [r for r in rows if status(r, end) == "silent failure" and r["code"] == "fvfsi"]
    print("\nfvfsi rows with a silent failure: %d" % len(silent))


def benchmarks(path):
    rows = [json.loads(line) for line in open(path) if line.strip()]
    print("| case | correctors | wall [s] (median of %d) | result | correctors per step (min / mean / max) |"
          % len([r for r in rows if r["case"] == rows[0]["case"] and r["variant"] == "fixed2"]))
    print("|---|---|---:|---|---|")
    for case in dict.fromkeys(r["case"] for r in rows):
        for variant in ("fixed2", "default"):
            rs = [r for r in rows if r["case"] == case and r["variant"] == variant]
            last = rs[-1]
            result = "drag %.7g, lift %.7g" % (last["drag"], last["lift"])
            if "point_A_displacement" in last:
                result += ", u(A) (%.7g, %.7g)" % tuple(last["point_A_displacement"])
            print("| %s | %s | %.2f | %s | %s |" % (
                case, "2 in every step" if variant == "fixed2" else "self-converging (default)",
                statistics.median(r["wall_s"] for r in rs), result,
                " / ".join("%g" % x for x in last.get("correctors_min_mean_max", []))))


if __name__ == "__main__":
    matrix(sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "hard_cases.json"))
    print()
    benchmarks(sys.argv[2] if len(sys.argv) > 2 else
               os.path.join(HERE, "hard_cases_benchmarks.jsonl"))
