#!/usr/bin/python3
"""Statistics, plots and JSON records of the Turek-Hron FSI2/FSI3 runs (doc/results/fsi3.sh,
fsi2.sh).

For a run's fsi_history.txt and a window [T0, T1] (the last seconds, the solution periodic):
mean = (max + min) / 2 and amplitude = (max - min) / 2 over the last full period of the flag's
oscillation (of u_y(A)) in the window, frequency = 1 / period from the up-crossings of each
quantity's mid level in the window (Turek and Hron's definitions, doc/reference/benchmarks.md
section 2), for u_x(A), u_y(A), drag and lift; the amplitude of every period in the window (it has
settled when they agree); the errors against the refined Featflow references and the paper's
Table 2.

  fsi_benchmark.py record CASE RUN_DIRECTORY T0 T1 PRM "SET..." > run.json   one RUN record
  fsi_benchmark.py table CASE run1.json run2.json ...                      markdown table rows
  fsi_benchmark.py plot CASE PNG RUN_DIRECTORY T0 T1                       u_x, u_y, drag, lift
  fsi_benchmark.py store CASE shipped.json run.json ...   doc/results/fsi_benchmarks.json[CASE]
  fsi_benchmark.py methods CASE run.json ...        coupling methods: table, fsi_benchmarks.json
  fsi_benchmark.py cavity-record H RUN_DIRECTORY "SET..." > run.json   one cavity mesh
  fsi_benchmark.py cavity-study PNG run_h1.json ... (coarsest first)   orders, table, JSON, plot

The cavity (paper section 4.2) is steady: per mesh u_y(A) and F_y, the y force of the fluid on
the interface, and the observed order of the paper's Eq. 34 from the three finest meshes,
p = ln[(phi_3 - phi_2) / (phi_2 - phi_1)] / ln 2 (phi_1 the finest).
"""
import json
import os
import subprocess
import sys

import numpy as np

# Refined references (Featflow, level 4+0) and the paper's Table 2: (mean, amplitude, frequency).
REFERENCE = {
    "fsi3": {"ux_A": (-2.88e-3, 2.72e-3, 10.93), "uy_A": (1.47e-3, 34.99e-3, 5.46),
             "drag": (460.5, 27.74, 10.93), "lift": (2.50, 153.91, 5.46)},
    "fsi2": {"ux_A": (-14.85e-3, 12.70e-3, 3.86), "uy_A": (1.30e-3, 81.6e-3, 1.93),
             "drag": (215.06, 77.65, 3.86), "lift": (0.61, 237.8, 1.93)},
}
PAPER = {
    "fsi3": {"ux_A": (-2.72e-3, 2.58e-3, 11.07), "uy_A": (1.67e-3, 33.84e-3, 5.53),
             "drag": (459.18, 24.86, 11.07), "lift": (1.59, 155.9, 5.53)},
    "fsi2": {"ux_A": (-14.26e-3, 12.34e-3, 3.9), "uy_A": (1.22e-3, 80.2e-3, 1.95),
             "drag": (211.34, 75.59, 3.9), "lift": (1.23, 238.35, 1.95)},
}
QUANTITIES = ["ux_A", "uy_A", "drag", "lift"]


def load(directory):
    """The columns of DIRECTORY/fsi_history.txt by name."""
    path = directory + "/fsi_history.txt"
    with open(path) as f:
        names = f.readline().lstrip("#").split()
    data = np.loadtxt(path, ndmin=2)
    return {name: data[:, i] for i, name in enumerate(names)}


def up_crossings(t, q, level):
    return np.array([t[i - 1] + (t[i] - t[i - 1]) * (level - q[i - 1]) / (q[i] - q[i - 1])
                     for i in range(1, len(q)) if q[i - 1] < level <= q[i]])


def fundamental_periods(t, q, t0, t1):
    """The full periods of Q (u_y(A): the flag's fundamental oscillation) in [t0, t1], as
    (start, end) pairs between up-crossings of its mid level."""
    m = (t >= t0) & (t <= t1)
    c = up_crossings(t[m], q[m], (q[m].max() + q[m].min()) / 2)
    return list(zip(c[:-1], c[1:]))


