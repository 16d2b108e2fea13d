#!/usr/bin/env bash
# Parallel efficiency of the shipped FSI3 case (doc/results/log.md; its result: performance.md,
# section 8): the first
# 110 time steps of prm/turek_hron_fsi3.prm (fluid n = 60: 47 160 cells, flag 123 x 6: 738 cells,
# dt = 0.75 ms), the coupling from step 11 on (Coupling/Start time = 0.0075), on 1 and 2 MPI ranks
# (fluid and solid each decomposed by p4est on its own), REPEATS runs each, alternating. Prints
# the wall time of the coupled steps (summary.json: coupled_wall_seconds) and of the whole run,
# the medians, the speed-up and the efficiency T1 / (2 T2), and writes RUN_DIRECTORY/parallel.png
# (the seconds of each TimerOutput section on 1 and 2 ranks, median runs). Needs two free cores;
# a completed run in RUN_DIRECTORY is not run again. Arguments after REPEATS go to every run (e.g.
# --set "Solid/Algorithm=coupled").
#
# The two cores of a VM need not run at the same speed: on the AMD EPYC VM of log.md one
# of them ran the same one-rank work 19% slower than the other for minutes on end, then 2-5%. A
# two-rank run waits for its slower rank at every meeting, so each round also runs the one-rank
# case on the second core (`taskset -c 1`; `mpirun -np 1` binds to the first, as mpirun -np 2
# binds rank 0 to the first and rank 1 to the second). Per round: T1 = the faster of the two
# one-rank runs (the best serial time), E = T1 / (2 T2), the ceiling C = T1 / (the slower one):
# what a perfectly balanced code without communication would reach on the two cores as they ran
# then, and E / C. The one-rank runs on the two cores follow each other, so C also holds the
# drift between runs two minutes apart; two_copies.sh (removed from the tree in the commit after
# 8f61d2a; `git show 8f61d2a:doc/results/two_copies.sh` restores it) ran the two cores at the same moment.
#   usage: doc/results/fsi_parallel.sh [path/to/fvfsi [RUN_DIRECTORY [REPEATS [--set KEY=VALUE ...]]]]
set -euo pipefail
cd "$(dirname "$0")/../.."
source doc/results/common.sh
study_arguments build/fsi_parallel "${1:-}" "${2:-}"   # fvfsi, runs; the machine line
repeats=${3:-3}
shift $(( $# < 3 ? $# : 3 ))
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
for r in $(seq 1 "$repeats"); do
  for np in 1 2 core1; do
    out=$runs/np${np}_$r
    completed "$out" && continue
    launch=(mpirun --oversubscribe -np "$np")
    [[ $np == core1 ]] && launch=(taskset -c 1)
    fsi3_first_steps 0.0825 "$out"
    "${launch[@]}" "$fvfsi" "${fsi3_case[@]}" "$@" > "$out.log" 2>&1
  done
done
/usr/bin/python3 - "$runs" "$repeats" <<'PY'
import json, statistics, sys
runs, repeats = sys.argv[1], int(sys.argv[2])
t = {}
for np in (1, 2):
    s = [json.load(open("%s/np%d_%d/summary.json" % (runs, np, r))) for r in range(1, repeats + 1)]
    t[np] = (statistics.median(x["results"]["coupled_wall_seconds"] for x in s),
             statistics.median(x["wall_seconds"] for x in s),
             [round(x["results"]["coupled_wall_seconds"], 2) for x in s],
             s[0]["results"]["coupling_iterations"])
print("| ranks | coupled steps [s] (runs) | median | whole run [s] | coupling iterations |")
print("|---|---|---|---|---|")
for np in (1, 2):
    print("| %d | %s | %.2f | %.2f | %d |" % (np, ", ".join(map(str, t[np][2])), t[np][0], t[np][1], t[np][3]))
print("speed-up (coupled steps) %.2f, efficiency %.0f%%; whole run: %.2f, %.0f%%" % (
    t[1][0] / t[2][0], 50 * t[1][0] / t[2][0], t[1][1] / t[2][1], 50 * t[1][1] / t[2][1]))
# Each round's one- and two-rank runs follow each other within two minutes; their ratio is less
# exposed to the machine's drift (whole runs 20-30% apart within minutes) than the medians are.
pairs = sorted(50 * a / b for a, b in zip(t[1][2], t[2][2]))
q = statistics.quantiles(pairs, n=4) if len(pairs) > 1 else pairs * 3
print("efficiency of the %d pairs (T1 on core 0): median %.0f%%, quartiles %.0f%% - %.0f%%, range %.0f%% - %.0f%%" % (
    len(pairs), statistics.median(pairs), q[0], q[-1], pairs[0], pairs[-1]))

# Each round against the two cores' speeds in that round.
T = lambda name, r: json.load(open("%s/%s_%d/summary.json" % (runs, name, r)))["results"]["coupled_wall_seconds"]
def spread(x):
    q = statistics.quantiles(x, n=4) if len(x) > 1 else x * 3
    return "median %.0f%% (quartiles %.0f-%.0f%%)" % (100 * statistics.median(x), 100 * q[0], 100 * q[-1])
print("| round | T1 core 0 [s] | T1 core 1 [s] | T2 [s] | E = T1/(2 T2) | C = T1/T1(slower core) | E/C |")
print("|---|---|---|---|---|---|---|")
E, C, R = [], [], []
for r in range(1, repeats + 1):
    a, b, t2 = T("np1", r), T("npcore1", r), T("np2", r)
    E.append(min(a, b) / (2 * t2)); C.append(min(a, b) / max(a, b)); R.append(max(a, b) / (2 * t2))
    print("| %d | %.2f | %.2f | %.2f | %.0f%% | %.2f | %.0f%% |" % (r, a, b, t2, 100 * E[-1], C[-1], 100 * R[-1]))
print("E: %s; C: %s; E/C: %s" % (spread(E), spread(C), spread(R)))

# The sections of the median run of each rank count.
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
timing = {}
for np in (1, 2):
    s = [json.load(open("%s/np%d_%d/summary.json" % (runs, np, r))) for r in range(1, repeats + 1)]
    s.sort(key=lambda x: x["results"]["coupled_wall_seconds"])
    timing[np] = s[len(s) // 2]["timing"]
top = {k: v for k, v in timing[1].items() if ": " not in k}  # not the fluid's own sections
sections = [k for k in top if top[k] > 0.01 * sum(top.values())]
fig, ax = plt.subplots(figsize=(6, 3.5))
for i, np in enumerate((1, 2)):
    ax.bar([j + 0.4 * i for j in range(len(sections))], [timing[np][k] for k in sections], 0.4,
           label="%d rank%s" % (np, "s" if np > 1 else ""))
for j, k in enumerate(sections):
    ax.text(j + 0.2, max(timing[1][k], timing[2][k]), "%.0f%%" % (50 * timing[1][k] / timing[2][k]),
            ha="center", va="bottom", fontsize=8)
ax.set_xticks([j + 0.2 for j in range(len(sections))], sections, fontsize=8)
ax.set_ylabel("wall time [s]")
ax.set_title("FSI3 shipped, 110 steps: sections on 1 and 2 ranks (efficiency)", fontsize=9)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(runs + "/parallel.png", dpi=100)
print("wrote", runs + "/parallel.png")
PY
