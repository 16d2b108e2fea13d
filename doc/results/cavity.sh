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
# order of its u_y(A); and the FSI study again with the Hessian correction. One MPI rank, Release
# build, one run at a time; about 20 minutes.
#   usage: doc/results/cavity.sh [path/to/fvfsi [RUN_DIRECTORY]]   (default: build/fvfsi, build/cavity_runs)
set -euo pipefail
python=${PYTHON:-/usr/bin/python3} # Debian's, with python3-numpy and python3-matplotlib
cd "$(dirname "$0")/../.."
fvfsi=${1:-build/fvfsi}
runs=${2:-build/cavity_runs}
mkdir -p "$runs"
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); load: $(cut -d' ' -f1-3 /proc/loadavg); commit $(git rev-parse --short HEAD)"
# chain PREFIX [SET...]: the four meshes, each from the state of the one before, with the extra
# --set overrides SET; their records in $records.
chain() {
  local prefix=$1 previous="" h out
  shift
  records=()
  for h in 0.1 0.05 0.025 0.0125; do
    out=$runs/$prefix$h
    set=("Mesh/Generator arguments=$h" "Solid mesh/Generator arguments=$h" "$@")
    [[ -n $previous ]] && set+=("Initial state from=$previous")
    previous=$out
    args=(); for s in "${set[@]}"; do args+=(--set "$s"); done
    "$fvfsi" prm/cavity_flexible_bottom.prm "${args[@]}" --set "Output directory=$out" > "$out.log" 2>&1 \
      || { echo "h = $h failed, see $out.log"; exit 1; }
    "$python" doc/results/fsi_benchmark.py cavity-record "$h" "$out" "${set[@]}" > "$out.json"
    records+=("$out.json")
  done
}
chain h
"$python" doc/results/fsi_benchmark.py cavity-study doc/results/cavity_convergence.png "${records[@]}"
# The same with the plate's Hessian correction (cavity["hessian_correction"] in the JSON).
chain hessian_h "Solid/Hessian correction=true"
"$python" doc/results/fsi_benchmark.py cavity-variant hessian_correction "${records[@]}"

# The plate alone (Scene = solid) under the uniform traction 1.3 Pa on its wet surface (about the
# FSI's mean, F_y / 4 m): u_y(A) per mesh, with and without the Hessian correction.
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
      --set "Solid/Hessian correction=$hessian" --set "Output directory=$out" > "$out.log" 2>&1 \
      || { echo "solid h = $h failed, see $out.log"; exit 1; }
    [[ $hessian == false ]] && row+=" | $("$python" -c "import json,sys; print(json.load(open(sys.argv[1]))['n_cells'])" "$out/summary.json")"
    row+=" | $("$python" -c "import json,sys; print('%.7f' % json.load(open(sys.argv[1]))['results']['point_A_displacement'][1])" "$out/summary.json")"
  done
  echo "$row |"
done
