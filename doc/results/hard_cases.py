#!/usr/bin/env python3
"""The hard-case matrix of doc/results/hard_cases.md: the rigid plate in a channel
(prm/wall_plate_channel.prm) run by fvfsi and, side by side on the same blocks, by OpenFOAM's
pimpleFoam (v1912 from Debian: apt-get install openfoam), at three refinements r, four largest
Courant numbers, impulsive and ramped inflow, on meshes of aspect ratio 4 (the tutorial's blocks)
and 15 (fewer columns, more rows). Each row: stable / stopped with a message / silent failure,
the drag at t = 0.5 s, its error against the finest run of its kind (fvfsi, r = 3, Courant 1),
PISO correctors per step, wall time.

usage (from the project root, after building): python3 doc/results/hard_cases.py FVFSI [WORK]
  FVFSI  the fvfsi executable (build/fvfsi)
  WORK   a scratch directory (default /tmp/hard_cases)
Environment: R="1 2 3", COURANT="1 4 10 20", INFLOW="impulsive ramped", ASPECT="4 15",
PEER=1 (0: fvfsi alone). Writes doc/results/hard_cases.json and prints the table's rows.
"""
import json
import os
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
FVFSI = os.path.abspath(sys.argv[1])
WORK = sys.argv[2] if len(sys.argv) > 2 else "/tmp/hard_cases"
END = 0.5


def blocks(r, aspect):
    """Cell counts (columns beside the plate, over it, rows up to y = 1, above) of a mesh."""
    return (30 * r, 3 * r, 15 * r, 30 * r) if aspect == 4 else (11 * r, 3 * r, 40 * r, 80 * r)


def inlet(inflow):
    return "10" if inflow == "impulsive" else "(t < 0.1 ? 100*t : 10)"


# dt that gives a largest Courant number of 1 near t = 0.5 s, per r, measured by calibrate().
def run_fvfsi(name, r, aspect, inflow, dt, extra=()):
    out = os.path.join(WORK, "fvfsi", name)
    os.makedirs(out, exist_ok=True)
    args = [FVFSI, os.path.join(ROOT, "prm", "wall_plate_channel.prm"),
            "--set", "Mesh/Generator arguments=%d: %d: %d: %d" % blocks(r, aspect),
            "--set", "Time/Time step=%.10g" % dt, "--set", "Time/End time=%g" % END,
            "--set", "Fluid/Velocity inlet=inlet: %s; 0" % inlet(inflow),
            "--set", "Fluid scene/Progress interval=100000", "--set", "Output directory=" + out]
    for e in extra:
        args += ["--set", e]
    start = time.time()
    p = subprocess.run(args, capture_output=True, text=True)
    wall = time.time() - start
    rows = []
    hist = os.path.join(out, "fluid_history.txt")
    if os.path.exists(hist):
        with open(hist) as f:
            names = f.readline().lstrip("#").split()
            rows = [dict(zip(names, map(float, line.split()))) for line in f if line.strip()]
    reached = bool(rows) and rows[-1]["t"] >= END - 1e-6 * dt
    message = ""
    if p.returncode != 0:
        message = (p.stderr.strip().splitlines() or ["(no message)"])[-1]
    status = "stable" if p.returncode == 0 and reached else (
        "stopped with a message" if p.returncode != 0 and message else "silent failure")
    # A run that exits 0 with an unbounded result would be a silent failure: the drag of the
    # plate stays below 1000 N/m in every stable run (it is 230 N/m at t = 0.5 s).
    if status == "stable" and not abs(rows[-1]["drag"]) < 1000:
        status = "silent failure"
    return {"code": "fvfsi", "status": status, "message": message, "wall_s": round(wall, 2),
            "steps": len(rows), "drag": rows[-1]["drag"] if rows else None,
            "max_courant": max(row["courant"] for row in rows) if rows else None,
            "courant_end": rows[-1]["courant"] if rows else None,
            "correctors_mean": (sum(row["correctors"] for row in rows) / len(rows)) if rows else None,
            "correctors_max": max(row["correctors"] for row in rows) if rows else None}


