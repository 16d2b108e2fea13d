#!/usr/bin/env bash
# The thick plate in a channel (paper section 4.5) runs of doc/results/fsi_3d.md, one at a time on
# one rank unless stated: prm/thick_plate.prm as shipped (steady FSI; fluid h = 0.0125 m, 45 056
# cells; plate h = 0.00625 m, 16 384 cells) and on two coarser meshes (fluid h = 0.05, 0.025 with
# the plate at h / 2); the plate alone under a uniform pressure on its upstream face on four meshes
# with the paper's face gradient and with Demirdzic-Muzaferija's (the solid's own convergence);
# the large-deformation variant (peak inflow 0.3 m/s, E = 1e4 Pa) on the shipped and the middle
# mesh; the temporal-order variant (transient, the inflow ramped to its peak at 0.1 s, u_x(A) at
# t = 0.08 s and its history, dt = 5e-3 ... 3.125e-4 s, fluid h = 0.025, plate h = 0.0125); the shipped case on 2
# ranks. Writes the markdown tables to stdout and the "plate" entry of doc/results/fsi_3d.json. A
# completed run in RUN_DIRECTORY is not run again. Cost: about 20 min on one core (measured: 194 s
# shipped, 195 s large deformation shipped, 150 s for the temporal runs).
#   usage: doc/results/fsi_3d_plate.sh [path/to/fvfsi [RUN_DIRECTORY]]
set -euo pipefail
cd "$(dirname "$0")/../.."
source doc/results/common.sh
python=${PYTHON:-/usr/bin/python3}
study_arguments build/fsi_3d_plate_runs "$@"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

# run NAME NP PRM [SET...]: PRM on NP ranks with the --set overrides into $runs/NAME, then its
# record $runs/NAME.json.
run() {
  local name=$1 np=$2 prm=$3 out=$runs/$1 args=()
  shift 3
  for s in "$@"; do args+=(--set "$s"); done
  if ! completed "$out"; then
    echo "$(date -u +%H:%M) $name: running (log $out.log)"
    mkdir -p "$out" && git rev-parse --short HEAD > "$out/commit.txt"
    mpirun --oversubscribe -np "$np" "$fvfsi" "$prm" "${args[@]}" \
      --set "Output directory=$out" > "$out.log" 2>&1
  fi
  "$python" doc/results/fsi_3d_plate.py record "$out" "$prm" "$@" > "$out.json"
}

run h0.05 1 prm/thick_plate.prm "Mesh/Generator arguments=0.05" "Solid mesh/Generator arguments=0.025"
run h0.025 1 prm/thick_plate.prm "Mesh/Generator arguments=0.025" "Solid mesh/Generator arguments=0.0125"
run shipped 1 prm/thick_plate.prm

# The plate alone: scene solid on the plate mesh, 10 Pa on the upstream face x = 0.45 m.
solid=("Scene=solid" "Mesh/Generator=fvfsi_thick_plate" "Mesh/Patch names=0: clamped, 1: symmetry, 2: interface"
       "Solid/External traction=" "Solid/Traction=interface: -10*(x<0.4501); 0; 0")
for variant in present Demirdzic-Muzaferija; do
  for h in 0.05 0.025 0.0125 0.00625; do
    run "solid_${variant}_$h" 1 prm/thick_plate.prm "${solid[@]}" "Mesh/Generator arguments=$h" "Solid/Variant=$variant"
  done
done

large=("Solid/Young's modulus=1e4" "Fluid/Velocity inlet=inlet: 0.3*y*(0.4-y)*(0.16-z^2)/(0.04*0.16); 0; 0")
run large_h0.025 1 prm/thick_plate.prm "${large[@]}" "Mesh/Generator arguments=0.025" "Solid mesh/Generator arguments=0.0125"
run large 1 prm/thick_plate.prm "${large[@]}"

temporal=("Fluid/Transient=true" "Solid/Transient=true" "Time/End time=0.08" "Fluid/Pressure correctors=2"
          "Coupling/Reuse time steps=3" "Mesh/Generator arguments=0.025" "Solid mesh/Generator arguments=0.0125"
          "Fluid/Velocity inlet=inlet: 0.2*(1-cos(pi*min(t,0.1)/0.1))/2*y*(0.4-y)*(0.16-z^2)/(0.04*0.16); 0; 0")
for dt in 0.005 0.0025 0.00125 0.000625 0.0003125; do
  run "temporal_dt$dt" 1 prm/thick_plate.prm "${temporal[@]}" "Time/Time step=$dt"
done

run shipped_np2 2 prm/thick_plate.prm

"$python" doc/results/fsi_3d_plate.py table "$runs"/{h0.05,h0.025,shipped,shipped_np2}.json
echo
echo "observed order (Eq. 34) from the three meshes: u_x(A) $("$python" doc/results/fsi_3d_plate.py order ux_A "$runs"/{h0.05,h0.025,shipped}.json), F_x $("$python" doc/results/fsi_3d_plate.py order Fx "$runs"/{h0.05,h0.025,shipped}.json)"
echo
"$python" doc/results/fsi_3d_plate.py solid-table "$runs"/solid_present_{0.05,0.025,0.0125,0.00625}.json \
  "$runs"/solid_Demirdzic-Muzaferija_{0.05,0.025,0.0125,0.00625}.json
echo
"$python" doc/results/fsi_3d_plate.py large-table "$runs"/{large_h0.025,large}.json
echo
for dt in 0.005 0.0025 0.00125 0.000625 0.0003125; do
  echo "dt = $dt s: u_x(A, 0.08 s) = $(jq .ux_A "$runs/temporal_dt$dt.json") m, F_x = $(jq .Fx "$runs/temporal_dt$dt.json") N, $(jq .wall_seconds "$runs/temporal_dt$dt.json") s"
done
echo "temporal orders of u_x(A, 0.08 s) (consecutive triples): $("$python" doc/results/fsi_3d_plate.py order ux_A "$runs"/temporal_dt{0.005,0.0025,0.00125,0.000625,0.0003125}.json)"
echo "u_x(A)(t) against dt = 3.125e-4 s: $("$python" doc/results/fsi_3d_plate.py history-order "$runs"/temporal_dt{0.005,0.0025,0.00125,0.000625,0.0003125}.json)"
"$python" doc/results/fsi_3d_plate.py store "$runs/shipped.json" --runs "$runs"/{h0.05,h0.025,shipped_np2}.json \
  --large "$runs"/{large_h0.025,large}.json --temporal "$runs"/temporal_dt{0.005,0.0025,0.00125,0.000625,0.0003125}.json
