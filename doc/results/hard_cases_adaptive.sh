#!/usr/bin/env bash
# Adaptive time steps on the plate in a channel (prm/wall_plate_channel.prm, r = 3) from its
# impulsive start to t = 0.5 s (hard_cases.md, section 3): the fixed dt of the shipped file against
# Time/Adaptive = Courant and error from dt = 1e-4 s. Prints one JSON line per run: steps, drag at
# the end, wall seconds, correctors per step.
#   usage (from the project root): doc/results/hard_cases_adaptive.sh build/fvfsi [WORK]
set -euo pipefail
FV=$(realpath "${1:?usage: hard_cases_adaptive.sh FVFSI [WORK]}")
WORK=${2:-/tmp/hard_cases_adaptive}
mkdir -p "$WORK"
run() {
  local name=$1; shift
  local start end
  start=$(date +%s.%N)
  "$FV" prm/wall_plate_channel.prm "$@" --set "Fluid scene/Progress interval=100000" \
    --set "Output directory=$WORK/$name" > "$WORK/$name.log" 2>&1
  end=$(date +%s.%N)
  python3 - "$name" "$start" "$end" "$WORK/$name" <<'PY'
import json, os, sys
name, start, end, out = sys.argv[1:]
with open(os.path.join(out, "fluid_history.txt")) as f:
    names = f.readline().lstrip("#").split()
    rows = [dict(zip(names, map(float, l.split()))) for l in f if l.strip()]
print(json.dumps({"run": name, "steps": len(rows), "t_end": rows[-1]["t"], "drag": rows[-1]["drag"],
                  "max_courant": max(r["courant"] for r in rows), "dt_last": rows[-1]["dt"],
                  "correctors_mean": round(sum(r["correctors"] for r in rows) / len(rows), 2),
                  "wall_s": round(float(end) - float(start), 2)}), flush=True)
PY
}
run fixed_2.5ms
run courant_1 --set "Time/Time step=1e-4" --set "Time/Adaptive=Courant" --set "Time/Max Courant number=1"
run courant_4 --set "Time/Time step=1e-4" --set "Time/Adaptive=Courant" --set "Time/Max Courant number=4"
run error_1e-3 --set "Time/Time step=1e-4" --set "Time/Adaptive=error" --set "Time/Error tolerance=1e-3"
run error_1e-4 --set "Time/Time step=1e-4" --set "Time/Adaptive=error" --set "Time/Error tolerance=1e-4"
