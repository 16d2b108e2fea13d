"""Tables of doc/results/solid_coupled.md from the runs of solid_coupled.sh.

    python3 doc/results/solid_coupled.py OUT

A case NAME has up to three runs OUT/NAME/1..3 (summary.json, log, rc = exit status); wall
times are the median of the runs, other values those of the first run.
"""
import json
import os
import statistics
import sys
from pathlib import Path

out = Path(sys.argv[1])
TIP_EXACT = -1.60275e-2  # exact Timoshenko u_y(2, 0) of prm/cantilever.prm [m]
CSM1_A = (-7.187e-3, -66.10e-3)  # Turek & Hron (2006) CSM1, u(A) [m]


def runs(name):
    """The summaries of the successful runs of NAME, and the first run's exit status and log."""
    dirs = sorted((out / name).glob("[123]"))
    if not dirs or not (dirs[0] / "rc").exists():
        return [], None, ""
    rc = int((dirs[0] / "rc").read_text())
    summaries = []
    for d in dirs:
        if (d / "rc").read_text().strip() != "0":
            continue
        summaries.append(json.loads((d / "summary.json").read_text()))
        cpu = d / "cpu"  # user and system seconds (older runs have none)
        if cpu.exists():
            summaries[-1]["cpu_seconds"] = sum(map(float, cpu.read_text().split()[-2:]))
    return summaries, rc, (dirs[0] / "log").read_text()


def wall(summaries):
    """Wall time [s] (and CPU time where measured), median of the runs."""
    times = [s["wall_seconds"] for s in summaries]
    label = "median of 3" if len(times) == 3 else "1 run"
    text = f"{statistics.median(times):.2f}"
    if all("cpu_seconds" in s for s in summaries):
        text += f" (CPU {statistics.median(s['cpu_seconds'] for s in summaries):.2f})"
    return f"{text}, {label}"


# The wall-time cap of the runs (solid_coupled.sh: CAP, default 180 s).
CAP = os.environ.get("CAP", "180")


def failure(rc, log):
    if rc is None:
        return "not run"
    if rc == 124:
        progress = [line for line in log.splitlines() if "outer iteration" in line]
        if not progress:
            return f"stopped at the {CAP} s cap"
        words = progress[-1].replace(":", "").split()
        k = words[words.index("iteration") + 1]
        change = words[words.index("change") + 1]
        return f"stopped at the {CAP} s cap: {k} outer iterations, relative change {change}"
    last = [line for line in log.splitlines() if "did not converge" in line or "error" in line]
    return "failed: " + (last[-1].strip() if last else f"exit status {rc}")


