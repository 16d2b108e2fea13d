#!/usr/bin/python3
"""Figures of the thick plate in a channel (paper section 4.5, doc/results/fsi_3d_plate.sh).

From a run's summary.json: the displacement of probe A = (0.45, 0.15, -0.15) and the force of
the fluid on the half plate, F_x (drag) and F_y (lift), against Richter's benchmark values
(u_x(A) = 5.95e-5 m, F_x = 1.33 N) and the paper's (u_y(A) = 2.40e-5 m, F_y = 0.1055 N; the
paper's u_x, F_x: 5.93e-5 m, 1.31 N); for the large-deformation variant u(A) against the
paper's (0.01463, 0.005, -0.000447) m. Temporal order: of u_x(A) at t = 0.08 s (Eq. 34) and of
the L2 norm over [0, 0.08 s] of u_x(A)(t) minus the run with the smallest time step. Observed order of three values phi_1, phi_2, phi_3 on
meshes or time steps halved each time (phi_3 the finest), the paper's Eq. 34:
  p = ln[(phi_1 - phi_2) / (phi_2 - phi_3)] / ln 2.

  fsi_3d_plate.py record RUN_DIRECTORY PRM "SET..." > run.json     one run (FSI or solid alone)
  fsi_3d_plate.py table run.json ...                               markdown rows (FSI runs)
  fsi_3d_plate.py large-table run.json ...                         the large-deformation runs
  fsi_3d_plate.py solid-table run.json ...                         markdown rows (solid alone)
  fsi_3d_plate.py order KEY a.json b.json c.json [...]             orders of consecutive triples
  fsi_3d_plate.py history-order dt1.json ... ref.json    L2-in-time errors of u_x(A) and orders
  fsi_3d_plate.py store shipped.json --runs run.json ... --large large.json
                        --temporal dt1.json dt2.json dt3.json dt4.json
      -> doc/results/fsi_3d.json["plate"]
"""
import json
import math
import os
import sys

from fsi_3d import commit_of, group_arguments, store_entry  # the tube's script, beside this one

REFERENCE = {"ux_A": 5.95e-5, "Fx": 1.33}          # Richter's benchmark
PAPER = {"ux_A": 5.93e-5, "uy_A": 2.40e-5, "Fx": 1.31, "Fy": 0.1055}
PAPER_LARGE = [0.01463, 0.005, -0.000447]        # the paper's Fig. 28, m


def record(directory, prm, overrides):
    s = json.load(open(directory + "/summary.json"))
    r = s["results"]
    u = r["point_A_displacement"]
    run = {"prm": prm, "set": overrides, "commit": commit_of(directory),
           "ranks": s.get("n_mpi_ranks", 1), "fluid_cells": r.get("fluid_cells"),
           "solid_cells": r.get("solid_cells", s.get("n_cells")),
           "wall_seconds": s.get("wall_seconds"), "timing": s.get("timing", {}),
           "peak_memory_mb": s.get("peak_memory_mb"),
           "ux_A": u[0], "uy_A": u[1], "uz_A": u[2], "Fx": r.get("drag"), "Fy": r.get("lift")}
    for key in ("coupling_iterations", "fluid_pseudo_steps", "solid_outer_iterations",
                "time_steps", "mean_coupling_iterations_per_step", "min_cell_volume_ratio"):
        if key in r:
            run[key] = r[key]
    history = directory + "/fsi_history.txt"
    if run.get("time_steps") and os.path.exists(history):  # a transient FSI run: dt, end [s]
        names = open(history).readline().lstrip("#").split()
        last = open(history).read().strip().splitlines()[-1].split()
        run["dt"], run["end_time"] = float(last[names.index("dt")]), float(last[0])
        rows = [line.split() for line in open(history) if not line.startswith("#")]
        run["ux_A_history"] = [[float(r[0]), float(r[names.index("ux_A")])] for r in rows]
    if "dt" in run or run["fluid_cells"] is None:
        return run  # the errors below are those of the steady FSI benchmark
    run["error_vs_reference"] = {k: run[k] / v - 1 for k, v in REFERENCE.items()
                                 if run.get(k) is not None}
    run["error_vs_paper"] = {k: run[k] / v - 1 for k, v in PAPER.items()
                             if run.get(k) is not None}
    return run


def percent(run, key, table):
    e = run[table].get(key)
    return "" if e is None else f" ({100 * e:+.1f}%)"


def table(records):
    print("| run | cells fluid + solid | u_x(A) [m] (vs 5.95e-5) | F_x [N] (vs 1.33) | u_y(A) [m] "
          "(vs paper 2.40e-5) | F_y [N] (vs paper 0.1055) | coupling it. | fluid pseudo steps | "
          "wall [s] |")
    print("|---|---|---|---|---|---|---|---|---|")
    for name, r in records:
        print(f"| {name} | {r['fluid_cells']} + {r['solid_cells']} | "
              f"{r['ux_A']:.4e}{percent(r, 'ux_A', 'error_vs_reference')} | "
              f"{r['Fx']:.4f}{percent(r, 'Fx', 'error_vs_reference')} | "
              f"{r['uy_A']:.4e}{percent(r, 'uy_A', 'error_vs_paper')} | "
              f"{r['Fy']:.4f}{percent(r, 'Fy', 'error_vs_paper')} | "
              f"{r.get('coupling_iterations', '')} | {r.get('fluid_pseudo_steps', '')} | "
              f"{r['wall_seconds']:.3g} |")


