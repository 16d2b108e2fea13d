#!/usr/bin/env bash
# The shipped benchmarks before and after the self-converging PISO correctors (hard_cases.md,
# "The shipped cases before and after"): each case run with the correctors held at two
# (Fluid/Max pressure correctors = 2, the arithmetic of fvfsi before them: the same solver with a
# fixed count) and at the defaults, alternating, REPEATS times; prints wall seconds, the result
# and the correctors per step of each run.
#
#   usage (from the project root): doc/results/hard_cases_benchmarks.sh build/fvfsi [WORK] [REPEATS=3]
#   VARIANTS="default" runs the defaults alone (the guards' margins of section 4).
#
# Cases: CFD2 (steady: no correctors to adapt, the same arithmetic), CFD3's cost case of
# ../shared/peers/openfoam-cfd3/cost.sh (n = 40, dt = 2.5e-4 s, 400 steps, full inflow from rest),
# the default scene (prm/fsi_demo.prm), and 100 coupled steps of prm/turek_hron_fsi3.prm continued
# from a checkpoint at t = 2 s (written once by the default settings, 2 667 fluid-alone steps).
set -euo pipefail
FV=$(realpath "${1:?usage: hard_cases_benchmarks.sh FVFSI [WORK] [REPEATS]}")
WORK=${2:-/tmp/hard_cases_benchmarks}
REPEATS=${3:-3}
mkdir -p "$WORK"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# run NAME VARIANT ARGS...: one run; prints NAME VARIANT wall_s and the summary's results.
run() {
  local name=$1 variant=$2; shift 2
  local out="$WORK/$name-$variant"
  local extra=()
  [ "$variant" = fixed2 ] && extra=(--set "Fluid/Max pressure correctors=2")
  local start end
  start=$(date +%s.%N)
  "$FV" "$@" "${extra[@]}" --set "Output directory=$out" > "$out.log" 2>&1
  end=$(date +%s.%N)
  python3 - "$name" "$variant" "$start" "$end" "$out" <<'EOF'
import json, sys, os
name, variant, start, end, out = sys.argv[1:]
r = json.load(open(os.path.join(out, "summary.json"))).get("results", {})
keep = {k: r[k] for k in ("drag", "lift", "time_steps", "point_A_displacement",
                          "total_coupling_iterations", "max_velocity_over_scale",
                          "max_displacement_over_scale") if k in r}
hist = [f for f in ("fluid_history.txt", "fsi_history.txt") if os.path.exists(os.path.join(out, f))]
correctors = []
if hist:
    with open(os.path.join(out, hist[0])) as f:
        names = f.readline().lstrip("#").split()
        if "correctors" in names:
            i = names.index("correctors")
            correctors = [float(l.split()[i]) for l in f if l.strip()]
if correctors:
    keep["correctors_min_mean_max"] = [min(correctors), round(sum(correctors) / len(correctors), 3),
                                       max(correctors)]
print(json.dumps({"case": name, "variant": variant, "wall_s": round(float(end) - float(start), 2),
                  **keep}), flush=True)
EOF
}

FSI3_CHECKPOINT="$WORK/fsi3-t2"
if [ ! -f "$FSI3_CHECKPOINT/checkpoint/state" ]; then
  "$FV" prm/turek_hron_fsi3.prm --set "Time/End time=2" --set "Checkpoint interval=2667" \
    --set "Fluid scene/Output interval=0" --set "Output directory=$FSI3_CHECKPOINT" \
    > "$FSI3_CHECKPOINT.log" 2>&1
fi

CFD3=(prm/turek_hron_cfd3.prm --set "Mesh/Generator arguments=40" --set "Time/Time step=0.00025"
      --set "Time/End time=0.1" --set "Fluid/Velocity inlet=inlet: 1.5*2*4*y*(0.41-y)/0.41^2; 0"
      --set "Fluid scene/Output interval=0")
FSI3=(prm/turek_hron_fsi3.prm --set "Restart from=$FSI3_CHECKPOINT" --set "Time/End time=2.075"
      --set "Fluid scene/Output interval=0")
for k in $(seq "$REPEATS"); do
  for variant in ${VARIANTS:-fixed2 default}; do
    run cfd2 "$variant" prm/turek_hron_cfd2.prm
    run cfd3_cost "$variant" "${CFD3[@]}"
    run fsi_demo "$variant" prm/fsi_demo.prm
    run fsi3_coupled_100 "$variant" "${FSI3[@]}"
  done
done