def cantilever():
    print("| mesh | cells | coupled: Newton its | tip u_y error | wall [s] |"
          " segregated: outer its | tip u_y error | wall [s] |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for r in range(4):
        row = [f"{40 << r} x {2 << r}", str(80 << (2 * r))]
        for algorithm in ("coupled", "segregated"):
            summaries, rc, log = runs(f"cantilever_r{r}_{algorithm}")
            if not summaries:
                row += [failure(rc, log), "-", "-"]
                continue
            res = summaries[0]["results"]
            u_y = res["point_tip_displacement"][1]
            row += [str(res["outer_iterations"]), f"{100 * (u_y / TIP_EXACT - 1):+.3f}%",
                    wall(summaries)]
        print("| " + " | ".join(row) + " |")


def table(header, names, row):
    """A markdown table: `header` (its first columns case and algorithm), then per
    (case, algorithm, NAME) the cells row(summaries) of the runs of NAME, or why there are none."""
    print("| " + " | ".join(header) + " |")
    print("|---|---|" + "---:|" * (len(header) - 2))
    for case, algorithm, name in names:
        summaries, rc, log = runs(name)
        cells = row(summaries) if summaries else [failure(rc, log)] + [""] * (len(header) - 3)
        print(f"| {case} | {algorithm} | " + " | ".join(cells) + " |")


def steady_row(summaries):
    res = summaries[0]["results"]
    a = res["point_A_displacement"]
    return [str(res["outer_iterations"]), f"{a[0]:.4e}", f"{100 * (a[0] / CSM1_A[0] - 1):+.2f}%",
            f"{a[1]:.4e}", f"{100 * (a[1] / CSM1_A[1] - 1):+.2f}%", wall(summaries)]


def timed_row(summaries):
    s = summaries[0]
    res = s["results"]
    if "point_A_displacement" in res:
        result = "u(A) = ({:.5e}, {:.5e}) m".format(*res["point_A_displacement"])
    else:
        result = f"max displacement error {res['max_displacement_error']:.4e} m"
    return [str(res["outer_iterations"]), str(s["n_cells"]), str(res["time_steps"]), result,
            wall(summaries)]


def fsi_row(summaries):
    s = summaries[0]
    res, t = s["results"], s["timing"]
    k = res["coupling_iterations"]
    return [str(res["coupled_time_steps"]), str(k), f"{res['solid_outer_iterations'] / k:.1f}",
            f"{t['solid']:.2f}", f"{1000 * t['solid'] / k:.1f}",
            f"{100 * t['solid'] / res['coupled_wall_seconds']:.1f}%", f"{t['fluid']:.1f}",
            f"{t['mesh motion']:.1f}", wall(summaries),
            "({:.5e}, {:.5e})".format(*res["point_A_displacement"])]


print("## Cantilever\n")
cantilever()
print("\n## CSM1\n")
table(["case", "algorithm", "iterations", "u_x(A) [m]", "error", "u_y(A) [m]", "error",
       "wall [s]"],
      [("CSM1 280 x 16", "coupled", "csm1_coupled"),
       ("CSM1 280 x 16", "coupled, Jacobian-free", "csm1_coupled_jfnk"),
       ("CSM1 280 x 16", "segregated", "csm1_segregated")], steady_row)
print("\n## CSM3 (first second) and plate with a hole\n")
table(["case", "algorithm", "iterations", "cells", "time steps", "result", "wall [s]"],
      [("CSM3 120 x 4, t <= 1 s", "coupled", "csm3_coupled"),
       ("CSM3 120 x 4, t <= 1 s", "segregated", "csm3_segregated"),
       ("plate with a hole, n = 179", "coupled", "plate_hole_64k_coupled"),
       ("plate with a hole, n = 179", "segregated", "plate_hole_64k_segregated")], timed_row)
print("\n## The sparse direct solver of the Newton systems\n")
table(["case", "algorithm", "iterations", "cells", "time steps", "result", "wall [s]"],
      [("plate with a hole, n = 90", "coupled, UMFPACK", "plate_hole_16k_coupled"),
       ("plate with a hole, n = 90", "coupled, KLU", "plate_hole_16k_klu"),
       ("plate with a hole, n = 90", "segregated", "plate_hole_16k_segregated"),
       ("plate with a hole, n = 179", "coupled, KLU", "plate_hole_64k_klu"),
       ("thick plate alone (3D)", "coupled, UMFPACK", "thick_plate_coupled"),
       ("thick plate alone (3D)", "coupled, KLU", "thick_plate_klu"),
       ("thick plate alone (3D)", "segregated", "thick_plate_segregated"),
       ("CSM1 280 x 16", "coupled, KLU", "csm1_klu")], timed_row)
print("\n## FSI\n")
table(["case", "solid algorithm", "coupled steps", "coupling its", "solid its per coupling it",
       "solid [s]", "solid per coupling it [ms]", "solid share of coupled steps", "fluid [s]",
       "mesh motion [s]", "wall [s]", "u(A) [m]"],
      [("FSI3, dt = 0.75 ms", "segregated", "fsi3_segregated"),
       ("FSI3, dt = 0.75 ms", "coupled", "fsi3_coupled"),
       ("quasi-steady flag, dt = 10 ms", "segregated", "fsi1_dt10ms_segregated"),
       ("quasi-steady flag, dt = 10 ms", "coupled", "fsi1_dt10ms_coupled")], fsi_row)