def large_table(records):
    print("| run | cells fluid + solid | u(A) [m] | against the paper's (0.01463, 0.005, -0.000447) | "
          "F_x, F_y [N] | coupling it. | smallest cell volume ratio | wall [s] |")
    print("|---|---|---|---|---|---|---|---|")
    for name, r in records:
        u = [r["ux_A"], r["uy_A"], r["uz_A"]]
        errors = ", ".join(f"{100 * (a / b - 1):+.1f}%" for a, b in zip(u, PAPER_LARGE))
        print(f"| {name} | {r['fluid_cells']} + {r['solid_cells']} | "
              f"({u[0]:.5f}, {u[1]:.5f}, {u[2]:.6f}) | {errors} | {r['Fx']:.3f}, {r['Fy']:.4f} | "
              f"{r['coupling_iterations']} | {r['min_cell_volume_ratio']:.3f} | "
              f"{r['wall_seconds']:.0f} |")


def solid_table(records):
    print("| run | cells | u_x(A) [m] | u_y(A) [m] | wall [s] |")
    print("|---|---|---|---|---|")
    for name, r in records:
        print(f"| {name} | {r['solid_cells']} | {r['ux_A']:.5e} | {r['uy_A']:.5e} | "
              f"{r['wall_seconds']:.1f} |")


def orders(key, runs):
    """Eq. 34's order of each consecutive triple; None where the differences change sign."""
    result = []
    for a, b, c in zip(runs, runs[1:], runs[2:]):
        d1, d2 = a[key] - b[key], b[key] - c[key]
        result.append(math.log(d1 / d2) / math.log(2) if d1 * d2 > 0 else None)
    return result


def history_errors(runs):
    """The L2 norm over time of u_x(A)(t) - u_x,ref(t) for each run but the last, the reference
    (the smallest time step), interpolated linearly to each run's times [m]."""
    ref = runs[-1]["ux_A_history"]
    t_ref, u_ref = [p[0] for p in ref], [p[1] for p in ref]

    def interpolate(t):
        i = max(1, min(len(t_ref) - 1, next((k for k, x in enumerate(t_ref) if x >= t),
                                            len(t_ref) - 1)))
        w = (t - t_ref[i - 1]) / (t_ref[i] - t_ref[i - 1])
        return (1 - w) * u_ref[i - 1] + w * u_ref[i]

    errors = []
    for run in runs[:-1]:
        e = [(u - interpolate(t)) ** 2 for t, u in run["ux_A_history"]]
        errors.append(math.sqrt(sum(e) / len(e)))
    return errors


def history_orders(runs):
    e = history_errors(runs)
    return e, [math.log(a / b) / math.log(2) for a, b in zip(e, e[1:])]


def store(args):
    groups = group_arguments(args[1:], ("--runs", "--large", "--temporal"))
    load = lambda files: [json.load(open(f)) for f in files]
    shipped = json.load(open(args[0]))
    plate = {"shipped": {k: shipped[k] for k in ("prm", "set", "commit", "fluid_cells",
                                                 "solid_cells", "wall_seconds", "ranks", "ux_A",
                                                 "uy_A", "uz_A", "Fx", "Fy",
                                                 "coupling_iterations")},
             "runs": load(groups["--runs"])}
    mesh_runs = [r for r in plate["runs"] if r["ranks"] == 1] + [shipped]  # coarsest first
    plate["mesh_order"] = {k: orders(k, mesh_runs[-3:])[0] for k in ("ux_A", "Fx", "uy_A", "Fy")}
    if groups["--large"]:
        large = load(groups["--large"])[-1]
        plate["large_deformation"] = {"u_A": [large["ux_A"], large["uy_A"], large["uz_A"]],
                                      "paper_u_A": PAPER_LARGE, "run": large}
    if groups["--temporal"]:
        temporal = load(groups["--temporal"])
        errors, history = history_orders(temporal)
        plate["temporal_order"] = history[-1]
        plate["temporal_order_note"] = (
            "order of the L2(0, 0.08 s) error of u_x(A)(t) against the smallest time step's run, "
            "from the two smallest of the others; u_x(A) at t = 0.08 s alone is not monotone in dt "
            "(the plate rings at about 40-60 Hz after the ramp's start, doc/results/fsi_3d.md)")
        plate["temporal_history_errors"] = errors
        plate["temporal_history_orders"] = history
        plate["temporal_point_orders"] = orders("ux_A", temporal)
        for run in temporal:
            run.pop("ux_A_history")
        plate["temporal_runs"] = temporal
    store_entry("plate", plate)


if __name__ == "__main__":
    if len(sys.argv) < 3:
        sys.exit(__doc__)
    command, args = sys.argv[1], sys.argv[2:]
    named = lambda files: [(os.path.basename(f)[:-5], json.load(open(f))) for f in files]
    if command == "record":
        print(json.dumps(record(args[0], args[1], args[2:]), indent=1))
    elif command == "table":
        table(named(args))
    elif command == "large-table":
        large_table(named(args))
    elif command == "solid-table":
        solid_table(named(args))
    elif command == "order":
        found = orders(args[0], [json.load(open(f)) for f in args[1:]])
        print(", ".join("not monotone" if p is None else f"{p:.2f}" for p in found))
    elif command == "history-order":
        errors, found = history_orders([json.load(open(f)) for f in args])
        print("L2 errors " + ", ".join(f"{e:.3e}" for e in errors) + " m; orders " +
              ", ".join(f"{p:.2f}" for p in found))
    elif command == "store":
        store(args)
    else:
        sys.exit(__doc__)
