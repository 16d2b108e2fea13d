#!/usr/bin/env bash
# FSI3 at the shipped accuracy in less time (issue 56, item 3): prm/turek_hron_fsi3.prm as shipped
# beside the same file with the levers of performance.md section 17 (IQN-IMVJ, the Newton solid,
# one non-orthogonal corrector, a larger time step), each run whole to 5 s on one rank pinned to
# its own core, two runs side by side (the pair shares the machine alike), statistics over [4, 5] s
# against the refined reference (doc/results/fsi_benchmark.py, as fsi3.sh).
#   usage: doc/results/fsi3_fast.sh FVFSI RUN_DIRECTORY NAME@CORE [NAME@CORE]
# NAME is one of the variants below (fast_file: prm/turek_hron_fsi3_fast.prm as it is); the runs
# of one call start together. Then: python3 doc/results/fsi3_fast.py RUN_DIRECTORY/A RUN_DIRECTORY/B
# for where the time of two runs went.
set -euo pipefail
cd "$(dirname "$0")/../.."
python=${PYTHON:-/usr/bin/python3}
fvfsi=$1 runs=$2
shift 2
mkdir -p "$runs"
source doc/results/fsi_runs.sh
machine

# The levers, each a list of --set overrides.
imvj=("Coupling/Method=IQN-IMVJ" "Coupling/Reuse time steps=0")
newton=("Solid/Algorithm=coupled")
nonorth1=("Fluid/Non-orthogonal correctors=1")
variant() {
  prm_file=
  case $1 in
    shipped) settings=() ;;
    fast_file) settings=() prm_file=prm/turek_hron_fsi3_fast.prm ;;
    imvj) settings=("${imvj[@]}") ;;
    imvj_newton_nonorth1) settings=("${imvj[@]}" "${newton[@]}" "${nonorth1[@]}") ;;
    imvj_newton_nonorth1_dt1) settings=("${imvj[@]}" "${newton[@]}" "${nonorth1[@]}" "Time/Time step=0.001") ;;
    imvj_newton_nonorth1_courant4) settings=("${imvj[@]}" "${newton[@]}" "${nonorth1[@]}" "Time/Adaptive=Courant" "Time/Max Courant number=4") ;;
    imvj_nonorth1_courant4) settings=("${imvj[@]}" "${nonorth1[@]}" "Time/Adaptive=Courant" "Time/Max Courant number=4") ;;
    *) echo "unknown variant $1" >&2; exit 1 ;;
  esac
}

pids=()
for run in "$@"; do
  name=${run%@*} core=${run#*@}
  variant "$name"
  ( launcher="taskset -c $core" prm_file=$prm_file run_fsi fsi3 "$name" 4 5 "${settings[@]}" ) &
  pids+=($!)
done
for p in "${pids[@]}"; do wait "$p"; done
for run in "$@"; do
  grep -h '"wall' "$runs/${run%@*}/summary.json" | head -1 || true
done