def dominant_frequency(t, q, t0, t1):
    """The frequency of Q in [t0, t1] from its autocorrelation: the first lag at which Q repeats
    itself (correlation above 1/2), refined by a parabola through the peak. Mean crossings would
    count the lift's harmonics as periods of their own; this sees drag and u_x(A) at twice the
    flag's frequency and lift and u_y(A) at the flag's (the reference's convention)."""
    m = (t >= t0) & (t <= t1)
    t, q = t[m], q[m]
    steps = np.diff(t)
    if steps.max() > (1 + 1e-6) * steps.min():  # adaptive steps: onto their mean step first
        uniform = np.linspace(t[0], t[-1], len(t))
        t, q = uniform, np.interp(uniform, t, q)
    x = q - q.mean()
    n = len(x)
    r = np.correlate(x, x, "full")[n - 1:] / np.arange(n, 0, -1)  # unbiased
    r /= r[0]
    start = np.argmax(r < 0)  # past the zero-lag peak
    for k in range(max(start, 1), n // 2):
        if r[k] > 0.5 and r[k - 1] < r[k] >= r[k + 1]:
            shift = 0.5 * (r[k - 1] - r[k + 1]) / (r[k - 1] - 2 * r[k] + r[k + 1])
            return 1 / ((k + shift) * (t[1] - t[0]))
    return None


def statistics(t, q, t0, t1, periods):
    """Mean and amplitude over the last full period of the flag's oscillation, and those of
    every period in [t0, t1] (they agree once the run is periodic). The frequency: the flag's
    (from the up-crossings of u_y(A) that bound PERIODS, precise to interpolation) times the
    whole multiple that Q's own dominant_frequency is of it (2 for drag and u_x(A), 1 for lift
    and u_y(A)): the autocorrelation of a few periods alone is good to a few tenths of a percent."""
    if not periods:
        return {"mean": None, "amplitude": None, "frequency": None, "period_amplitudes": []}
    fundamental = len(periods) / (periods[-1][1] - periods[0][0])
    own = dominant_frequency(t, q, t0, t1)
    frequency = None if own is None else fundamental * max(round(own / fundamental), 1)
    per_period = []
    for a, b in periods:
        w = (t >= a) & (t <= b)
        per_period.append(((q[w].max() + q[w].min()) / 2, (q[w].max() - q[w].min()) / 2))
    return {"mean": per_period[-1][0], "amplitude": per_period[-1][1],
            "frequency": frequency,
            "period_amplitudes": [p[1] for p in per_period]}


def error(value, reference):
    return None if value is None else (value - reference) / abs(reference)


def summary(directory):
    """DIRECTORY/summary.json; stops if that run failed (fvfsi writes status "failed")."""
    with open(directory + "/summary.json") as f:
        s = json.load(f)
    if s.get("status") == "failed":
        sys.exit(f"{directory}: the run failed: {s.get('error')}")
    return s


def record(case, directory, t0, t1, prm, overrides):
    """One RUN record of doc/results/fsi_benchmarks.json."""
    h = load(directory)
    s = summary(directory)
    r = s["results"]
    coupled = h["coupling_iterations"] > 0
    run = {"prm": prm, "set": overrides,
           "commit": git_commit(directory),
           "ranks": s["n_mpi_ranks"], "fluid_cells": r["fluid_cells"], "solid_cells": r["solid_cells"],
           "dt": float(h["t"][1] - h["t"][0]), "dt_max": float(np.diff(h["t"]).max()), "end_time": float(h["t"][-1]), "window": [t0, t1],
           "wall_seconds": s["wall_seconds"], "time_steps": r["time_steps"],
           "coupling_iterations_mean": float(h["coupling_iterations"][coupled].mean()),
           "coupling_iterations_max": int(h["coupling_iterations"].max()),
           "min_cell_volume_ratio": r["min_cell_volume_ratio"]}
    w = coupled & (h["t"] >= t0) & (h["t"] <= t1)  # the statistics window
    if w.any():
        run["coupling_iterations_window_mean"] = float(h["coupling_iterations"][w].mean())
        run["coupling_iterations_window_max"] = int(h["coupling_iterations"][w].max())
    if "timing" in s:
        run["timing"] = s["timing"]
    # Wall time per coupled step (the steps from Coupling/Start time on).
    # (runs made before commit f552d36 do not have it)
    if "coupled_wall_seconds" in r:
        run["coupled_wall_seconds"] = r["coupled_wall_seconds"]
        run["wall_per_coupled_step"] = r["coupled_wall_seconds"] / max(int(coupled.sum()), 1)
    periods = fundamental_periods(h["t"], h["uy_A"], t0, t1)
    for q in QUANTITIES:
        st = statistics(h["t"], h[q], t0, t1, periods)
        ref = REFERENCE[case][q]
        st["error_mean"], st["error_amplitude"], st["error_frequency"] = (
            error(st["mean"], ref[0]), error(st["amplitude"], ref[1]), error(st["frequency"], ref[2]))
        run[q] = st
    return run


def percent(x):
    return "-" if x is None else f"{100 * x:+.1f}%"


def table(case, runs):
    """Markdown rows: per run the four quantities as mean ± amplitude [frequency] with the errors
    of amplitude and frequency against the refined references, the cost and the iterations."""
    lines = ["| run | cells fluid + solid | dt [s] | " + " | ".join(QUANTITIES) +
             " | wall [s] | coupling it. mean / max | min V/V_ref |",
             "|---|---|---|" + "---|" * len(QUANTITIES) + "---|---|---|"]
    for name, run in runs:
        cells = []
        for q in QUANTITIES:
            st = run[q]
            scale = 1e3 if q.startswith("u") else 1
            if st["mean"] is None:
                cells.append("no full period")
                continue
            cells.append(f"{scale * st['mean']:.4g} ± {scale * st['amplitude']:.4g} [{st['frequency']:.3g}]"
                         f" (A {percent(st['error_amplitude'])}, f {percent(st['error_frequency'])})")
        dt = f"{run['dt']:.3g}"
        if run.get("dt_max", run["dt"]) > 1.001 * run["dt"]:  # adaptive: the first and the largest
            dt += f" to {run['dt_max']:.3g}"
        lines.append(f"| {name} | {run['fluid_cells']} + {run['solid_cells']} | {dt} | " +
                     " | ".join(cells) + f" | {run['wall_seconds']:.0f} | "
                     f"{run['coupling_iterations_mean']:.2f} / {run['coupling_iterations_max']} | "
                     f"{run['min_cell_volume_ratio']:.3f} |")
    ref = REFERENCE[case]
    paper = PAPER[case]
    for label, values in (("refined reference", ref), ("paper Table 2", paper)):
        cells = [f"{(1e3 if q.startswith('u') else 1) * values[q][0]:.4g} ± "
                 f"{(1e3 if q.startswith('u') else 1) * values[q][1]:.4g} [{values[q][2]}]"
                 for q in QUANTITIES]
        lines.append(f"| {label} | | | " + " | ".join(cells) + " | | | |")
    return "\n".join(lines)


def methods(case, paths):
    """The coupling-method comparison: iterations per coupled step, wall time, u(A) at the end."""
    lines = ["| method | reuse | criterion | coupling it. mean / max (all coupled steps) | "
             "mean / max in the window | wall [s] | wall per coupled step [s] | u_y(A) at the end [m] |",
             "|---|---|---|---|---|---|---|---|"]
    runs = []
    for path in paths:
        with open(path) as f:
            run = json.load(f)
        runs.append(run)
        settings = dict(s.split("=", 1) for s in run["set"])
        # (no "|" in a markdown cell)
        criterion = ("paper: residual reduced 1e6 from the step's largest"
                     if "Coupling/Residual reduction" in settings else "residual <= 1e-5 d~ (shipped)")
        h = load(path.replace(".json", ""))
        coupled = int((h["coupling_iterations"] > 0).sum())
        lines.append(f"| {settings.get('Coupling/Method')} | {settings.get('Coupling/Reuse time steps')} "
                     f"| {criterion} | {run['coupling_iterations_mean']:.2f} / "
                     f"{run['coupling_iterations_max']} | "
                     f"{run.get('coupling_iterations_window_mean', float('nan')):.2f} / "
                     f"{run.get('coupling_iterations_window_max', '-')} | {run['wall_seconds']:.0f} | "
                     f"{run['wall_per_coupled_step']:.3f} | {h['uy_A'][-1]:.5e} |")
    store(case, {"methods": runs})
    return "\n".join(lines)


def git_commit(directory):
    """The commit of the binary that made the run (DIRECTORY/commit.txt, written by
    fsi_runs.sh), else the tree's."""
    if os.path.exists(directory + "/commit.txt"):
        return open(directory + "/commit.txt").read().strip()
    return subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                          text=True).stdout.strip()


