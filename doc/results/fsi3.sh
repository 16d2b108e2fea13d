#!/usr/bin/env bash
# Turek-Hron FSI3 (paper section 4.3): the study of doc/results/fsi3.md. Every run is
# prm/turek_hron_fsi3.prm with the overrides listed below (one MPI rank, Release, one run at a
# time), statistics over the last second [4, 5] s (the coupling starts at 2 s):
#   study:   the paper's resolution (fluid n = 40 of fvfsi_turek_hron_channel, 20 960 cells; flag
#            82 x 4 cells) at dt = 0.75 ms; the flag refined to 164 x 8 (a 4-cell-thick flag is
#            too stiff in bending: doc/results/csm.md); the fluid mesh n = 24, 40, 60 with the
#            164 x 8 flag; dt = 1.5, 0.75, 0.375 ms on n = 40 with the 164 x 8 flag;
# Writes the markdown tables to stdout, doc/results/fsi3_*.png and the "fsi3" entry of
# doc/results/fsi_benchmarks.json. Cost: about ... h on one core.
#   usage: doc/results/fsi3.sh [path/to/fvfsi [RUN_DIRECTORY [study|methods ...]]]
set -euo pipefail
cd "$(dirname "$0")/../.."
python=${PYTHON:-/usr/bin/python3} # Debian's, with python3-numpy and python3-matplotlib
fvfsi=${1:-build/fvfsi}
runs=${2:-build/fsi3_runs}
shift 2 || true
parts=("$@")
[[ ${#parts[@]} -eq 0 ]] && parts=(study methods)
mkdir -p "$runs"
source doc/results/fsi_runs.sh
machine

for part in "${parts[@]}"; do
  case $part in
    study)
      s164=("Solid mesh/Generator arguments=164: 8")
      run_fsi fsi3 shipped 4 5
      run_fsi fsi3 n40_s82_dt075 4 5 "Solid mesh/Generator arguments=82: 4"
      run_fsi fsi3 n40_s164_dt075 4 5 "${s164[@]}"
      run_fsi fsi3 n60_s164_dt075 4 5 "${s164[@]}" "Mesh/Generator arguments=60"
      run_fsi fsi3 n40_s164_dt0375 4 5 "${s164[@]}" "Time/Time step=0.000375"
      run_fsi fsi3 n24_s164_dt075 4 5 "${s164[@]}" "Mesh/Generator arguments=24"
      run_fsi fsi3 n40_s164_dt15 4 5 "${s164[@]}" "Time/Time step=0.0015"
      records=()
      for r in shipped n40_s82_dt075 n40_s164_dt075 n60_s164_dt075 n40_s164_dt0375 n24_s164_dt075 n40_s164_dt15; do
        [[ -f $runs/$r.json ]] && records+=("$runs/$r.json")
      done
      "$python" doc/results/fsi_benchmark.py table fsi3 "${records[@]}"
      "$python" doc/results/fsi_benchmark.py store fsi3 "${records[@]}"
      cp "$runs/shipped.png" doc/results/fsi3_shipped.png ;;
    methods)
      short=("Time/End time=3")
      paper=("Coupling/Tolerance=0" "Coupling/Residual reduction=1e-6")
      records=()
      for method in "IQN-ILS|3" "IQN-ILS|0" "IQN-IMVJ|0" "Aitken|0"; do
        m=${method%|*} reuse=${method#*|}
        set=("${short[@]}" "Coupling/Method=$m" "Coupling/Reuse time steps=$reuse")
        run_fsi fsi3 "method_${m}_reuse${reuse}" 2.5 3 "${set[@]}"
        run_fsi fsi3 "method_${m}_reuse${reuse}_paper" 2.5 3 "${set[@]}" "${paper[@]}"
        records+=("$runs/method_${m}_reuse${reuse}.json" "$runs/method_${m}_reuse${reuse}_paper.json")
      done
      "$python" doc/results/fsi_benchmark.py methods "${records[@]}" ;;
  esac
done
