#!/usr/bin/env bash
# Does a rank that waits in Open MPI by yielding the CPU (mpi_yield_when_idle) instead of polling
# make the two-rank run less sensitive to this VM's disturbances (doc/results/performance.md,
# section 8, "Waiting by yielding")? The first 40 steps of prm/turek_hron_fsi3.prm (10 steps of
# the fluid alone, 30 coupled), REPEATS rounds, each round running one rank on core 0, two ranks
# as `mpirun -np 2` and two ranks as `mpirun -np 2 --mca mpi_yield_when_idle 1`. Prints each
# run's coupled-step seconds and geometry section (local loops: the check on the moment) and
# the efficiency T1 / (2 T2) of every round. A completed run in RUN_DIRECTORY is not run again.
#   usage: doc/results/mpi_yield_probe.sh BUILD RUN_DIRECTORY REPEATS
#   (BUILD holds `fvfsi` and `libfvfsi_lib.so`, e.g. build/)
set -euo pipefail
cd "$(dirname "$0")/../.."
source doc/results/common.sh
dir=$1 runs=$2 repeats=$3
mkdir -p "$runs"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
machine_line
for r in $(seq 1 "$repeats"); do
  for mode in one poll yield; do
    out=$runs/${mode}_$r
    completed "$out" && continue
    case $mode in
      one) launch=(taskset -c 0) ;;
      poll) launch=(mpirun -np 2) ;;
      yield) launch=(mpirun -np 2 --mca mpi_yield_when_idle 1) ;;
    esac
    fsi3_first_steps 0.03 "$out"
    LD_LIBRARY_PATH=$dir "${launch[@]}" "$dir/fvfsi" "${fsi3_case[@]}" > "$out.log" 2>&1
  done
done
/usr/bin/python3 - "$runs" "$repeats" <<'PY'
import json, statistics, sys
runs, repeats = sys.argv[1], int(sys.argv[2])
s = {(m, r): json.load(open("%s/%s_%d/summary.json" % (runs, m, r)))
     for m in ("one", "poll", "yield") for r in range(1, repeats + 1)}
t = {m: [s[(m, r)]["results"]["coupled_wall_seconds"] for r in range(1, repeats + 1)]
     for m in ("one", "poll", "yield")}
for m in ("one", "poll", "yield"):
    print("%-5s coupled steps [s]: %s (median %.2f); geometry [s]: %s" % (
        m, ", ".join("%.2f" % x for x in t[m]), statistics.median(t[m]),
        ", ".join("%.2f" % s[(m, r)]["timing"]["geometry"] for r in range(1, repeats + 1))))
for m in ("poll", "yield"):
    e = [a / (2 * b) for a, b in zip(t["one"], t[m])]
    print("%-5s E per round: %s; median %.1f%%" % (
        m, ", ".join("%.0f%%" % (100 * x) for x in e), 100 * statistics.median(e)))
PY