def openfoam_case(case, r, aspect, inflow, dt):
    """pimpleFoam on the same blocks: PISO, 4 correctors, backward, linearUpwind (as
    ../shared/peers/openfoam-plate/make_case.sh, with the counts of `blocks`)."""
    nx, npl, n1, n2 = blocks(r, aspect)
    os.makedirs(os.path.join(case, "0"), exist_ok=True)
    os.makedirs(os.path.join(case, "constant"), exist_ok=True)
    os.makedirs(os.path.join(case, "system"), exist_ok=True)

    def h(cls, obj):
        return "FoamFile { version 2.0; format ascii; class %s; object %s; }\n" % (cls, obj)

    v = [(-3, 0), (-0.05, 0), (0.05, 0), (3, 0), (-3, 1), (-0.05, 1), (0.05, 1), (3, 1),
         (-3, 4), (-0.05, 4), (0.05, 4), (3, 4)]
    vertices = " ".join("(%g %g 0)" % p for p in v) + " " + " ".join("(%g %g 1)" % p for p in v)
    with open(os.path.join(case, "system", "blockMeshDict"), "w") as f:
        f.write(h("dictionary", "blockMeshDict") + "vertices ( %s );\n" % vertices + """blocks (
 hex (0 1 5 4 12 13 17 16) (%d %d 1) simpleGrading (0.5 1 1)
 hex (2 3 7 6 14 15 19 18) (%d %d 1) simpleGrading (2 1 1)
 hex (4 5 9 8 16 17 21 20) (%d %d 1) simpleGrading (0.5 2 1)
 hex (5 6 10 9 17 18 22 21) (%d %d 1) simpleGrading (1 2 1)
 hex (6 7 11 10 18 19 23 22) (%d %d 1) simpleGrading (2 2 1) );
boundary (
 inlet { type patch; faces ((0 4 16 12) (4 8 20 16)); }
 outlet { type patch; faces ((3 7 19 15) (7 11 23 19)); }
 flap { type wall; faces ((1 5 17 13) (5 6 18 17) (6 2 14 18)); }
 upperWall { type wall; faces ((8 9 21 20) (9 10 22 21) (10 11 23 22)); }
 lowerWall { type wall; faces ((0 1 13 12) (2 3 15 14)); }
 frontAndBack { type empty; faces ((0 1 5 4) (2 3 7 6) (4 5 9 8) (5 6 10 9) (6 7 11 10)
   (12 13 17 16) (14 15 19 18) (16 17 21 20) (17 18 22 21) (18 19 23 22)); } );
""" % (nx, n1, nx, n1, nx, n2, npl, n2, nx, n2))
    inlet_value = ("fixedValue; value uniform (10 0 0)" if inflow == "impulsive" else
                   "uniformFixedValue; uniformValue table ((0 (0 0 0)) (0.1 (10 0 0)) "
                   "(100 (10 0 0)))")
    with open(os.path.join(case, "0", "U"), "w") as f:
        f.write(h("volVectorField", "U") + """dimensions [0 1 -1 0 0 0 0]; internalField uniform (0 0 0);
boundaryField { inlet { type %s; } outlet { type zeroGradient; }
 flap { type noSlip; } upperWall { type noSlip; } lowerWall { type noSlip; } frontAndBack { type empty; } }
""" % inlet_value)
    with open(os.path.join(case, "0", "p"), "w") as f:
        f.write(h("volScalarField", "p") + """dimensions [0 2 -2 0 0 0 0]; internalField uniform 0;
boundaryField { inlet { type zeroGradient; } outlet { type fixedValue; value uniform 0; }
 flap { type zeroGradient; } upperWall { type zeroGradient; } lowerWall { type zeroGradient; } frontAndBack { type empty; } }
""")
    with open(os.path.join(case, "constant", "transportProperties"), "w") as f:
        f.write(h("dictionary", "transportProperties") + "transportModel Newtonian; nu 1;\n")
    with open(os.path.join(case, "constant", "turbulenceProperties"), "w") as f:
        f.write(h("dictionary", "turbulenceProperties") + "simulationType laminar;\n")
    with open(os.path.join(case, "system", "fvSchemes"), "w") as f:
        f.write(h("dictionary", "fvSchemes") + """ddtSchemes { default backward; } gradSchemes { default Gauss linear; }
divSchemes { default none; div(phi,U) bounded Gauss linearUpwind grad(U); div((nuEff*dev2(T(grad(U))))) Gauss linear; }
laplacianSchemes { default Gauss linear corrected; } interpolationSchemes { default linear; } snGradSchemes { default corrected; }
""")
    with open(os.path.join(case, "system", "fvSolution"), "w") as f:
        f.write(h("dictionary", "fvSolution") + """solvers { p { solver PCG; preconditioner DIC; tolerance 1e-8; relTol 1e-3; } pFinal { $p; relTol 0; }
 "U.*" { solver smoothSolver; smoother symGaussSeidel; tolerance 1e-6; relTol 0; minIter 2; } }
PIMPLE { nCorrectors 4; nNonOrthogonalCorrectors 1; consistent true; momentumPredictor true; nOuterCorrectors 1; }
""")
    with open(os.path.join(case, "system", "controlDict"), "w") as f:
        f.write(h("dictionary", "controlDict") + """application pimpleFoam; startFrom startTime; startTime 0; stopAt endTime; endTime %g; deltaT %.10g;
writeControl timeStep; writeInterval 100000; purgeWrite 0; writeFormat ascii; writePrecision 8; runTimeModifiable false;
functions { forces { type forces; libs ("libforces.so"); patches (flap); rho rhoInf; rhoInf 1; CofR (0 0 0);
 writeControl timeStep; writeInterval 1; log false; } }
""" % (END, dt))
    subprocess.run(["blockMesh"], cwd=case, capture_output=True, check=True)


