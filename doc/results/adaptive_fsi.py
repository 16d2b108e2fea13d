#!/usr/bin/env python3
"""Adaptive time steps on FSI3 (doc/results/hard_cases.md, section 3): error of the flag's
amplitude and frequency against wall time, fixed steps against Time/Adaptive = Courant and error.

The case: prm/turek_hron_fsi3.prm on a coarse channel (Generator arguments 20, 5 281 cells) with
the paper's flag mesh (82 x 4), the fluid alone to Coupling/Start time = 1 s, IQN-ILS to 3 s.
Measured over the window 2.5-3 s (the oscillation developed): the amplitude (max - min) / 2 and
the frequency (from the upward zero crossings of u_y(A) - its mean) of u_y(A), and the mean and
amplitude of the drag. Errors against the run with the smallest fixed step (REFERENCE).

usage (from the project root, after building):
  python3 doc/results/adaptive_fsi.py FVFSI [WORK]
Environment: RUNS (names of RUN below, default all). Appends to doc/results/adaptive_fsi.jsonl;
`python3 doc/results/adaptive_fsi.py table` prints the table.
"""
import json
import os
import subprocess
import sys
import time

from hard_cases_fsi import history  # a history file as a list of {column: value}

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
WINDOW = (2.5, 3.0)
REFERENCE = "fixed_0.5ms"
RUNS = {
    "fixed_4ms": ["Time/Time step=0.004"],
    "fixed_2ms": ["Time/Time step=0.002"],
    "fixed_1ms": ["Time/Time step=0.001"],
    "courant_4": ["Time/Time step=0.002", "Time/Adaptive=Courant", "Time/Max Courant number=4"],
    "courant_2": ["Time/Time step=0.002", "Time/Adaptive=Courant", "Time/Max Courant number=2"],
    "courant_1": ["Time/Time step=0.002", "Time/Adaptive=Courant", "Time/Max Courant number=1"],
    "error_3e-3": ["Time/Time step=0.002", "Time/Adaptive=error", "Time/Error tolerance=3e-3"],
    "error_1e-3": ["Time/Time step=0.002", "Time/Adaptive=error", "Time/Error tolerance=1e-3"],
    "error_3e-4": ["Time/Time step=0.002", "Time/Adaptive=error", "Time/Error tolerance=3e-4"],
    "fixed_0.5ms": ["Time/Time step=0.0005"],
}


def measure(rows):
    w = [r for r in rows if WINDOW[0] <= r["t"] <= WINDOW[1] + 1e-9]
    u = [r["uy_A"] for r in w]
    mean = sum(u) / len(u)
    up = []
    for a, b in zip(w, w[1:]):
        ua, ub = a["uy_A"] - mean, b["uy_A"] - mean
        if ua < 0 <= ub:
            up.append(a["t"] + (b["t"] - a["t"]) * (-ua) / (ub - ua))
    drag = [r["drag"] for r in w]
    return {"uy_A_amplitude": (max(u) - min(u)) / 2,
            "frequency": (len(up) - 1) / (up[-1] - up[0]) if len(up) > 1 else None,
            "drag_mean": sum(drag) / len(drag), "drag_amplitude": (max(drag) - min(drag)) / 2,
            "dt_window_mean": (w[-1]["t"] - w[0]["t"]) / (len(w) - 1),
            "courant_window_max": max(r["courant"] for r in w)}


def run(name, fvfsi, work):
    out = os.path.join(work, name)
    settings = ["Mesh/Generator arguments=20", "Solid mesh/Generator arguments=82: 4",
                "Time/End time=3", "Coupling/Start time=1", "Fluid scene/Output interval=0",
                "Fluid scene/Progress interval=1000000", "Output directory=" + out] + RUNS[name]
    args = [fvfsi, os.path.join(ROOT, "prm", "turek_hron_fsi3.prm")]
    for s in settings:
        args += ["--set", s]
    start = time.time()
    p = subprocess.run(args, capture_output=True, text=True)
    wall = time.time() - start
    rows = history(os.path.join(out, "fsi_history.txt"))
    coupled = [r for r in rows if r["coupling_iterations"] > 0]
    result = {"name": name, "settings": settings, "returncode": p.returncode,
              "wall_s": round(wall, 1), "steps": len(rows), "coupled_steps": len(coupled),
              "iterations_mean": sum(r["coupling_iterations"] for r in coupled) / len(coupled)}
    if p.returncode == 0:
        result.update(measure(rows))
    return result


def table():
    rows = {}
    for line in open(os.path.join(HERE, "adaptive_fsi.jsonl")):
        r = json.loads(line)
        rows[r["name"]] = r
    ref = rows[REFERENCE]
    print("CPU: %s; command: `python3 doc/results/adaptive_fsi.py build/fvfsi`; errors against "
          "%s over t = %g-%g s\n" % (ref.get("cpu", "?"), REFERENCE, *WINDOW))
    print("| run | steps | mean dt in the window [ms] | max Courant in the window | coupling "
          "iterations per step | u_y(A) amplitude [mm] | error | frequency [Hz] | error | drag "
          "mean error | drag amplitude error | wall [s] |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for name in RUNS:
        if name not in rows:
            continue
        r = rows[name]
        if r["returncode"] != 0:
            print("| %s | %d | - | - | - | stopped | - | - | - | - | - | %.0f |" % (
                name, r["steps"], r["wall_s"]))
            continue
        e = lambda k: "%+.2f%%" % (100 * (r[k] / ref[k] - 1)) if name != REFERENCE else "-"
        print("| %s | %d | %.3f | %.2f | %.2f | %.3f | %s | %.4f | %s | %s | %s | %.0f |" % (
            name, r["steps"], 1e3 * r["dt_window_mean"], r["courant_window_max"],
            r["iterations_mean"], 1e3 * r["uy_A_amplitude"], e("uy_A_amplitude"),
            r["frequency"], e("frequency"), e("drag_mean"), e("drag_amplitude"), r["wall_s"]))


def main():
    if sys.argv[1] == "table":
        table()
        return
    fvfsi = os.path.abspath(sys.argv[1])
    work = sys.argv[2] if len(sys.argv) > 2 else "/tmp/adaptive_fsi"
    cpu = subprocess.run("grep -m1 'model name' /proc/cpuinfo | cut -d: -f2", shell=True,
                         capture_output=True, text=True).stdout.strip()
    for name in os.environ.get("RUNS", " ".join(RUNS)).split():
        result = run(name, fvfsi, work)
        result["cpu"] = cpu
        with open(os.path.join(HERE, "adaptive_fsi.jsonl"), "a") as f:
            f.write(json.dumps(result) + "\n")
        print(json.dumps(result), flush=True)


if __name__ == "__main__":
    main()
