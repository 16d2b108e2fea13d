#!/usr/bin/env python3
"""FSI3 faster (issue 56, item 3; performance.md section 17): where the time of two whole runs of
prm/turek_hron_fsi3.prm goes, and each lever's share of the difference.

From each run's summary.json (fvfsi's counts and TimerOutput): the wall time as
    set-up + fluid solves x t_fluid + coupling iterations x (t_mesh + t_geometry + t_solid + t_rest)
with t_fluid the fluid timer per fluid solve (one per fluid-alone step, one per coupling
iteration), the others per coupling iteration. The levers are then applied to the first run's
model one at a time, in the order given, each replacing its factors with the second run's:
  dt         the number of steps (fluid alone and coupled) at the second run's time step;
  iterations coupling iterations per coupled step (the coupling method);
  fluid      t_fluid (the pressure solves per fluid solve: non-orthogonal correctors);
  solid      t_solid (the solid's algorithm);
  the rest   mesh motion, geometry, transfers, acceleration, set-up.
A lever's share depends on the order (the factors multiply), so the table gives each step's
saving and the model's total against the measured wall time.

usage: python3 doc/results/fsi3_fast.py RUN_DIRECTORY/FIRST RUN_DIRECTORY/SECOND
"""
import json
import sys


def model(directory):
    """The factors of the cost model of one run."""
    with open(directory + "/summary.json") as f:
        s = json.load(f)
    r, t = s["results"], s["timing"]
    iterations = r["coupling_iterations"]
    fluid_alone = r["time_steps"] - r["coupled_time_steps"]
    solves = fluid_alone + iterations
    rest = sum(t.get(k, 0) for k in ("displacement transfer", "traction transfer", "acceleration",
                                      "step start copy"))
    timed = t["fluid"] + t["mesh motion"] + t["geometry"] + t["solid"] + rest
    return {"wall": s["wall_seconds"], "setup": s["wall_seconds"] - timed,
            "fluid_alone": fluid_alone, "coupled": r["coupled_time_steps"],
            "per_step": iterations / r["coupled_time_steps"],
            "t_fluid": t["fluid"] / solves, "t_mesh": t["mesh motion"] / iterations,
            "t_geometry": t["geometry"] / iterations, "t_solid": t["solid"] / iterations,
            "t_rest": rest / iterations,
            "pressure_per_solve": r["fluid_pressure_linear_solves"] / solves,
            "cg": r["fluid_pressure_iterations_per_solve"]}


def wall(m):
    iterations = m["coupled"] * m["per_step"]
    return (m["setup"] + (m["fluid_alone"] + iterations) * m["t_fluid"] +
            iterations * (m["t_mesh"] + m["t_geometry"] + m["t_solid"] + m["t_rest"]))


def main(first, second):
    a, b = model(first), model(second)
    print(f"| factor | {first} | {second} |")
    print("|---|---:|---:|")
    rows = [("wall [s]", "wall", "{:.0f}"), ("set-up and output [s]", "setup", "{:.1f}"),
            ("steps of the fluid alone", "fluid_alone", "{:d}"), ("coupled steps", "coupled", "{:d}"),
            ("coupling iterations per coupled step", "per_step", "{:.2f}"),
            ("fluid per solve [ms]", "t_fluid", "ms"), ("pressure solves per fluid solve", "pressure_per_solve", "{:.2f}"),
            ("CG iterations per pressure solve", "cg", "{:.2f}"),
            ("mesh motion per coupling iteration [ms]", "t_mesh", "ms"),
            ("geometry per coupling iteration [ms]", "t_geometry", "ms"),
            ("solid per coupling iteration [ms]", "t_solid", "ms"),
            ("transfers, acceleration, step-start copy per coupling iteration [ms]", "t_rest", "ms")]
    for label, key, form in rows:
        cell = (lambda v: f"{1e3 * v:.1f}") if form == "ms" else form.format
        print(f"| {label} | {cell(a[key])} | {cell(b[key])} |")
    print()
    print("| lever (applied in this order) | model wall [s] | saved [s] | x of the first run's model |")
    print("|---|---:|---:|---:|")
    m = dict(a)
    start = wall(m)
    print(f"| the first run (model; measured {a['wall']:.0f} s) | {start:.0f} | | 1.000 |")
    levers = [("time step (steps)", ("fluid_alone", "coupled")), ("coupling iterations per step", ("per_step",)),
              ("fluid per solve", ("t_fluid",)), ("solid per coupling iteration", ("t_solid",)),
              ("the rest (mesh motion, geometry, transfers, set-up)", ("t_mesh", "t_geometry", "t_rest", "setup"))]
    for label, keys in levers:
        before = wall(m)
        for k in keys:
            m[k] = b[k]
        print(f"| {label} | {wall(m):.0f} | {before - wall(m):.0f} | {wall(m) / start:.3f} |")
    print(f"| the second run (measured) | {b['wall']:.0f} | | {b['wall'] / a['wall']:.3f} (measured) |")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
