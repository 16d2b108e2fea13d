#!/usr/bin/env python3
"""The pressure solve's options on the CFD3 cost case (issue 56, item 1; performance.md section 15).

Two parts, both on one rank (taskset -c 0), each option's runs alternating with the others' so
that the machine's drift falls on all alike:

  probe  ML's options on one dumped pressure system of the cost case (the 500th pressure solve
         of the 400-step run at n = 40, 20 960 cells, dumped with
         doc/benchmarks/pressure_dump_probe.patch): doc/benchmarks/amg_probe, CG to 1e-2 (the
         correctors' reduction) and 1e-6 (the last solve of a step), iterations and median ms;
         and hypre's BoomerAMG with PETSc's CG on the same system (doc/benchmarks/hypre_probe).
  runs   whole runs of the cost case (doc/benchmarks/openfoam_cfd3_cost.sh's fvfsi side: 400 PISO
         steps from rest, dt = 0.25 ms, n = 40) with options fvfsi exposes: the pressure-solve
         time of fvfsi's timer, CG iterations per solve, wall time, and the change of drag and
         lift after the 400 steps against the defaults.

usage (from the project root):
  python3 doc/results/pressure_options.py probe AMG_PROBE HYPRE_PROBE DUMP_DIR [REPEATS]
  python3 doc/results/pressure_options.py runs FVFSI WORK [ROUNDS [solves|amg|start]]
Appends its records to doc/results/pressure_options.jsonl and prints the tables.
"""
import json
import os
import re
import statistics
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
RECORDS = os.environ.get("RECORDS", os.path.join(HERE, "pressure_options.jsonl"))

# ML variants for amg_probe ("COARSE_SIZE:REPLICATE[:KEY=VALUE,...]", '_' for ' '); the first is
# fvfsi's LinearSolver as shipped (deal.II's elliptic set-up: Chebyshev of degree 2, threshold
# 0.02, smoothed aggregation, KLU below 2000 rows).
PROBE_VARIANTS = [
    ("shipped: Chebyshev degree 2", "2000:0"),
    ("Chebyshev degree 1", "2000:0:smoother:_sweeps=1"),
    ("Chebyshev degree 3", "2000:0:smoother:_sweeps=3"),
    ("symmetric Gauss-Seidel, 1 sweep", "2000:0:smoother:_type=symmetric_Gauss-Seidel,smoother:_sweeps=1"),
    ("symmetric Gauss-Seidel, 2 sweeps", "2000:0:smoother:_type=symmetric_Gauss-Seidel,smoother:_sweeps=2"),
    ("coarse size 500", "500:0"),
    ("coarse size 8000", "8000:0"),
    ("aggregation threshold 0.05", "2000:0:aggregation:_threshold=0.05"),
    ("plain aggregation (damping 0)", "2000:0:aggregation:_damping_factor=0.0"),
    ("W-cycle", "2000:0:prec_type=MGW"),
]

# BoomerAMG's strong thresholds for hypre_probe.
HYPRE_THRESHOLDS = [("hypre BoomerAMG (PETSc CG), strong threshold 0.25", "0.25"),
                    ("hypre BoomerAMG (PETSc CG), strong threshold 0.5", "0.5")]

