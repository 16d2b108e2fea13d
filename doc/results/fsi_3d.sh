#!/usr/bin/env bash
# The elastic tube (paper section 4.4) runs of doc/results/fsi_3d.md, one at a time on one rank
# unless stated: prm/elastic_tube.prm as shipped (3 840 fluid + 3 072 wall cells, dt = 1e-4 s, to
# 10 ms), dt = 2e-4 s, the temporal study (dt = 1e-4, 5e-5, 2.5e-5 s on the shipped mesh, all
# with Coupling/Relaxation = 0.01, which dt = 2.5e-5 s needs), the finer mesh (Global
# refinements 3 on both sides: 30 720 + 24 576 cells), and the parallel runs: the FSI case, the fluid alone
# (Scene = fluid, the walls rigid) and the wall alone (Scene = solid, the inlet pressure history
# on its inner surface) on 1 and 2 ranks, REPEATS each. Writes the markdown
# tables to stdout, doc/results/fsi_3d_tube.png and the "tube" entry of doc/results/fsi_3d.json.
# A completed run in RUN_DIRECTORY is not run again. Cost: about 35 min (measured: 66, 57, 735 s
# for the shipped, dt = 2e-4 s and refined runs, about 160, 260 and 510 s for the temporal study
# with another run beside, 137 s for the parallel ones); the parallel runs need
# two free cores (STAGE=serial runs the rest only, e.g. beside another job).
#   usage: [STAGE=serial] doc/results/fsi_3d.sh [path/to/fvfsi [RUN_DIRECTORY [REPEATS]]]
set -euo pipefail
cd "$(dirname "$0")/../.."
source doc/results/common.sh
python=${PYTHON:-/usr/bin/python3} # Debian's, with python3-numpy and python3-matplotlib
fvfsi=${1:-build/fvfsi}
runs=${2:-build/fsi_3d_runs}
repeats=${3:-3}
mkdir -p "$runs"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
machine_line "commit $(git rev-parse --short HEAD)"

# run NAME NP [SET...]: prm/elastic_tube.prm on NP ranks with the --set overrides into $runs/NAME.
run() {
  local name=$1 np=$2 out=$runs/$1 args=()
  shift 2
  for s in "$@"; do args+=(--set "$s"); done
  completed "$out" && return
  echo "$(date -u +%H:%M) $name: running (log $out.log)"
  mkdir -p "$out" && git rev-parse --short HEAD > "$out/commit.txt"
  mpirun --oversubscribe -np "$np" "$fvfsi" prm/elastic_tube.prm "${args[@]}" \
    --set "Fluid scene/Output interval=0" --set "Output directory=$out" > "$out.log" 2>&1
}
record() { # record NAME [SET...]
  local name=$1
  shift
  "$python" doc/results/fsi_3d.py tube-record "$runs/$name" prm/elastic_tube.prm "$@" > "$runs/$name.json"
}

order=("$runs/order_dt1e-4.json" "$runs/order_dt5e-5.json" "$runs/order_dt2.5e-5.json")
run shipped 1
run dt2e-4 1 "Time/Time step=2e-4"
for dt in 1e-4 5e-5 2.5e-5; do
  run "order_dt$dt" 1 "Coupling/Relaxation=0.01" "Time/Time step=$dt"
done
run refined 1 "Mesh/Global refinements=3" "Solid mesh/Global refinements=3"
record shipped
record dt2e-4 "Time/Time step=2e-4"
for dt in 1e-4 5e-5 2.5e-5; do
  record "order_dt$dt" "Coupling/Relaxation=0.01" "Time/Time step=$dt"
done
record refined "Mesh/Global refinements=3" "Solid mesh/Global refinements=3"
table() {
  "$python" doc/results/fsi_3d.py tube-table "$runs"/{dt2e-4,shipped,order_dt1e-4,order_dt5e-5,order_dt2.5e-5,refined}.json
  echo
  echo "temporal order of the peak radial displacement (dt = 1e-4, 5e-5, 2.5e-5 s): $("$python" doc/results/fsi_3d.py tube-order "${order[@]}")"
}
if [[ ${STAGE:-all} == serial ]]; then
  table
  exit 0
fi

# Parallel: 20 time steps (2 ms) of each; the fluid alone on rigid walls; the wall alone under
# the inlet pressure history on its inner surface (the case's fluid pressure at the inlet).
short=("Time/End time=0.002")
fluid=("Scene=fluid" "Mesh motion/Type=none")
solid=("Scene=solid" "Mesh/Generator=fvfsi_tube_wall" "Mesh/Generator arguments=0.005: 0.001: 0.05: 12"
       "Mesh/Patch names=0: inner, 1: outer, 2: ends" "Solid/External traction="
       "Solid/Pressure=inner: 1333.2*(t <= 0.003)" "Solid scene/Probes=A: 0.025, 0.005, 0")
for r in $(seq 1 "$repeats"); do
  for np in 1 2; do
    run "fsi_np${np}_$r" "$np" "${short[@]}"
    run "fluid_np${np}_$r" "$np" "${short[@]}" "${fluid[@]}"
    run "solid_np${np}_$r" "$np" "${short[@]}" "${solid[@]}"
  done
done

table
echo
"$python" doc/results/fsi_3d.py tube-parallel "$runs" "$repeats"
"$python" doc/results/fsi_3d.py tube-plot doc/results/fsi_3d_tube.png \
  "$runs/refined" "30 720 + 24 576 cells, dt = 1e-4 s" "$runs/shipped" "3 840 + 3 072 cells, dt = 1e-4 s" \
  "$runs/order_dt2.5e-5" "3 840 + 3 072 cells, dt = 2.5e-5 s"
"$python" doc/results/fsi_3d.py tube-store "$runs/shipped.json" --order "${order[@]}" \
  --runs "$runs/dt2e-4.json" "$runs/refined.json" --parallel "$runs" "$repeats"
