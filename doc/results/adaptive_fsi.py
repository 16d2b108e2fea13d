#!/usr/bin/env python3
"""Adaptive time steps on FSI3 and FSI2 (doc/results/hard_cases.md, section 3): error of the
flag's amplitude and frequency against wall time, fixed steps against Time/Adaptive = Courant and
error.

FSI3: prm/turek_hron_fsi3.prm on a coarse channel (Generator arguments 20, 5 281 cells) with the
paper's flag mesh (82 x 4), the fluid alone to Coupling/Start time = 1 s, IQN-ILS to 6 s, measured
over 5-6 s, in the settled oscillation: the envelope of u_y(A) overshoots after the flag starts
to swing (amplitude per half second 13.7, 37.3, 33.7, 30.4, 30.5, 30.4 mm from t = 1.5 s with
fixed 2 ms steps) and is settled from about 3.5 s on. An earlier version of this script measured
over 2.5-3 s, inside the overshoot, where a run whose swing starts a little earlier (the error
mode's) shows another phase of the envelope, not a less accurate oscillation
(adaptive_fsi_window_2.5-3s.jsonl, hard_cases.md section 3). FSI2: see FSI2 below.

Measured in the window: the amplitude (max - min) / 2 and the frequency (from the upward zero
crossings of u_y(A) - its mean) of u_y(A), and the mean and amplitude of the drag. Errors against
the run with the smallest fixed step (the case's reference).

usage (from the project root, after building):
  python3 doc/results/adaptive_fsi.py [fsi3|fsi2] FVFSI [WORK]
Environment: RUNS (names of the case's runs below, default all). Appends to the case's jsonl in
doc/results; `python3 doc/results/adaptive_fsi.py table [fsi3|fsi2]` prints its table, and
`python3 doc/results/adaptive_fsi.py remeasure fsi2 WORK` measures the runs again from their
histories in WORK. Means are taken in time (trapezoidal rule); the FSI3 data of
adaptive_fsi.jsonl was measured with plain averages of the samples (its histories are gone), which
biases the adaptive runs' drag mean.
"""
import json
import os
import subprocess
import sys

# a history file as a list of {column: value}; a run of fvfsi and its history
from hard_cases_fsi import history, run_fvfsi

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
def study(prm, end_time, window, start_dt, fixed, courants, tolerances, reference):
    """A case: its prm file, the settings every run shares (the coarse channel, the paper's flag,
    the fluid alone to 1 s), the window of the settled oscillation, and the runs (name: their own
    settings): fixed steps [s], Courant targets and error tolerances (adaptive runs start from
    start_dt), the reference (the smallest fixed step) last."""
    runs = {"fixed_%gms" % (1e3 * dt): ["Time/Time step=%g" % dt] for dt in fixed}
    start = ["Time/Time step=%g" % start_dt]
    for c in courants:
        runs["courant_%g" % c] = start + ["Time/Adaptive=Courant", "Time/Max Courant number=%g" % c]
    for tol in tolerances:
        runs["error_" + tol] = start + ["Time/Adaptive=error", "Time/Error tolerance=" + tol]
    name = "fixed_%gms" % (1e3 * reference)
    runs[name] = ["Time/Time step=%g" % reference]
    return {"prm": prm, "window": window, "reference": name,
            "settings": ["Mesh/Generator arguments=20", "Solid mesh/Generator arguments=82: 4",
                         "Time/End time=%g" % end_time, "Coupling/Start time=1"],
            "runs": runs}


FSI3 = dict(study("turek_hron_fsi3.prm", 6, (5.0, 6.0), 0.002, [0.002, 0.001], [2, 1],
                  ["3e-3", "1e-3", "3e-4"], 0.0005), jsonl="adaptive_fsi.jsonl")
# FSI2 (prm/turek_hron_fsi2.prm, the Newton solid): its swing grows for several seconds (fsi2.md:
# settled over 12-15 s on the shipped meshes), so the window is the last 3 s of a 15 s run.
FSI2 = dict(study("turek_hron_fsi2.prm", 15, (12.0, 15.0), 0.0015, [0.003, 0.0015], [1],
                  ["1e-3", "3e-4"], 0.00075), jsonl="adaptive_fsi2.jsonl")
CASES = {"fsi3": FSI3, "fsi2": FSI2}


def time_mean(w, key):
    """The mean of a column over the window in time (trapezoidal rule): with adaptive steps the
    samples crowd where the flow changes fast, and their plain average is biased."""
    area = sum((b["t"] - a["t"]) * (a[key] + b[key]) / 2 for a, b in zip(w, w[1:]))
    return area / (w[-1]["t"] - w[0]["t"])