def run_openfoam(name, r, aspect, inflow, dt):
    case = os.path.join(WORK, "openfoam", name)
    subprocess.run(["rm", "-rf", case])
    openfoam_case(case, r, aspect, inflow, dt)
    start = time.time()
    p = subprocess.run(["pimpleFoam"], cwd=case, capture_output=True, text=True)
    wall = time.time() - start
    drag, t_last, courant = None, 0, []
    force = os.path.join(case, "postProcessing", "forces", "0", "force.dat")
    if os.path.exists(force):
        with open(force) as f:
            for line in f:
                if line.startswith("#"):
                    continue
                parts = line.replace("(", " ").replace(")", " ").split()
                t_last, drag = float(parts[0]), float(parts[1])
    for line in p.stdout.splitlines():
        if line.startswith("Courant Number mean"):
            courant.append(float(line.split()[-1]))
    # pimpleFoam stops at the last step before endTime - dt / 2, fvfsi at the first one past
    # endTime - 1e-6 dt: both within half a step of END.
    reached = t_last >= END - 0.5 * dt - 1e-9
    status = ("stable" if p.returncode == 0 and reached and drag is not None and abs(drag) < 1000
              else "stopped with a message" if p.returncode != 0 else "silent failure")
    message = "" if p.returncode == 0 else (
        "floating point exception" if "Floating point" in p.stdout + p.stderr else
        (p.stderr.strip().splitlines() or ["exit %d" % p.returncode])[-1])
    return {"code": "pimpleFoam", "status": status, "message": message, "wall_s": round(wall, 2),
            "t_end": t_last,
            "steps": len(courant), "drag": drag, "max_courant": max(courant) if courant else None,
            "courant_end": courant[-1] if courant else None}


def calibrate(r, aspect):
    """Courant number per second of time step near t = 0.5 s (one probe run)."""
    dt = 0.0025 * 3 / r * 0.25
    res = run_fvfsi("calibrate_r%d_a%d" % (r, aspect), r, aspect, "impulsive", dt)
    return res["courant_end"] / dt


def main():
    rs = [int(x) for x in os.environ.get("R", "1 2 3").split()]
    courants = [float(x) for x in os.environ.get("COURANT", "1 4 10 20").split()]
    inflows = os.environ.get("INFLOW", "impulsive ramped").split()
    aspects = [int(x) for x in os.environ.get("ASPECT", "4 15").split()]
    peer = os.environ.get("PEER", "1") == "1"
    cpu = subprocess.run("grep -m1 'model name' /proc/cpuinfo | cut -d: -f2", shell=True,
                         capture_output=True, text=True).stdout.strip()
    rows = []
    for aspect in aspects:
        for r in rs:
            rate = calibrate(r, aspect)
            for co in courants:
                dt = co / rate
                for inflow in inflows:
                    name = "r%d_a%d_co%g_%s" % (r, aspect, co, inflow)
                    case = {"r": r, "aspect": aspect, "courant_target": co, "inflow": inflow,
                            "dt": dt, "cells": 2790 * r * r if aspect == 4 else 2880 * r * r}
                    results = [run_fvfsi(name, r, aspect, inflow, dt)]
                    if peer:
                        results.append(run_openfoam(name, r, aspect, inflow, dt))
                    for res in results:
                        row = dict(case, **res)
                        rows.append(row)
                        print(json.dumps(row), flush=True)
    # Errors against the finest fvfsi run of each kind (largest r, smallest Courant number).
    for row in rows:
        refs = [x for x in rows if x["code"] == "fvfsi" and x["aspect"] == row["aspect"] and
                x["inflow"] == row["inflow"] and x["r"] == max(rs) and
                x["courant_target"] == min(courants) and x["status"] == "stable"]
        if refs and row["drag"] is not None and row["status"] == "stable":
            row["drag_error"] = row["drag"] / refs[0]["drag"] - 1
    with open(os.path.join(HERE, "hard_cases.json"), "w") as f:
        json.dump({"cpu": cpu, "command": "python3 doc/results/hard_cases.py build/fvfsi",
                   "end_time": END, "rows": rows}, f, indent=1)


if __name__ == "__main__":
    main()