JSON = "doc/results/fsi_benchmarks.json"


def store(key, value):
    """doc/results/fsi_benchmarks.json[key] updated with the entries of value (the rest kept)."""
    try:
        with open(JSON) as f:
            data = json.load(f)
    except FileNotFoundError:
        data = {}
    data.setdefault(key, {}).update(value)
    with open(JSON, "w") as f:
        json.dump(data, f, indent=1)
        f.write("\n")


def cavity_record(h, directory, overrides):
    s = summary(directory)
    r = s["results"]
    return {"h": h, "set": overrides, "commit": git_commit(directory), "ranks": s["n_mpi_ranks"],
            "fluid_cells": r["fluid_cells"], "solid_cells": r["solid_cells"],
            "wall_seconds": s["wall_seconds"], "coupling_iterations": r["coupling_iterations"],
            "fluid_pseudo_steps": r["fluid_pseudo_steps"],
            "solid_outer_iterations": r["solid_outer_iterations"],
            "uy_A": r["point_A_displacement"][1], "Fy": r["lift"]}


def observed_order(values):
    """Eq. 34 from the three finest of VALUES (coarsest first), refinement ratio 2; None where
    the three do not converge monotonically (the two differences change sign)."""
    phi3, phi2, phi1 = values[-3:]
    ratio = (phi3 - phi2) / (phi2 - phi1)
    return float(np.log(ratio) / np.log(2)) if ratio > 0 else None


