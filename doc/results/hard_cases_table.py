#!/usr/bin/env python3
"""The Markdown tables of doc/results/hard_cases.md from hard_cases.json (hard_cases.py),
hard_cases_benchmarks.jsonl (hard_cases_benchmarks.sh), hard_cases_pimple.jsonl
(hard_cases_pimple.py) and hard_cases_fsi.jsonl (hard_cases_fsi.py).

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


def pimple(matrix_path, path):
    """PISO (the matrix) beside PIMPLE with relaxation, at the same steps."""
    reference = {}
    for x in json.load(open(matrix_path))["rows"]:
        if x["code"] == "fvfsi" and x["r"] == 3 and x["courant_target"] == 1:
            reference[(x["aspect"], x["inflow"])] = x["drag"]
    rows = [json.loads(line) for line in open(path) if line.strip()]
    print("CPU: %s; command: `python3 doc/results/hard_cases_pimple.py build/fvfsi`, settings: %s\n"
          % (rows[0]["cpu"], ", ".join(rows[0]["settings"])))
    print("| aspect | r | inflow | Courant | PISO: status | drag vs finest | wall [s] | PIMPLE: "
          "status | drag vs finest | outer loops per step (mean / max) | correctors per step "
          "(mean) | wall [s] |")
    print("|---:|---:|---|---:|---|---:|---:|---|---:|---|---:|---:|")
    for row in rows:
        ref = reference[(row["aspect"], row["inflow"])]
        piso = "%+.2f%%" % (100 * (row["piso_drag"] / ref - 1)) if row["piso_status"] == "stable" else "-"
        ok = row["status"] == "stable"
        print("| %d | %d | %s | %g | %s | %s | %.1f | %s | %s | %s | %s | %.1f |" % (
            row["aspect"], row["r"], row["inflow"], row["courant_target"],
            row["piso_status"].replace("stopped with a message", "stopped by the guard"), piso,
            row["piso_wall_s"], row["status"],
            "%+.2f%%" % (100 * (row["drag"] / ref - 1)) if ok else "-",
            "%.2f / %d" % (row["outer_mean"], row["outer_max"]) if row["outer_mean"] else "-",
            "%.1f" % row["correctors_mean"] if row["correctors_mean"] else "-", row["wall_s"]))


def fsi(path):
    rows = [json.loads(line) for line in open(path) if line.strip()]
    # Errors: u_y(A) of every coupled step against the row's reference (IQN-ILS to 1e-8 with
    # tight solves), the largest difference over the reference's largest |u_y(A)|.
    for row in rows:
        base = row["row"].replace("_tight", "")  # the same case, its solvers tighter
        refs = [x for x in rows if x["row"] in (row["row"], base) and x["tolerance"] < 1e-6 and
                x["status"] == "stable"]
        a, b = row.get("uy_A_coupled"), refs[0].get("uy_A_coupled") if refs else None
        if row["status"] == "stable" and a and b and len(a) == len(b) and row["tolerance"] > 1e-6:
            row["uy_A_error"] = max(abs(x - y) for x, y in zip(a, b)) / max(abs(y) for y in b)
    # Each case together, its reference first.
    cases = list(dict.fromkeys(r["row"] for r in rows))
    methods = ["IQN-ILS", "Aitken", "IQN-IMVJ"]
    rows.sort(key=lambda r: (cases.index(r["row"]), r["tolerance"], methods.index(r["method"])))
    print("CPU: %s; command: `python3 doc/results/hard_cases_fsi.py build/fvfsi`\n" % rows[0]["cpu"])
    print("| case | method | tolerance | status | coupling iterations per step (mean / max) | "
          "max abs u_y(A) [mm] | u_y(A) error vs the row's reference | wall [s] |")
    print("|---|---|---:|---|---|---:|---:|---:|")
    for row in rows:
        ok = row["status"] == "stable"
        what = row["status"]
        if row["status"] == "stopped with a message":
            # the cause: the error's first line without the step's name
            cause = row.get("error", row["message"]).split("\n")[0]
            cause = cause.split("): ", 1)[-1] if "): " in cause else cause
            what = "stopped at t = %s: %s" % (
                row.get("error", "").split("(t = ")[1].split(" s")[0] if "(t = " in
                row.get("error", "") else "?", cause[:100])
        print("| %s | %s | %g | %s | %s | %s | %s | %.1f |" % (
            row["row"], row["method"], row["tolerance"], what,
            "%.2f / %d" % (row["iterations_mean"], row["iterations_max"])
            if row["iterations_mean"] is not None else "-",
            "%.3f" % (1e3 * row["uy_A_max"]) if ok else "-",
            ("%.1e" % row["uy_A_error"]) if "uy_A_error" in row else
            ("(reference)" if ok and row["tolerance"] < 1e-6 else "-"), row["wall_s"]))
    silent = [r for r in rows if r["status"] == "silent failure"]
    print("\nrows with a silent failure: %d" % len(silent))


if __name__ == "__main__":
    if len(sys.argv) > 1 and sys.argv[1] == "pimple":
        pimple(os.path.join(HERE, "hard_cases.json"), os.path.join(HERE, "hard_cases_pimple.jsonl"))
        sys.exit(0)
    if len(sys.argv) > 1 and sys.argv[1] == "fsi":
        fsi(os.path.join(HERE, "hard_cases_fsi.jsonl"))
        sys.exit(0)
    matrix(sys.argv[1] if len(sys.argv) > 1 else os.path.join(HERE, "hard_cases.json"))
    print()
    benchmarks(sys.argv[2] if len(sys.argv) > 2 else
               os.path.join(HERE, "hard_cases_benchmarks.jsonl"))
