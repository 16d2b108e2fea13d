#!/usr/bin/env python3
"""An FSI3 coupling iteration beside a fluid step (doc/results/performance.md, section 3).

prm/turek_hron_fsi3.prm at the paper's resolution (fluid n = 40: 20 960 cells, flag 82 x 4: 328
cells, dt = 0.75e-3 s), 50 time steps from rest, run two ways:
  coupled: Coupling/Start time = 0.0075 (10 steps of the fluid alone, then 40 coupled steps);
  fluid:   Coupling/Start time = 1      (50 steps of the fluid alone).
For each solid algorithm named on the command line, REPEATS runs of each, one at a time; prints
the per-coupling-iteration breakdown (medians) from the TimerOutput sections of summary.json
(`timing`) and the ratio of a coupling iteration to a fluid step.

  usage: doc/results/fsi_iteration_cost.py FVFSI RUN_DIRECTORY [REPEATS [ALGORITHM...]]
         (defaults: 3 repeats, algorithms segregated and coupled); RESOLUTION=shipped: the
         shipped meshes instead of the paper's
Also writes RUN_DIRECTORY/iteration_cost.png: the sections of a coupling iteration as stacked
bars per algorithm beside the fluid step alone and 1.3x it (issue 12's target). A completed run
in RUN_DIRECTORY is not run again.
"""
import json
import os
import statistics
import subprocess
import sys

# RESOLUTION=shipped in the environment: the shipped meshes (n = 60: 47 160 cells, flag 123 x 6:
# 738 cells; issue 56, item 4) instead of the paper's.
SHIPPED = os.environ.get("RESOLUTION") == "shipped"
COMMON = ([] if SHIPPED else ["Mesh/Generator arguments=40", "Solid mesh/Generator arguments=82: 4"]) + \
    ["Time/End time=0.0375", "Fluid scene/Output interval=0"]
FLUID_ALONE_STEPS_IN_COUPLED_RUN = 10
FLUID_ALONE_STEPS = 50
SECTIONS = ["fluid", "mesh motion", "geometry", "solid", "transfers + acceleration"]


def run(fvfsi, directory, sets):
    """Run fvfsi once (unless directory holds a completed run); return its summary.json."""
    summary = os.path.join(directory, "summary.json")
    if not os.path.exists(summary):
        arguments = [fvfsi, "prm/turek_hron_fsi3.prm"]
        for s in COMMON + sets + ["Output directory=" + directory]:
            arguments += ["--set", s]
        with open(directory + ".log", "w") as log:
            subprocess.run(arguments, stdout=log, stderr=subprocess.STDOUT, check=True)
    with open(summary) as f:
        return json.load(f)


def breakdown(coupled, fluid):
    """Seconds per coupling iteration by section, and the fluid step alone."""
    t, n = coupled["timing"], coupled["results"]["coupling_iterations"]
    fluid_step = fluid["timing"]["fluid"] / FLUID_ALONE_STEPS
    row = {
        "fluid": (t["fluid"] - FLUID_ALONE_STEPS_IN_COUPLED_RUN * fluid_step) / n,
        "mesh motion": t["mesh motion"] / n,
        "geometry": t["geometry"] / n,
        "solid": t["solid"] / n,
        "transfers + acceleration":
            (t["traction transfer"] + t["displacement transfer"] + t["acceleration"]) / n,
    }
    row["all"] = sum(row.values())
    # Everything of the coupled phase (also what the sections do not time), per iteration.
    row["coupled wall"] = coupled["results"]["coupled_wall_seconds"] / n
    row["fluid step"] = fluid_step
    row["iterations"] = n
    return row


def main():
    fvfsi, runs = sys.argv[1], sys.argv[2]
    repeats = int(sys.argv[3]) if len(sys.argv) > 3 else 3
    algorithms = sys.argv[4:] or ["segregated", "coupled"]
    os.makedirs(runs, exist_ok=True)
    print("| solid algorithm | " + " | ".join(SECTIONS) + " | all (timed) | coupled phase "
          "| fluid step alone | ratio (timed / coupled phase) | coupling iterations |")
    print("|---" * (len(SECTIONS) + 7) + "|")
    medians = {}
    for algorithm in algorithms:
        rows = []
        for r in range(repeats):
            solid = ["Solid/Algorithm=" + algorithm]
            base = os.path.join(runs, "%s_%d" % (algorithm, r))
            coupled = run(fvfsi, base + "_coupled", solid + ["Coupling/Start time=0.0075"])
            fluid = run(fvfsi, base + "_fluid", solid + ["Coupling/Start time=1"])
            rows.append(breakdown(coupled, fluid))
        med = {k: statistics.median(row[k] for row in rows) for k in rows[0]}
        medians[algorithm] = med
        ms = lambda x: "%.1f" % (1e3 * x)
        print("| %s | %s | %s | %s | %s | %.2f / %.2f | %d |" % (
            algorithm, " | ".join(ms(med[s]) for s in SECTIONS), ms(med["all"]),
            ms(med["coupled wall"]), ms(med["fluid step"]), med["all"] / med["fluid step"],
            med["coupled wall"] / med["fluid step"], med["iterations"]))
    plot(medians, os.path.join(runs, "iteration_cost.png"))


def plot(medians, png):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(6, 3.5))
    names = list(medians)
    for i, algorithm in enumerate(names):
        bottom = 0
        for j, section in enumerate(SECTIONS):
            height = 1e3 * medians[algorithm][section]
            ax.bar(i, height, bottom=bottom, color="C%d" % j, label=section if i == 0 else None)
            bottom += height
        step = 1e3 * medians[algorithm]["fluid step"]
        ax.hlines([step, 1.3 * step], i - 0.4, i + 0.4, colors="k", linestyles=["-", "--"])
    ax.set_xticks(range(len(names)), [n + " solid" for n in names])
    ax.set_ylabel("ms per coupling iteration")
    ax.set_title("FSI3, %s cells; lines: fluid step alone, 1.3x"
                 % ("47 160 + 738" if SHIPPED else "20 960 + 328"), fontsize=9)
    ax.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    fig.savefig(png, dpi=100)
    print("wrote", png)


if __name__ == "__main__":
    main()
