#!/usr/bin/env bash
# Turek-Hron FSI2 (paper section 4.3): the study of doc/results/fsi2.md. Every run is
# prm/turek_hron_fsi2.prm with the overrides listed below (one MPI rank, Release, one run at a
# time); the coupling starts at 2 s. The shipped run goes to 15 s (bounded and periodic over the
# long run, the smallest fluid cell-volume ratio in fsi_history.txt), statistics over [12, 15] s;
# the others to 10 s, statistics over [7, 10] s: the meshes n = 24 (flag 49 x 3) and 40 (82 x 4,
# shipped) at dt = 1.5 ms, and dt = 0.75 ms on n = 40.
# Writes the markdown table to stdout, doc/results/fsi2_shipped.png and the "fsi2" entry of
# doc/results/fsi_benchmarks.json.
#   usage: doc/results/fsi2.sh [path/to/fvfsi [RUN_DIRECTORY]]
set -euo pipefail
cd "$(dirname "$0")/../.."
python=${PYTHON:-/usr/bin/python3} # Debian's, with python3-numpy and python3-matplotlib
fvfsi=${1:-build/fvfsi}
runs=${2:-build/fsi2_runs}
mkdir -p "$runs"
source doc/results/fsi_runs.sh
machine

run_fsi fsi2 shipped 12 15
run_fsi fsi2 n24_dt15 7 10 "Time/End time=10" "Mesh/Generator arguments=24" "Solid mesh/Generator arguments=49: 3"
run_fsi fsi2 n40_dt075 7 10 "Time/End time=10" "Time/Time step=0.00075"
records=()
for r in shipped n24_dt15 n40_dt075; do
  [[ -f $runs/$r.json ]] && records+=("$runs/$r.json")
done
"$python" doc/results/fsi_benchmark.py table fsi2 "${records[@]}"
"$python" doc/results/fsi_benchmark.py store fsi2 "${records[@]}"
cp "$runs/shipped.png" doc/results/fsi2_shipped.png