def order_text(order):
    return "undefined (not monotone)" if order is None else f"{order:.2f}"


def cavity_study(png, runs):
    uy = [r["uy_A"] for r in runs]
    fy = [r["Fy"] for r in runs]
    study = {"runs": runs, "order_uy_A": observed_order(uy), "order_Fy": observed_order(fy)}
    lines = ["| h [m] | cells fluid + solid | u_y(A) [m] | error vs finest | F_y [N/m] | "
             "error vs finest | coupling it. | fluid pseudo steps | solid outer it. | wall [s] |",
             "|---|---|---|---|---|---|---|---|---|---|"]
    for r in runs:
        lines.append(f"| {r['h']} | {r['fluid_cells']} + {r['solid_cells']} | {r['uy_A']:.5f} | "
                     f"{percent(r['uy_A'] / uy[-1] - 1)} | {r['Fy']:.4f} | "
                     f"{percent(r['Fy'] / fy[-1] - 1)} | {r['coupling_iterations']} | "
                     f"{r['fluid_pseudo_steps']} | {r['solid_outer_iterations']} | "
                     f"{r['wall_seconds']:.1f} |")
    lines.append(f"\nObserved order (Eq. 34, three finest meshes): u_y(A) "
                 f"{order_text(study['order_uy_A'])}, F_y {order_text(study['order_Fy'])} "
                 f"(paper: 1.85, 1.91)")
    if png is None:
        return study, "\n".join(lines)
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    h = np.array([r["h"] for r in runs[:-1]])
    fig, ax = plt.subplots(figsize=(5, 4))
    for values, label in ((uy, "u_y(A)"), (fy, "F_y")):
        ax.loglog(h, np.abs(np.array(values[:-1]) / values[-1] - 1), "o-", label=label)
    ax.loglog(h, 0.5 * (h / h[0]) ** 2 * abs(uy[0] / uy[-1] - 1), "k--", lw=0.8, label="order 2")
    ax.set_xlabel("h [m]")
    ax.set_ylabel("relative difference to the finest mesh")
    ax.set_title("Cavity with a flexible bottom", fontsize=9)
    ax.legend()
    fig.tight_layout()
    fig.savefig(png, dpi=110)
    return study, "\n".join(lines)


