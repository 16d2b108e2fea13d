#!/usr/bin/env bash
# The parallel efficiency this machine allows a bulk-synchronous code (doc/results/log.md, "Again on
# the Intel Xeon, with the machine's own ceiling"): doc/benchmarks/bsp_ceiling.cc, a perfectly parallel stand-in for a linear solve on
# 47 104 cells (no halo, no serial part, the work split exactly in two) whose ranks meet in an
# MPI_Allreduce after every 1, 4 or 16 five-point sweeps (about 70, 280, 1100 us of work on one
# rank). Runs one and two ranks REPEATS times each, alternating, and prints the wall times, their
# medians and the efficiency T1 / (2 T2): below 100% only because the machine's two virtual CPUs
# do not run at the same speed at the same moment. Needs two free cores.
#   usage: doc/results/bsp_ceiling.sh [BUILD_DIRECTORY [REPEATS]]
set -euo pipefail
cd "$(dirname "$0")/../.."
source doc/results/common.sh
build=${1:-build}
repeats=${2:-5}
cmake --build "$build" --target bsp_ceiling > /dev/null
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
machine_line "commit $(git rev-parse --short HEAD)"
echo "| sweeps per meeting | one rank [s] (runs) | two ranks [s] (runs) | medians | efficiency |"
echo "|---|---|---|---|---|"
for sweeps in 1 4 16; do
  syncs=$((80000 / sweeps))
  t1=() t2=()
  for r in $(seq 1 "$repeats"); do
    for np in 1 2; do
      t=$(mpirun --oversubscribe -np "$np" "$build/doc/benchmarks/bsp_ceiling" \
            --sweeps-per-sync "$sweeps" --syncs "$syncs" | sed 's/.* wall \([0-9.]*\) .*/\1/')
      if [[ $np == 1 ]]; then t1+=("$t"); else t2+=("$t"); fi
    done
  done
  /usr/bin/python3 - "$sweeps" "${t1[*]}" "${t2[*]}" <<'PY'
import statistics, sys
sweeps, t1, t2 = sys.argv[1], [float(t) for t in sys.argv[2].split()], [float(t) for t in sys.argv[3].split()]
m1, m2 = statistics.median(t1), statistics.median(t2)
print("| %s | %s | %s | %.2f, %.2f | %.0f%% |" % (sweeps, ", ".join("%.2f" % t for t in t1),
      ", ".join("%.2f" % t for t in t2), m1, m2, 50 * m1 / m2))
PY
done
