#!/usr/bin/env bash
# Channel flow over a cavity with a flexible bottom (paper section 4.2): the mesh study of
# doc/results/cavity.md. prm/cavity_flexible_bottom.prm (steady FSI) on the paper's four cell sizes
# h = 0.1, 0.05, 0.025, 0.0125 m, fluid and plate meshes refined together; prints the markdown
# table (u_y(A), F_y, errors against the finest mesh, coupling iterations, fluid pseudo steps,
# solid outer iterations, wall time) and the observed orders of Eq. 34, writes
# doc/results/cavity_convergence.png and the "cavity" entry of doc/results/fsi_benchmarks.json.
# Each mesh finer than the first starts from the state of the one before (`Initial state from`,
# mesh sequencing), all with SIMPLEC (`Fluid/Consistent pressure coupling`, as shipped since
# the study; the study set it with --set): the steady fluid at h = 0.0125 oscillates with SIMPLE
# at alpha = 0.95 (cavity.md). Then the plate alone under a
# uniform traction on the same four meshes, with and without `Solid/Hessian correction`, for the
# order of its u_y(A). The shipped plate is graded (`fvfsi_cavity_plate` arguments `h: 1.25`) and
# solved by Newton's method; the study runs again with the uniform plate (segregated, as before
# 2026-12-03), with its Hessian correction, and with a stronger grading (beta = 1.5); the plate
# alone on uniform and graded meshes down to h = 0.003125. One MPI rank, Release build, one run
# at a time; about 45 minutes.
#   usage: doc/results/cavity.sh [path/to/fvfsi [RUN_DIRECTORY]]   (default: build/fvfsi, build/cavity_runs)
set -euo pipefail
python=${PYTHON:-/usr/bin/python3} # Debian's, with python3-numpy and python3-matplotlib
cd "$(dirname "$0")/../.."
source doc/results/common.sh
study_arguments build/cavity_runs "$@"
# chain PREFIX [SET...]: the four meshes, each from the state of the one before, with the extra
# --set overrides SET (and the plate graded with exponent $plate_grading if set); their records
# in $records.
chain() {
  local prefix=$1 previous="" h out
  shift
  records=()
  for h in 0.1 0.05 0.025 0.0125; do
    out=$runs/$prefix$h
    set=("Mesh/Generator arguments=$h" "Solid mesh/Generator arguments=$h${plate_grading:+: $plate_grading}" "$@")
    [[ -n $previous ]] && set+=("Initial state from=$previous")
    previous=$out
    args=(); for s in "${set[@]}"; do args+=(--set "$s"); done
    "$fvfsi" prm/cavity_flexible_bottom.prm "${args[@]}" --set "Output directory=$out" > "$out.log" 2>&1 \
      || { echo "h = $h failed, see $out.log"; exit 1; }
    "$python" doc/results/fsi_benchmark.py cavity-record "$h" "$out" "${set[@]}" > "$out.json"
    records+=("$out.json")
  done
}
# The study: the plate graded with beta = 1.25 and the Newton solid, as shipped.
plate_grading=1.25
chain h
"$python" doc/results/fsi_benchmark.py cavity-study doc/results/cavity_convergence.png "${records[@]}"
# The uniform plate with the segregated solid (the study before 2026-12-03), with and without the
# plate's Hessian correction (cavity["uniform_plate"], cavity["hessian_correction"] in the JSON).
plate_grading=""
chain uniform_h "Solid/Algorithm=segregated"
"$python" doc/results/fsi_benchmark.py cavity-variant uniform_plate "${records[@]}"
chain hessian_h "Solid/Hessian correction=true" "Solid/Algorithm=segregated"
"$python" doc/results/fsi_benchmark.py cavity-variant hessian_correction "${records[@]}"
# The plate graded more strongly, beta = 1.5 (cavity["graded_plate_1.5"]).
plate_grading=1.5
chain graded1.5_h
"$python" doc/results/fsi_benchmark.py cavity-variant graded_plate_1.5 "${records[@]}"

# The plate alone (Scene = solid) under the uniform traction 1.3 Pa on its wet surface (about the
# FSI's mean, F_y / 4 m): u_y(A) per uniform mesh, segregated solid, with and without the Hessian
# correction.
echo "| h [m] | solid cells | u_y(A) [m] | u_y(A), Hessian correction [m] |"
echo "|---|---|---|---|"
for h in 0.1 0.05 0.025 0.0125; do
  row="| $h"
  for hessian in false true; do
    out=$runs/solid_h${h}_hessian_$hessian
    "$fvfsi" prm/cavity_flexible_bottom.prm --set "Scene=solid" \
      --set "Mesh/Generator=fvfsi_cavity_plate" --set "Mesh/Generator arguments=$h" \
      --set "Mesh/Patch names=0: clamped, 1: bottom, 2: interface" \
      --set "Solid/External traction=" --set "Solid/Traction=bottom: 0; 0 | interface: 0; -1.3" \
      --set "Solid/Hessian correction=$hessian" --set "Solid/Algorithm=segregated" \
      --set "Output directory=$out" > "$out.log" 2>&1 \
      || { echo "solid h = $h failed, see $out.log"; exit 1; }
    [[ $hessian == false ]] && row+=" | $("$python" -c "import json,sys; print(json.load(open(sys.argv[1]))['n_cells'])" "$out/summary.json")"
    row+=" | $("$python" -c "import json,sys; print('%.7f' % json.load(open(sys.argv[1]))['results']['point_A_displacement'][1])" "$out/summary.json")"
  done
  echo "$row |"
done

# The plate alone again, Newton solid (Solid/Algorithm = coupled: the segregated solid fails on
# graded plates, cavity.md), one mesh finer (and the uniform plate two finer), uniform
# and graded (`fvfsi_cavity_plate` arguments `h: beta`, cells shrinking towards the clamped ends
# and both surfaces): the uniform plate's order over five meshes and the limit both reach.
echo
echo "| h [m] | solid cells | u_y(A) uniform [m] | graded beta = 1.25 [m] | graded beta = 1.5 [m] |"
echo "|---|---|---|---|---|"
for h in 0.1 0.05 0.025 0.0125 0.00625 0.003125; do
  row="| $h"
  for beta in 1 1.25 1.5; do
    [[ $h == 0.003125 && $beta != 1 ]] && { row+=" | "; continue; }
    out=$runs/solid_h${h}_beta$beta
    "$fvfsi" prm/cavity_flexible_bottom.prm --set "Scene=solid" \
      --set "Mesh/Generator=fvfsi_cavity_plate" --set "Mesh/Generator arguments=$h: $beta" \
      --set "Mesh/Patch names=0: clamped, 1: bottom, 2: interface" \
      --set "Solid/External traction=" --set "Solid/Traction=bottom: 0; 0 | interface: 0; -1.3" \
      --set "Solid/Algorithm=coupled" --set "Output directory=$out" > "$out.log" 2>&1 \
      || { echo "solid h = $h beta = $beta failed, see $out.log"; exit 1; }
    [[ $beta == 1 ]] && row+=" | $("$python" -c "import json,sys; print(json.load(open(sys.argv[1]))['n_cells'])" "$out/summary.json")"
    row+=" | $("$python" -c "import json,sys; print('%.9f' % json.load(open(sys.argv[1]))['results']['point_A_displacement'][1])" "$out/summary.json")"
  done
  echo "$row |"
done

