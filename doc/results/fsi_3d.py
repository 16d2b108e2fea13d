#!/usr/bin/python3
"""Figures of the 3D FSI benchmarks (doc/results/fsi_3d.sh): the elastic tube (paper section 4.4).

From a run's fsi_history.txt: the pressure p_NAME on the axis probes pNN (NN the distance from the
inlet in mm) and the displacement of the inner wall at the midsection, probe A on the +y side
(u_y is radial).
  wave speed: the time of the pressure peak at each axis probe (a parabola through the largest
    sample and its neighbours), then the least-squares slope of x over that time for the probes
    from 10 mm to 35 mm (near the inlet the pulse is still forming; the outlet p = 0 reflects it
    with the opposite sign);
  peak radial displacement: max u_y(A) (parabolic interpolation likewise) and its time;
  temporal order at the peak from three time steps dt, dt/2, dt/4:
    p = ln[(u_1 - u_2) / (u_2 - u_3)] / ln 2  (u_1 the coarsest).

  fsi_3d.py tube-record RUN_DIRECTORY PRM "SET..." > run.json     one run
  fsi_3d.py tube-table run.json ...                               markdown rows
  fsi_3d.py tube-plot PNG RUN_DIRECTORY LABEL [RUN_DIRECTORY LABEL ...]   p(x, t) and u_r(A)
  fsi_3d.py tube-order a.json b.json c.json                       the temporal order
  fsi_3d.py tube-parallel RUN_DIRECTORY REPEATS     speed-ups of {fsi,fluid,solid}_np{1,2}_R
  fsi_3d.py tube-store shipped.json [--order a.json b.json c.json] [--runs run.json ...]
                       [--parallel RUN_DIRECTORY REPEATS]
      -> doc/results/fsi_3d.json["tube"]
"""
import json
import os
import subprocess
import sys

import numpy as np

from fsi_benchmark import load  # the columns of RUN_DIRECTORY/fsi_history.txt by name

EQ36_SPEED = 4.81      # m/s, the paper's Eq. 36 (Moens-Korteweg with axial stress waves)
PAPER_SPEED = 4.54     # m/s, the paper's simulated speed
PAPER_PEAK = 0.157e-3  # m, read off the paper's Fig. 25 (solids4foam's finest run: 0.158 mm)
SPEED_PROBES = (0.010, 0.035)


def peak(t, q):
    """(time, value) of the maximum of q(t): a parabola through the largest sample and its
    neighbours."""
    i = int(np.argmax(q))
    if i == 0 or i == len(q) - 1:
        return float(t[i]), float(q[i])
    a, b, c = np.polyfit(t[i - 1:i + 2] - t[i], q[i - 1:i + 2], 2)
    if a >= 0:
        return float(t[i]), float(q[i])
    s = -b / (2 * a)
    return float(t[i] + s), float(c - b * b / (4 * a))


def axis_probes(h):
    """[(x, name)] of the axis pressure probes pNN."""
    return sorted((int(k[3:]) * 1e-3, k) for k in h if k.startswith("p_p") and k[3:].isdigit())


def wave_speed(h):
    arrivals = [(x, peak(h["t"], h[k])[0]) for x, k in axis_probes(h)]
    used = [(x, t) for x, t in arrivals if SPEED_PROBES[0] - 1e-9 <= x <= SPEED_PROBES[1] + 1e-9]
    xs, ts = np.array(used).T
    return float(np.polyfit(ts, xs, 1)[0]), arrivals


def commit_of(directory):
    """The commit the run directory names in commit.txt, else this checkout's."""
    path = directory + "/commit.txt"
    if os.path.exists(path):
        return open(path).read().strip()
    return subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True,
                          text=True).stdout.strip()


