#!/usr/bin/env bash
# Channel flow over a cavity with a flexible bottom (paper section 4.2): the mesh study of
# doc/results/cavity.md. prm/cavity_flexible_bottom.prm (steady FSI) on the paper's four cell sizes
# h = 0.1, 0.05, 0.025, 0.0125 m, fluid and plate meshes refined together; prints the markdown
# table (u_y(A), F_y, errors against the finest mesh, coupling iterations, fluid pseudo steps,
# solid outer iterations, wall time) and the observed orders of Eq. 34, writes
# doc/results/cavity_convergence.png and the "cavity" entry of doc/results/fsi_benchmarks.json.
# One MPI rank, Release build, one run at a time (h = 0.0125 does not converge yet: cavity.md).
#   usage: doc/results/cavity.sh [path/to/fvfsi [RUN_DIRECTORY]]   (default: build/fvfsi, build/cavity_runs)
set -euo pipefail
python=${PYTHON:-/usr/bin/python3} # Debian's, with python3-numpy and python3-matplotlib
cd "$(dirname "$0")/../.."
fvfsi=${1:-build/fvfsi}
runs=${2:-build/cavity_runs}
mkdir -p "$runs"
echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); load: $(cut -d' ' -f1-3 /proc/loadavg); commit $(git rev-parse --short HEAD)"
records=()
for h in 0.1 0.05 0.025 0.0125; do
  out=$runs/h$h
  set=("Mesh/Generator arguments=$h" "Solid mesh/Generator arguments=$h")
  args=(); for s in "${set[@]}"; do args+=(--set "$s"); done
  "$fvfsi" prm/cavity_flexible_bottom.prm "${args[@]}" --set "Output directory=$out" > "$out.log" 2>&1 \
    || { echo "h = $h failed, see $out.log"; exit 1; }
  "$python" doc/results/fsi_benchmark.py cavity-record "$h" "$out" "${set[@]}" > "$out.json"
  records+=("$out.json")
done
"$python" doc/results/fsi_benchmark.py cavity-study doc/results/cavity_convergence.png "${records[@]}"
