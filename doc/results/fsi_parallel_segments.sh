#!/usr/bin/env bash
# The whole shipped FSI3 run (prm/turek_hron_fsi3.prm: 5 s, 6 667 time steps, the coupling from
# 2 s on) on one and on two ranks, measured in segments so that the VM's drift falls on both alike
# (doc/results/performance.md, section 8). A whole run on one rank and then one on two ranks are
# 45 and 30 minutes apart, and this VM's speed changes by 20-30% within minutes; here the run is
# cut into segments of SEGMENT_STEPS time steps, and each segment runs twice, back to back, from
# the same checkpoint: once on one rank (`taskset -c 0`) and once on two (`mpirun -np 2`), the
# order swapped from one segment to the next. The two-rank run's checkpoint starts the next
# segment, so the segments follow one trajectory: the two-rank run's, restarted exactly (a restart
# continues a run to the last bit, tests/coupling/checkpoint_restart). Per segment and in all:
#   T1, T2  the time-step loop's wall time on one and two ranks: the sum of the scene's top-level
#           TimerOutput sections (summary.json `timing`: fluid, mesh motion, geometry, solid,
#           transfers, acceleration, step start copy; not the checkpoint), which covers all but
#           ~1% of a whole run's wall time (the set-up and the last output);
#   E = T1 / (2 T2), and the efficiency of the `geometry` section (local loops with no
#   communication: 93-133% when the machine is quiet, each half fitting the caches better)
#   as a check on the moment.
# Each run also pays a restart (meshes built, checkpoint read, ~3 s) and writes one; the table
# shows the processes' wall times too. Needs two free cores and ~80 minutes (AMD EPYC VM); a
# completed segment in RUN_DIRECTORY is not run again.
# More passes on the same segments: FROM_RUNS=<the first pass's RUN_DIRECTORY> starts every
# segment from that pass's checkpoints (the same work again); then
# doc/results/fsi_parallel_segments_median.py RUNS RUNS_2 RUNS_3 takes each segment's median one-
# and two-rank times over the passes (performance.md reports that figure). With FROM_RUNS,
# SEGMENTS="8 9 10" runs only those segments (a probe of a setting on part of the run; the
# tables and segments.json then cover only them).
# Writes RUN_DIRECTORY/segments.json: each segment's times and the sections summed over all.
#   usage: doc/results/fsi_parallel_segments.sh [path/to/fvfsi [RUN_DIRECTORY [SEGMENT_STEPS
#          [END_TIME [--set KEY=VALUE ...]]]]]   (END_TIME and the --set arguments: for a short
#          check of the script, e.g. 0.03 --set "Coupling/Start time=0.0075")
set -euo pipefail
cd "$(dirname "$0")/../.."
source doc/results/common.sh
fvfsi=${1:-build/fvfsi}
runs=${2:-build/fsi_parallel_segments}
seg=${3:-400}
end=${4:-5}
shift $(( $# < 4 ? $# : 4 ))
prm=prm/turek_hron_fsi3.prm
dt=0.00075
mkdir -p "$runs"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
[[ -x $fvfsi ]] || { echo "fsi_parallel_segments.sh: no executable $fvfsi" >&2; exit 1; }
machine_line "source tree at commit $(git rev-parse --short HEAD); binary $fvfsi"
n_steps=$(/usr/bin/python3 -c "import math; print(math.ceil($end / $dt - 1e-6))")
n_seg=$(( (n_steps + seg - 1) / seg ))
only=${SEGMENTS:-$(seq -s ' ' 1 "$n_seg")}
[[ -z ${SEGMENTS:-} || -n ${FROM_RUNS:-} ]] ||
  { echo "fsi_parallel_segments.sh: SEGMENTS needs FROM_RUNS (their checkpoints)" >&2; exit 1; }
run() { # run SEGMENT RANKS RESTART_DIRECTORY END_TIME [--set KEY=VALUE ...]
  local k=$1 np=$2 from=$3 end_k=$4
  shift 4
  local out=$runs/seg${k}_np$np
  completed "$out" && return
  local launch=(mpirun -np 2)
  [[ $np == 1 ]] && launch=(taskset -c 0)
  local restart=()
  [[ -n $from ]] && restart=(--set "Restart from=$from")
  local t0=$(date +%s.%N)
  if ! "${launch[@]}" "$fvfsi" "$prm" --set "Fluid scene/Output interval=0" \
    --set "Checkpoint interval=$seg" --set "Time/End time=$end_k" --set "Output directory=$out" \
    "${restart[@]}" "$@" > "$out.log" 2>&1; then
    echo "fsi_parallel_segments.sh: segment $k on $np rank(s) failed; see $out.log" >&2
    exit 1
  fi
  local t1=$(date +%s.%N)
  echo "$(/usr/bin/python3 -c "print('%.2f' % ($t1 - $t0))")" > "$out.wall"
  echo "$(date -u +%H:%M:%S) segment $k/$n_seg, $np rank(s): $(cat "$out.wall") s"
}
extra=("$@")
previous=""
for k in $(seq 1 "$n_seg"); do
  end_k=$(/usr/bin/python3 -c "print(min($end, round($k * $seg * $dt, 10)))")
  if (( k % 2 )); then order="1 2"; else order="2 1"; fi
  if [[ " $only " == *" $k "* ]]; then
    for np in $order; do run "$k" "$np" "$previous" "$end_k" "${extra[@]}"; done
  fi
  previous=${FROM_RUNS:-$runs}/seg${k}_np2
done
/usr/bin/python3 - "$runs" "$only" <<'PY'
import json, sys
runs, segments = sys.argv[1], [int(k) for k in sys.argv[2].split()]
load = lambda k, np: json.load(open("%s/seg%d_np%d/summary.json" % (runs, k, np)))
wall = lambda k, np: float(open("%s/seg%d_np%d.wall" % (runs, k, np)).read())
def loop_time(k, np):
    t = load(k, np)["timing"]
    return sum(v for key, v in t.items() if ":" not in key and key != "checkpoint")
print("| segment | last step | T1 [s] | T2 [s] | E | geometry E | process wall 1 / 2 ranks [s] |")
print("|---|---|---|---|---|---|---|")
S1 = S2 = W1 = W2 = 0.0
for k in segments:
    t1, t2 = loop_time(k, 1), loop_time(k, 2)
    g1, g2 = load(k, 1)["timing"].get("geometry", 0), load(k, 2)["timing"].get("geometry", 0)
    ge = "%.0f%%" % (100 * g1 / (2 * g2)) if g2 > 0 else "-"
    steps = load(k, 2)["results"]["time_steps"]
    S1 += t1; S2 += t2; W1 += wall(k, 1); W2 += wall(k, 2)
    print("| %d | %d | %.2f | %.2f | %.0f%% | %s | %.2f / %.2f |"
          % (k, steps, t1, t2, 100 * t1 / (2 * t2), ge, wall(k, 1), wall(k, 2)))
print("| all | | %.1f | %.1f | **%.1f%%** | | %.1f / %.1f (%.1f%%) |"
      % (S1, S2, 100 * S1 / (2 * S2), W1, W2, 100 * W1 / (2 * W2)))
sections = {}
for k in segments:
    for np in (1, 2):
        for key, v in load(k, np)["timing"].items():
            sections.setdefault(key, [0.0, 0.0])[np - 1] += v
print("\n| section (all segments) | one rank [s] | two ranks [s] | efficiency | lost on two ranks [s] |")
print("|---|---|---|---|---|")
for key, (a, b) in sorted(sections.items(), key=lambda kv: -(kv[1][1] - kv[1][0] / 2)):
    print("| %s | %.1f | %.1f | %.0f%% | %.1f |" % (key, a, b, 100 * a / (2 * b) if b else 0, b - a / 2))
json.dump({"segments": [{"segment": k, "loop_seconds": [loop_time(k, 1), loop_time(k, 2)],
                         "process_wall_seconds": [wall(k, 1), wall(k, 2)],
                         "timing": [load(k, 1)["timing"], load(k, 2)["timing"]],
                         "results": [load(k, 1)["results"], load(k, 2)["results"]]}
                        for k in segments],
           "sections": sections, "efficiency_loop": S1 / (2 * S2),
           "efficiency_process_wall": W1 / (2 * W2)},
          open("%s/segments.json" % runs, "w"), indent=1)
PY