# Whole runs: options the .prm file sets (none: the defaults), in two groups.
RUN_GROUPS = {}
RUN_GROUPS["solves"] = [
    ("defaults (2 non-orthogonal correctors)", []),
    ("Non-orthogonal correctors = 1", ["Fluid/Non-orthogonal correctors=1"]),
    ("Non-orthogonal correctors = 0", ["Fluid/Non-orthogonal correctors=0"]),
    ("AMG aggregation threshold = 0.05", ["Fluid pressure solver/AMG aggregation threshold=0.05"]),
    ("Preconditioner update interval = 1", ["Fluid/Preconditioner update interval=1"]),
    ("Preconditioner update interval = 50", ["Fluid/Preconditioner update interval=50"]),
]
# ML's options of the probe that fvfsi's LinearSolver exposes, alone and with no non-orthogonal
# corrector.
RUN_GROUPS["amg"] = [
    ("defaults (2 non-orthogonal correctors)", []),
    ("AMG smoother sweeps = 1", ["Fluid pressure solver/AMG smoother sweeps=1"]),
    ("AMG coarse size = 4000", ["Fluid pressure solver/AMG coarse size=4000"]),
    ("AMG smoother sweeps = 1, coarse size = 4000", ["Fluid pressure solver/AMG smoother sweeps=1",
                                                     "Fluid pressure solver/AMG coarse size=4000"]),
    ("Non-orthogonal correctors = 0", ["Fluid/Non-orthogonal correctors=0"]),
    ("Non-orthogonal correctors = 0, AMG smoother sweeps = 1", ["Fluid/Non-orthogonal correctors=0",
                                                                "Fluid pressure solver/AMG smoother sweeps=1"]),
]

# The start value of a step's first pressure solve (Fluid/Pressure extrapolation), with the
# file's one non-orthogonal corrector; the runs with every corrector solved to 1e-6 tell which
# start ends nearer the tightly solved step.
RUN_GROUPS["start"] = [
    ("the file (1 non-orthogonal corrector)", []),
    ("Pressure extrapolation = true", ["Fluid/Pressure extrapolation=true"]),
    ("Corrector residual reduction = 1e-6", ["Fluid pressure solver/Corrector residual reduction=1e-6"]),
    ("Pressure extrapolation = true, Corrector residual reduction = 1e-6",
     ["Fluid/Pressure extrapolation=true", "Fluid pressure solver/Corrector residual reduction=1e-6"]),
]


def machine():
    model = next(l.split(":", 1)[1].strip() for l in open("/proc/cpuinfo") if l.startswith("model name"))
    commit = subprocess.run(["git", "rev-parse", "--short", "HEAD"], capture_output=True, text=True).stdout.strip()
    return {"cpu": model, "cores": os.cpu_count(), "utc": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()), "commit": commit}


def append(records):
    with open(RECORDS, "a") as out:
        for r in records:
            out.write(json.dumps(r) + "\n")


def probe(amg_probe, hypre_probe, dump, repeats):
    env = dict(os.environ, VARIANTS=" ".join(v for _, v in PROBE_VARIANTS),
               THRESHOLDS=" ".join(v for _, v in HYPRE_THRESHOLDS))
    out = subprocess.run(["taskset", "-c", "0", amg_probe, dump, str(repeats)], env=env,
                         capture_output=True, text=True, check=True).stdout
    out += subprocess.run(["taskset", "-c", "0", hypre_probe, dump, str(repeats)], env=env,
                          capture_output=True, text=True, check=True).stdout
    # "ML, np 1, tol 0.01, coarse size 2000, ...: 5 CG iterations, 3.1 ms per solve (x1 of the first), set-up 12 ms"
    pattern = re.compile(r"tol ([0-9.e-]+), (.*): (\d+) CG iterations, ([0-9.e+-]+) ms per solve .*set-up ([0-9.e+-]+) ms")
    rows = {}
    for line in out.splitlines():
        m = pattern.search(line)
        if not m:
            continue
        tol, name, its, ms, setup = m.groups()
        rows.setdefault(name, {})[float(tol)] = (int(its), float(ms), float(setup))
    info = machine()
    records = []
    print(f"probe: {info}, {repeats} solves of each, one rank")
    print("| option | CG iterations (1e-2 / 1e-6) | ms per solve (1e-2 / 1e-6) | x of shipped | set-up [ms] |")
    print("|---|---|---|---|---|")
    names = list(rows)
    base = rows[names[0]]
    for (label, variant), name in zip(PROBE_VARIANTS + HYPRE_THRESHOLDS, names):
        r = rows[name]
        print(f"| {label} | {r[0.01][0]} / {r[1e-06][0]} | {r[0.01][1]:.2f} / {r[1e-06][1]:.2f} | "
              f"{r[0.01][1] / base[0.01][1]:.2f} / {r[1e-06][1] / base[1e-06][1]:.2f} | {r[0.01][2]:.1f} |")
        records.append({"part": "probe", "option": label, "variant": variant, **info, "repeats": repeats,
                        "iterations": [r[0.01][0], r[1e-06][0]], "ms": [r[0.01][1], r[1e-06][1]],
                        "setup_ms": r[0.01][2]})
    append(records)


