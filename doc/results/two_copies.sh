#!/usr/bin/env bash
# What two ranks can gain on this machine at best (doc/results/performance.md, section 8): the
# same one-rank run alone, and two copies of it at once (no communication between them, nothing
# shared but the machine: memory bandwidth and caches). T_alone / T_pair is the efficiency a
# perfectly parallel code would reach on two ranks here. The case: the first 40 time steps of
# prm/turek_hron_fsi3.prm as shipped (fluid n = 60, 47 160 cells; flag 123 x 6), the coupling from
# step 11 on, as doc/results/fsi_parallel.sh but shorter. REPEATS alone runs and REPEATS pairs,
# alternating; prints each wall time (summary.json: wall_seconds), the medians and the ratio.
# Needs two free cores.
#   usage: doc/results/two_copies.sh [path/to/fvfsi [RUN_DIRECTORY [REPEATS]]]
set -euo pipefail
cd "$(dirname "$0")/../.."
fvfsi=${1:-build/fvfsi}
runs=${2:-build/two_copies}
repeats=${3:-3}
mkdir -p "$runs"
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); load: $(cut -d' ' -f1-3 /proc/loadavg); commit $(git rev-parse --short HEAD)"
run() { # run NAME: one rank into $runs/NAME
  "$fvfsi" prm/turek_hron_fsi3.prm --set "Coupling/Start time=0.0075" \
    --set "Time/End time=0.03" --set "Fluid scene/Output interval=0" \
    --set "Output directory=$runs/$1" > "$runs/$1.log" 2>&1
}
for r in $(seq 1 "$repeats"); do
  run "alone_$r"
  run "pair_a_$r" & run "pair_b_$r" & wait
done
/usr/bin/python3 - "$runs" "$repeats" <<'PY'
import json, statistics, sys
runs, repeats = sys.argv[1], int(sys.argv[2])
wall = lambda name: json.load(open("%s/%s/summary.json" % (runs, name)))["wall_seconds"]
alone = [wall("alone_%d" % r) for r in range(1, repeats + 1)]
pair = [wall("pair_%s_%d" % (x, r)) for r in range(1, repeats + 1) for x in "ab"]
print("| run | wall [s] (runs) | median |")
print("|---|---|---|")
print("| alone | %s | %.2f |" % (", ".join("%.2f" % t for t in alone), statistics.median(alone)))
print("| two copies at once | %s | %.2f |" % (", ".join("%.2f" % t for t in pair), statistics.median(pair)))
print("bound on the two-rank efficiency: T_alone / T_pair = %.2f"
      % (statistics.median(alone) / statistics.median(pair)))
PY