def measure(rows, window):
    w = [r for r in rows if window[0] <= r["t"] <= window[1] + 1e-9]
    u = [r["uy_A"] for r in w]
    mean = time_mean(w, "uy_A")
    up = []
    for a, b in zip(w, w[1:]):
        ua, ub = a["uy_A"] - mean, b["uy_A"] - mean
        if ua < 0 <= ub:
            up.append(a["t"] + (b["t"] - a["t"]) * (-ua) / (ub - ua))
    drag = [r["drag"] for r in w]
    return {"uy_A_amplitude": (max(u) - min(u)) / 2,
            "frequency": (len(up) - 1) / (up[-1] - up[0]) if len(up) > 1 else None,
            "drag_mean": time_mean(w, "drag"), "drag_amplitude": (max(drag) - min(drag)) / 2,
            "dt_window_mean": (w[-1]["t"] - w[0]["t"]) / (len(w) - 1),
            "courant_window_max": max(r["courant"] for r in w)}


def run(case, name, fvfsi, work):
    out = os.path.join(work, name)
    settings = case["settings"] + ["Fluid scene/Output interval=0",
                                   "Fluid scene/Progress interval=1000000",
                                   "Output directory=" + out] + case["runs"][name]
    p, wall, rows, coupled = run_fvfsi(fvfsi, case["prm"], settings, out)
    result = {"name": name, "settings": settings, "returncode": p.returncode,
              "wall_s": round(wall, 1), "steps": len(rows), "coupled_steps": len(coupled),
              "iterations_mean": sum(r["coupling_iterations"] for r in coupled) / len(coupled)}
    if p.returncode == 0:
        result.update(measure(rows, case["window"]))
    return result


def table(case_name):
    case = CASES[case_name]
    rows = {}
    for line in open(os.path.join(HERE, case["jsonl"])):
        r = json.loads(line)
        rows[r["name"]] = r
    ref = rows[case["reference"]]
    print("CPU: %s; command: `python3 doc/results/adaptive_fsi.py %s build/fvfsi`; errors against "
          "%s over t = %g-%g s\n" % (ref.get("cpu", "?"), case_name, case["reference"],
                                     *case["window"]))
    print("| run | steps | mean dt in the window [ms] | max Courant in the window | coupling "
          "iterations per step | u_y(A) amplitude [mm] | error | frequency [Hz] | error | drag "
          "mean error | drag amplitude error | wall [s] |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for name in case["runs"]:
        if name not in rows:
            continue
        r = rows[name]
        if r["returncode"] != 0:
            print("| %s | %d | - | - | - | stopped | - | - | - | - | - | %.0f |" % (
                name, r["steps"], r["wall_s"]))
            continue
        e = lambda k: "%+.2f%%" % (100 * (r[k] / ref[k] - 1)) if name != case["reference"] else "-"
        print("| %s | %d | %.3f | %.2f | %.2f | %.3f | %s | %.4f | %s | %s | %s | %.0f |" % (
            name, r["steps"], 1e3 * r["dt_window_mean"], r["courant_window_max"],
            r["iterations_mean"], 1e3 * r["uy_A_amplitude"], e("uy_A_amplitude"),
            r["frequency"], e("frequency"), e("drag_mean"), e("drag_amplitude"), r["wall_s"]))


def remeasure(case_name, work):
    """Measure the runs of the case's jsonl again from their histories in WORK (after a change of
    measure()), keeping each run's cost."""
    case = CASES[case_name]
    path = os.path.join(HERE, case["jsonl"])
    with open(path) as f:
        results = [json.loads(line) for line in f if line.strip()]
    for result in results:
        rows = history(os.path.join(work, result["name"], "fsi_history.txt"))
        if result["returncode"] == 0 and rows:
            result.update(measure(rows, case["window"]))
    with open(path, "w") as f:
        f.writelines(json.dumps(r) + "\n" for r in results)


def main():
    if sys.argv[1] == "table":
        table(sys.argv[2] if len(sys.argv) > 2 else "fsi3")
        return
    if sys.argv[1] == "remeasure":  # remeasure CASE WORK
        remeasure(sys.argv[2], sys.argv[3])
        return
    case_name = sys.argv[1] if sys.argv[1] in CASES else "fsi3"
    args = sys.argv[2:] if sys.argv[1] in CASES else sys.argv[1:]
    case = CASES[case_name]
    fvfsi = os.path.abspath(args[0])
    work = args[1] if len(args) > 1 else "/tmp/adaptive_" + case_name
    cpu = subprocess.run("grep -m1 'model name' /proc/cpuinfo | cut -d: -f2", shell=True,
                         capture_output=True, text=True).stdout.strip()
    for name in os.environ.get("RUNS", " ".join(case["runs"])).split():
        result = run(case, name, fvfsi, work)
        result["cpu"] = cpu
        with open(os.path.join(HERE, case["jsonl"]), "a") as f:
            f.write(json.dumps(result) + "\n")
        print(json.dumps(result), flush=True)


if __name__ == "__main__":
    main()
