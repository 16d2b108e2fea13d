#!/usr/bin/env bash
# How fast each of the machine's two cores runs, moment by moment, while both are busy
# (doc/results/performance.md, section 8): the same chunk of work (core_speed_probe.c, on an
# array of ARRAY_MB megabytes: 4 stays in the caches, 256 streams from memory) again and again on
# core 0 and on core 1 at once for DURATION seconds, then core_speed_probe.py's table per WINDOW
# seconds. A two-rank run waits for its slower rank at every meeting, so the slower core's speed
# is what two ranks can reach at that moment. Needs two free cores and a C compiler.
#   usage: doc/results/core_speed_probe.sh [DURATION [ARRAY_MB [WINDOW [RUN_DIRECTORY]]]]
set -euo pipefail
cd "$(dirname "$0")/../.."
source doc/results/common.sh
duration=${1:-300}
array_mb=${2:-4}
window=${3:-10}
runs=${4:-build/core_speed_probe}
mkdir -p "$runs"
machine_line "array $array_mb MB"
cc -O2 -o "$runs/core_speed_probe" doc/results/core_speed_probe.c
taskset -c 0 "$runs/core_speed_probe" "$duration" "$array_mb" > "$runs/core0.txt" 2> /dev/null &
taskset -c 1 "$runs/core_speed_probe" "$duration" "$array_mb" > "$runs/core1.txt" 2> /dev/null &
wait
python3 doc/results/core_speed_probe.py "$runs/core0.txt" "$runs/core1.txt" "$window"
