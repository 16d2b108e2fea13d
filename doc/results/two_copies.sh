#!/usr/bin/env bash
# Two ranks against what the machine allows at that moment (doc/results/performance.md, section
# 8). Each round runs, one after another: the one-rank run alone on the first core (T1), the same
# case on two MPI ranks (T2; mpirun binds rank 0 to the first core, rank 1 to the second), and two
# copies of the one-rank run at once, one on each core (Tc0, Tc1: no communication between them,
# nothing shared but the machine: memory bandwidth, caches, and whatever else the host runs on
# the two cores). A two-rank run waits for its slower rank at every meeting, so the ceiling is
# set by the slower copy, Tc = max(Tc0, Tc1) (the two cores of this VM have run the same work up
# to 19% apart, in either direction, for minutes on end). Per round:
#   E = T1 / (2 T2)   the parallel efficiency;
#   C = T1 / Tc       what a perfectly balanced code without communication would reach on two
#                     ranks at that moment;
#   E / C = Tc / (2 T2), the efficiency against that ceiling: the code's share of what is lost.
# On a quiet machine C = 1 and E / C = E; when the host slows a core (seen on this VM: whole runs
# 20-30% apart within minutes), E falls with C and E / C does not. The case: the
# first 40 time steps of prm/turek_hron_fsi3.prm as shipped (fluid n = 60, 47 160 cells; flag
# 123 x 6), the coupling from step 11 on; END_TIME = 0.0825 gives the 110 steps of
# fsi_parallel.sh. Times are the coupled steps' (summary.json: coupled_wall_seconds). Needs two
# free cores.
#   usage: doc/results/two_copies.sh [path/to/fvfsi [RUN_DIRECTORY [ROUNDS [END_TIME]]]]
set -euo pipefail
cd "$(dirname "$0")/../.."
source doc/results/common.sh
fvfsi=${1:-build/fvfsi}
runs=${2:-build/two_copies}
rounds=${3:-3}
end_time=${4:-0.03}
mkdir -p "$runs"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
machine_line "commit $(git rev-parse --short HEAD)"
run() { # run NAME RANKS|coreN
  completed "$runs/$1" && return
  # One rank without mpirun, on the core named: two `mpirun -np 1` at once would both bind their
  # rank to core 0.
  local launch=(mpirun -np "$2")
  [[ $2 == core* ]] && launch=(taskset -c "${2#core}")
  local fsi3_case
  fsi3_first_steps "$end_time" "$runs/$1"
  "${launch[@]}" "$fvfsi" "${fsi3_case[@]}" > "$runs/$1.log" 2>&1
}
for r in $(seq 1 "$rounds"); do
  run "alone_$r" core0
  run "np2_$r" 2
  run "pair_a_$r" core0 & run "pair_b_$r" core1 & wait
done
/usr/bin/python3 - "$runs" "$rounds" <<'PY'
import json, statistics, sys
runs, rounds = sys.argv[1], int(sys.argv[2])
t = lambda name: json.load(open("%s/%s/summary.json" % (runs, name)))["results"]["coupled_wall_seconds"]
print("| round | T1 [s] | T2 [s] | Tc0, Tc1 [s] (two copies) | E = T1/(2 T2) | C = T1/max(Tc) | E/C |")
print("|---|---|---|---|---|---|---|")
E, C, R = [], [], []
for r in range(1, rounds + 1):
    t1, t2 = t("alone_%d" % r), t("np2_%d" % r)
    tc0, tc1 = t("pair_a_%d" % r), t("pair_b_%d" % r)
    tc = max(tc0, tc1)
    E.append(t1 / (2 * t2)); C.append(t1 / tc); R.append(tc / (2 * t2))
    print("| %d | %.2f | %.2f | %.2f, %.2f | %.0f%% | %.2f | %.0f%% |" % (r, t1, t2, tc0, tc1, 100 * E[-1], C[-1], 100 * R[-1]))
q = lambda x: "median %.0f%% (quartiles %.0f-%.0f%%)" % tuple(
    100 * v for v in [statistics.median(x)] + (statistics.quantiles(x, n=4)[::2] if len(x) > 1 else x * 2))
print("E: %s; C: median %.2f; E/C: %s" % (q(E), statistics.median(C), q(R)))
# The rounds in which the machine let two ranks run at (nearly) full speed.
quiet = [e for e, c in zip(E, C) if c >= 0.95]
print("rounds with C >= 0.95: %d, E %s" % (len(quiet), ", ".join("%.0f%%" % (100 * e) for e in quiet)))
PY