def plot(case, png, directory, t0, t1):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    h = load(directory)
    fig, axes = plt.subplots(5, 1, figsize=(9, 12), sharex=True)
    labels = {"ux_A": "u_x(A) [m]", "uy_A": "u_y(A) [m]", "drag": "drag [N/m]", "lift": "lift [N/m]"}
    late = h["t"] >= 0.1 * h["t"][-1]  # the y range without the flow's start at t = 0
    for ax, q in zip(axes[:4], QUANTITIES):
        ax.plot(h["t"], h[q], lw=0.6, label="fvfsi")
        mean, amplitude, _ = REFERENCE[case][q]
        low, high = min(h[q][late].min(), mean - amplitude), max(h[q][late].max(), mean + amplitude)
        ax.set_ylim(low - 0.05 * (high - low), high + 0.05 * (high - low))
        for level, style in ((mean, "-"), (mean - amplitude, "--"), (mean + amplitude, "--")):
            ax.axhline(level, color="k", lw=0.6, ls=style)
        ax.axvspan(t0, t1, color="0.9", zorder=0)
        ax.set_ylabel(labels[q])
    if "min_volume_ratio" in h:  # (a column since commit 3bff9b7)
        axes[4].plot(h["t"], h["min_volume_ratio"], lw=0.6)
    axes[4].set_ylabel("min V / V_ref")
    axes[0].set_title(f"{case.upper()}: {directory.rstrip('/').split('/')[-1]} (black: reference "
                      "mean and mean ± amplitude; grey: statistics window)", fontsize=9)
    axes[-1].set_xlabel("t [s]")
    fig.tight_layout()
    fig.savefig(png, dpi=110)


if __name__ == "__main__":
    command, case = sys.argv[1], sys.argv[2]
    if command == "record":
        directory, t0, t1, prm = sys.argv[3], float(sys.argv[4]), float(sys.argv[5]), sys.argv[6]
        overrides = [s for s in sys.argv[7:]]
        json.dump(record(case, directory, t0, t1, prm, overrides), sys.stdout, indent=1)
    elif command == "table":
        runs = []
        for path in sys.argv[3:]:
            with open(path) as f:
                runs.append((path.split("/")[-1].replace(".json", ""), json.load(f)))
        print(table(case, runs))
    elif command == "store":
        runs = []
        for path in sys.argv[3:]:
            with open(path) as f:
                runs.append(json.load(f))
        store(case, {"shipped": runs[0], "runs": runs})
    elif command == "methods":
        print(methods(case, sys.argv[3:]))
    elif command == "cavity-record":
        json.dump(cavity_record(float(sys.argv[2]), sys.argv[3], sys.argv[4:]), sys.stdout, indent=1)
    elif command == "cavity-study":
        runs = []
        for path in sys.argv[3:]:
            with open(path) as f:
                runs.append(json.load(f))
        study, text = cavity_study(sys.argv[2], runs)
        store("cavity", study)
        print(text)
    elif command == "cavity-variant":  # NAME RUN.json...: stored as cavity[NAME], no plot
        runs = []
        for path in sys.argv[3:]:
            with open(path) as f:
                runs.append(json.load(f))
        study, text = cavity_study(None, runs)
        store("cavity", {sys.argv[2]: study})
        print(text)
    elif command == "plot":
        plot(case, sys.argv[3], sys.argv[4], float(sys.argv[5]), float(sys.argv[6]))
    else:
        sys.exit(__doc__)