def tube_record(directory, prm, overrides):
    h = load(directory)
    with open(directory + "/summary.json") as f:
        s = json.load(f)
    r = s["results"]
    speed, arrivals = wave_speed(h)
    t_peak, u_peak = peak(h["t"], h["uy_A"])
    cells = r["fluid_cells"] + r["solid_cells"]
    return {
        "prm": prm, "set": overrides, "commit": commit_of(directory), "ranks": s.get("n_mpi_ranks", 1),
        "fluid_cells": r["fluid_cells"], "solid_cells": r["solid_cells"],
        "dt": float(h["dt"][-1]), "end_time": float(h["t"][-1]),
        "wall_seconds": s.get("wall_seconds"), "timing": s.get("timing", {}),
        "peak_memory_mb": s.get("peak_memory_mb"),
        "memory_per_cell_kb": 1024 * s["peak_memory_mb"] / cells if "peak_memory_mb" in s else None,
        "time_steps": r["time_steps"],
        "coupling_iterations_mean": r["mean_coupling_iterations_per_step"],
        "coupling_iterations_max": r["max_coupling_iterations_per_step"],
        "wave_speed": speed, "wave_speed_error_vs_eq36": speed / EQ36_SPEED - 1,
        "peak_arrival": [[x, t] for x, t in arrivals],
        "peak_radial_displacement": u_peak, "peak_time": t_peak,
    }


def tube_table(records):
    print("| run | cells fluid + solid | dt [s] | wave speed [m/s] (vs Eq. 36, 4.81) | peak u_r(A) "
          "[mm] at t [ms] | coupling it. mean / max | wall [s] | memory [kB/cell] |")
    print("|---|---|---|---|---|---|---|---|")
    for name, r in records:
        memory = f"{r['memory_per_cell_kb']:.1f}" if r.get("memory_per_cell_kb") else ""
        print(f"| {name} | {r['fluid_cells']} + {r['solid_cells']} | {r['dt']:g} | "
              f"{r['wave_speed']:.3f} ({100 * r['wave_speed_error_vs_eq36']:+.1f}%) | "
              f"{1e3 * r['peak_radial_displacement']:.4f} at {1e3 * r['peak_time']:.2f} | "
              f"{r['coupling_iterations_mean']:.2f} / {r['coupling_iterations_max']} | "
              f"{r['wall_seconds']:.0f} | {memory} |")


def temporal_order(records):
    """The observed order, or None where the three values do not converge monotonically (the
    differences change sign: Eq. 34 does not apply)."""
    u = [r["peak_radial_displacement"] for r in records]
    if (u[0] - u[1]) * (u[1] - u[2]) <= 0:
        return None
    return float(np.log((u[0] - u[1]) / (u[1] - u[2])) / np.log(2))


def tube_plot(png, runs):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, (a, b) = plt.subplots(2, 1, figsize=(7, 7), sharex=True)
    h = load(runs[0][0])
    for x, k in axis_probes(h):
        a.plot(1e3 * h["t"], h[k], lw=1, label=f"x = {1e3 * x:.0f} mm")
    a.set_ylabel("pressure on the axis [Pa]")
    a.set_title(f"elastic tube: {runs[0][1]}", fontsize=9)
    a.legend(fontsize=7, ncol=3)
    for directory, label in runs:
        h = load(directory)
        b.plot(1e3 * h["t"], 1e3 * h["uy_A"], lw=1.2, label=label)
    b.axhline(1e3 * PAPER_PEAK, color="k", ls=":", lw=0.8, label="paper's peak (Fig. 25)")
    b.set_ylim(top=1.15e3 * PAPER_PEAK)
    b.set_ylabel("radial displacement at A [mm]")
    b.set_xlabel("t [ms]")
    b.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(png, dpi=110)


