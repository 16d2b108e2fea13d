#!/usr/bin/env bash
# The small-time-step instability of the elastic tube (doc/results/fsi_3d.md, "What made small
# time steps stable"): short runs of prm/elastic_tube.prm, mostly one refinement below the shipped
# meshes (480 fluid + 384 wall cells, 8 faces round the tube, 2 wall cells through its 1 mm),
# each printing the pressure on the axis 5 mm from the inlet at every time step. A run that
# oscillates from step to step with a growing amplitude is unstable (it stops when the wall
# diverges). Cost: about 3 min on one core.
#   usage: doc/results/fsi_3d_tube_stability.sh [path/to/fvfsi [RUN_DIRECTORY]]
set -euo pipefail
cd "$(dirname "$0")/../.."
source doc/results/common.sh
study_arguments build/fsi_3d_stability_runs "$@"
coarse=("Mesh/Global refinements=1" "Solid mesh/Global refinements=1")
vertex=("Coupling/Face average displacement=false")

# case NAME END_TIME [SET...]: the run, then "NAME: p(5 mm) [Pa] per step" (and how it stopped).
case_() {
  local name=$1 end=$2 args=()
  shift 2
  for s in "$@"; do args+=(--set "$s"); done
  "$fvfsi" prm/elastic_tube.prm "${args[@]}" --set "Time/End time=$end" \
    --set "Fluid scene/Output interval=0" --set "Output directory=$runs/$name" > "$runs/$name.log" 2>&1 || true
  # fsi_history.txt: column 12 is p at the first axis probe (5 mm)
  printf '%s: %s\n' "$name" "$(awk 'NR > 1 { printf "%.0f ", $12 }' "$runs/$name/fsi_history.txt")"
  if grep -q "FSI run stopped" "$runs/$name.log"; then echo "  (stopped: the wall diverged)"; fi
}

echo "== vertex values (the paper's transfer), BDF2, 8 faces round: the threshold"
case_ v_dt1.5e-4 0.004 "${coarse[@]}" "${vertex[@]}" "Time/Time step=1.5e-4"
case_ v_dt1.25e-4 0.004 "${coarse[@]}" "${vertex[@]}" "Time/Time step=1.25e-4"
case_ v_dt1e-4 0.0015 "${coarse[@]}" "${vertex[@]}"
echo "== vertex values, backward Euler (Time/Scheme): a lower threshold, not none"
case_ v_euler_dt1e-4 0.0015 "${coarse[@]}" "${vertex[@]}" "Time/Scheme=backward Euler"
case_ v_euler_dt5e-5 0.0015 "${coarse[@]}" "${vertex[@]}" "Time/Scheme=backward Euler" "Time/Time step=5e-5"
echo "== vertex values, dt = 1e-4 s: the wall's mesh decides, not the fluid's"
case_ v_fluid1_wall2 0.0012 "Mesh/Global refinements=1" "${vertex[@]}"
case_ v_fluid2_wall1 0.0012 "Solid mesh/Global refinements=1" "${vertex[@]}"
echo "== vertex values, the shipped meshes"
case_ v_shipped_dt5e-5 0.0015 "${vertex[@]}" "Time/Time step=5e-5"
case_ v_shipped_dt2.5e-5 0.0006 "${vertex[@]}" "Time/Time step=2.5e-5" "Coupling/Relaxation=0.01"
echo "== face average (shipped), 8 faces round"
case_ f_dt1e-4 0.002 "${coarse[@]}"
case_ f_dt5e-5 0.002 "${coarse[@]}" "Time/Time step=5e-5"
case_ f_dt2.5e-5 0.002 "${coarse[@]}" "Time/Time step=2.5e-5" "Coupling/Relaxation=0.01"