def one_run(fvfsi, work, sets):
    out = os.path.join(work, "run")
    args = ["taskset", "-c", "0", fvfsi, "prm/turek_hron_cfd3.prm",
            "--set", "Mesh/Generator arguments=40", "--set", "Time/End time=0.1",
            "--set", "Time/Time step=0.00025",
            "--set", "Fluid/Velocity inlet=inlet: 1.5*2*4*y*(0.41-y)/0.41^2; 0",
            "--set", "Fluid scene/Output interval=0", "--set", "Output directory=" + out]
    for s in sets:
        args += ["--set", s]
    start = time.time()
    log = subprocess.run(args, capture_output=True, text=True, check=True).stdout
    wall = time.time() - start
    solve = float(re.search(r"\| pressure solve\s+\|\s+\d+ \|\s+([0-9.]+)s", log).group(1))
    m = re.search(r"fluid pressure: (\d+) linear solves, ([0-9.]+) iterations per solve", log)
    result = json.load(open(os.path.join(out, "summary.json")))["results"]
    return {"wall": wall, "pressure_solve": solve, "solves": int(m.group(1)),
            "iterations_per_solve": float(m.group(2)), "drag": result["drag"], "lift": result["lift"]}


def runs(fvfsi, work, rounds, group):
    RUN_OPTIONS = RUN_GROUPS[group]
    os.makedirs(work, exist_ok=True)
    info = machine()
    data = {label: [] for label, _ in RUN_OPTIONS}
    for _ in range(rounds):
        for label, sets in RUN_OPTIONS:
            data[label].append(one_run(fvfsi, work, sets))
    print(f"runs: {info}, {rounds} rounds, one rank, 400 steps at n = 40 (20 960 cells)")
    print("| option | pressure solves | CG iterations per solve | pressure solve [s] (median) | wall [s] (median) | x of defaults (wall) | drag change | lift change |")
    print("|---|---|---|---|---|---|---|---|")
    base = data[RUN_OPTIONS[0][0]]
    base_wall = statistics.median(r["wall"] for r in base)
    records = []
    for label, sets in RUN_OPTIONS:
        r = data[label]
        wall = statistics.median(x["wall"] for x in r)
        solve = statistics.median(x["pressure_solve"] for x in r)
        d_drag = (r[0]["drag"] - base[0]["drag"]) / abs(base[0]["drag"])
        d_lift = (r[0]["lift"] - base[0]["lift"]) / abs(base[0]["lift"])
        print(f"| {label} | {r[0]['solves']} | {r[0]['iterations_per_solve']:.2f} | {solve:.2f} | {wall:.2f} | "
              f"{wall / base_wall:.3f} | {d_drag:+.1e} | {d_lift:+.1e} |")
        records.append({"part": "runs", "group": group, "option": label, "sets": sets, **info, "runs": r})
    append(records)


if __name__ == "__main__":
    if len(sys.argv) < 4 or sys.argv[1] not in ("probe", "runs"):
        sys.exit(__doc__)
    if sys.argv[1] == "probe":
        probe(sys.argv[2], sys.argv[3], sys.argv[4], int(sys.argv[5]) if len(sys.argv) > 5 else 30)
    else:
        runs(sys.argv[2], sys.argv[3], int(sys.argv[4]) if len(sys.argv) > 4 else 3,
             sys.argv[5] if len(sys.argv) > 5 else "solves")