def tube_parallel(runs, repeats):
    """Medians of the wall times of the fsi, fluid and solid runs on 1 and 2 ranks, the speed-ups
    T1 / T2 and efficiencies T1 / (2 T2); prints a markdown table and returns the figures."""
    import statistics
    result = {}
    for case in ("fsi", "fluid", "solid"):
        entry = {}
        for np_ in (1, 2):
            s = [json.load(open(f"{runs}/{case}_np{np_}_{r}/summary.json"))
                 for r in range(1, repeats + 1)]
            entry[f"np{np_}_wall_seconds"] = [x["wall_seconds"] for x in s]
            entry[f"np{np_}_median"] = statistics.median(x["wall_seconds"] for x in s)
            if case == "fsi":
                entry[f"np{np_}_coupling_iterations"] = s[0]["results"]["coupling_iterations"]
                entry[f"np{np_}_interface_bytes_per_iteration"] = \
                    s[0]["results"].get("interface_bytes_per_coupling_iteration")
        entry["speed_up"] = entry["np1_median"] / entry["np2_median"]
        entry["efficiency"] = entry["speed_up"] / 2
        result[case] = entry
    print("| case (20 steps) | 1 rank [s] (runs) | 2 ranks [s] (runs) | speed-up | efficiency |")
    print("|---|---|---|---|---|")
    for case, e in result.items():
        runs1 = ", ".join(f"{x:.1f}" for x in e["np1_wall_seconds"])
        runs2 = ", ".join(f"{x:.1f}" for x in e["np2_wall_seconds"])
        print(f"| {case} | {e['np1_median']:.1f} ({runs1}) | {e['np2_median']:.1f} ({runs2}) | "
              f"{e['speed_up']:.2f} | {100 * e['efficiency']:.0f}% |")
    f = result["fsi"]
    print(f"\nFSI coupling iterations: {f['np1_coupling_iterations']} (1 rank), "
          f"{f['np2_coupling_iterations']} (2 ranks); interface bytes received per coupling "
          f"iteration, summed over the ranks: {f['np2_interface_bytes_per_iteration']} (2 ranks)")
    return result


def group_arguments(args, flags):
    """{flag: [the arguments after it up to the next flag]} for each of flags."""
    groups = {flag: [] for flag in flags}
    which = None
    for a in args:
        if a in groups:
            which = a
        elif which is None:
            sys.exit(f"{a}: expected one of {', '.join(flags)} first")
        else:
            groups[which].append(a)
    return groups


def store_entry(key, value):
    """Writes value as fsi_3d.json[key], beside this script, keeping the other entries."""
    path = os.path.join(os.path.dirname(os.path.abspath(__file__)), "fsi_3d.json")
    data = json.load(open(path)) if os.path.exists(path) else {}
    data[key] = value
    with open(path, "w") as f:
        json.dump(data, f, indent=1)


def tube_store(args):
    groups = group_arguments(args[1:], ("--order", "--runs", "--parallel"))
    tube = {"shipped": json.load(open(args[0])),
            "runs": [json.load(open(f)) for f in groups["--runs"]]}
    if len(groups["--order"]) == 3:
        order_runs = [json.load(open(f)) for f in groups["--order"]]
        tube["temporal_order"] = temporal_order(order_runs)
        peaks = ", ".join("%.4f" % (1e3 * r["peak_radial_displacement"]) for r in order_runs)
        tube["temporal_order_note"] = (
            "the peaks of the three time steps are not monotone" if tube["temporal_order"] is None
            else "Eq. 34 on the peak radial displacement at the midsection (" + peaks + " mm); a "
            "point value: the L2-in-time differences of u_r(A)(t) converge more slowly (the "
            "inlet's step makes the tube ring at frequencies the larger time steps damp), "
            "doc/results/fsi_3d.md")
        tube["temporal_order_runs"] = order_runs
    if len(groups["--parallel"]) == 2:
        import contextlib
        import io
        with contextlib.redirect_stdout(io.StringIO()):
            tube["parallel"] = tube_parallel(groups["--parallel"][0], int(groups["--parallel"][1]))
    store_entry("tube", tube)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    command, args = sys.argv[1], sys.argv[2:]
    if command == "tube-record":
        print(json.dumps(tube_record(args[0], args[1], args[2:]), indent=1))
    elif command == "tube-table":
        tube_table([(os.path.basename(f)[:-5], json.load(open(f))) for f in args])
    elif command == "tube-plot":
        tube_plot(args[0], list(zip(args[1::2], args[2::2])))
    elif command == "tube-parallel":
        tube_parallel(args[0], int(args[1]))
    elif command == "tube-order":
        order = temporal_order([json.load(open(f)) for f in args])
        print("none (not monotone)" if order is None else f"{order:.3f}")
    elif command == "tube-store":
        tube_store(args)
    else:
        sys.exit(__doc__)
