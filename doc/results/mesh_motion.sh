#!/usr/bin/env bash
# Mesh quality under Laplace mesh motion (doc/results/mesh_motion.md): prm/turek_hron_moving_flag.prm
# run to t = 0.125 s (a quarter period: the flag tip at its full amplitude A) for tip amplitudes
# A = 0.04 ... 0.20 m and the three diffusivities, one MPI rank, one run at a time. Prints one markdown
# row per run: the smallest V/V_ref over cells and time steps (summary.json min_cell_volume_ratio),
# or the error message if a cell inverted, and the wall time; and the table as mesh_motion.png.
#
# Usage: doc/results/mesh_motion.sh BUILD_DIR   (BUILD_DIR holds a Release fvfsi)
set -uo pipefail
build=${1:?usage: mesh_motion.sh BUILD_DIR}
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
table_study # repo, out, emit
echo "machine: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs), $(nproc) cores, load $(cut -d' ' -f1-3 /proc/loadavg)"
echo "commit: $(git -C "$repo" rev-parse --short HEAD)"
echo
emit "| diffusivity | tip amplitude A [m] | min V/V_ref | wall [s] |"
emit "|---|---:|---:|---:|"
for diffusivity in "uniform" "inverse distance" "quadratic inverse distance"; do
  for A in 0.04 0.08 0.12 0.16 0.20; do
    dir="$out/${diffusivity// /_}_$A"
    log=$("$build/fvfsi" "$repo/prm/turek_hron_moving_flag.prm" --set "Output directory=$dir" \
      --set "Time/End time=0.125" --set "Mesh motion/Diffusivity=$diffusivity" \
      --set "Mesh motion/Moving patches=flag: 0; $A*((x - 0.249)/0.351)^2*sin(2*pi*2*t)" \
      --set "Fluid scene/Output interval=0" 2>&1)
    # (a failed run writes summary.json too, with status "failed")
    if [[ -f "$dir/summary.json" ]] && grep -q '"status": "completed"' "$dir/summary.json"; then
      ratio=$(python3 -c "import json; print('%.3f' % json.load(open('$dir/summary.json'))['results']['min_cell_volume_ratio'])")
      wall=$(python3 -c "import json; print('%.1f' % json.load(open('$dir/summary.json'))['wall_seconds'])")
      emit "| $diffusivity | $A | $ratio | $wall |"
    else
      emit "| $diffusivity | $A | inverted: $(echo "$log" | grep -m1 'error' | sed -e 's/.*inverted (volume <= 0) at //' -e 's/; the displacement.*//') | - |"
    fi
  done
done
# The table as doc/results/mesh_motion.png.
/usr/bin/python3 "$repo/doc/results/table_plot.py" "$table" "$repo/doc/results/mesh_motion.png" \
  --x "tip amplitude A [m]" --y "min V/V_ref" --group diffusivity \
  --title "Laplace mesh motion, moving flag: smallest V/V_ref"
rm -rf "$out"
