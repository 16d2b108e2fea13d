#!/usr/bin/env bash
# Linear (Eq. 19) vs quadratic face normal gradient of the FV Laplacian (doc/results/core.md, section
# "Face normal gradient"): the Poisson scenes prm/poisson_2d.prm and prm/poisson_3d.prm on the meshes
# of tests/core/poisson_convergence (an 8x8 / 4x4x4 coarse mesh with every interior vertex moved by
# 0.25 of its shortest edge, uniformly refined), refinements 1-5 in 2D and 1-4 in 3D, one MPI rank.
# Prints one markdown row per run from summary.json; orders are log2 of the error ratio of
# consecutive rows (h halves). The rows of refinements 1-3 are those of the test. The errors are
# plotted as poisson_face_gradient.png.
#
# Usage: doc/results/poisson_face_gradient.sh BUILD_DIR   (BUILD_DIR holds a Release fvfsi)
# Run time on this 2-core machine: about 1 minute CPU, 2 minutes wall under load (the 262,144-cell 3D runs are most of it).
set -uo pipefail
build=${1:?usage: poisson_face_gradient.sh BUILD_DIR}
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"
table_study # repo, out, emit
echo "commit: $(git -C "$repo" rev-parse --short HEAD)"
echo
emit "| dim | face gradient | cells | max cell error | order | max face-gradient error | order | L2 face-gradient error | order | max Dirichlet-face gradient error | order | correction iterations | wall [s] |"
emit "|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|"
for dim in 2 3; do
  if [[ $dim == 2 ]]; then coarse="8: 0: 1: true"; levels="1 2 3 4 5"; else coarse="4: 0: 1: true"; levels="1 2 3 4"; fi
  for face_gradient in linear quadratic; do
    previous=""
    for r in $levels; do
      dir="$out/${dim}d_${face_gradient}_$r"
      "$build/fvfsi" "$repo/prm/poisson_${dim}d.prm" --set "Output directory=$dir" \
        --set "Mesh/Generator=subdivided_hyper_cube" --set "Mesh/Generator arguments=$coarse" \
        --set "Mesh/Distort coarse mesh=true" --set "Mesh/Global refinements=$r" \
        --set "Poisson/Face gradient=$face_gradient" > /dev/null 2>&1
      row=$(python3 - "$dir/summary.json" "$previous" <<'EOF'
import json, math, sys
s = json.load(open(sys.argv[1]))
r = s["results"]
keys = ["max_cell_error", "max_face_gradient_error", "l2_face_gradient_error", "max_boundary_face_gradient_error"]
prev = dict(zip(keys, map(float, sys.argv[2].split()))) if sys.argv[2] else None
cols = []
for k in keys:
    cols.append("%.3e" % r[k])
    cols.append("%.2f" % math.log2(prev[k] / r[k]) if prev else "-")
print(" | ".join([str(s["n_cells"])] + cols + [str(r["correction_iterations"]), "%.1f" % s["wall_seconds"]]))
print(" ".join(repr(r[k]) for k in keys))
EOF
)
      emit "| ${dim}D | $face_gradient | $(echo "$row" | head -1) |"
      previous=$(echo "$row" | tail -1)
    done
  done
done
# The table as doc/results/poisson_face_gradient.png.
/usr/bin/python3 "$repo/doc/results/table_plot.py" "$table" \
  "$repo/doc/results/poisson_face_gradient.png" --x cells --y "max cell error" \
  --y "max face-gradient error" --group dim --group "face gradient" --logx --logy \
  --title "Poisson on distorted meshes: linear vs quadratic face gradient"
rm -rf "$out"
