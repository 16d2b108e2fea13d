#!/usr/bin/env bash
# Measures the coupling methods on prm/fsi_pressure_column.prm and prints the markdown table of
# doc/results/fsi.md: interface displacement error against the static solution, coupling
# iterations (total, max per step), wall seconds (median of 3 runs, one rank); and as a bar chart,
# doc/results/fsi_coupling_methods.png.
#   usage: doc/results/fsi.sh [path/to/fvfsi]   (default: build/fvfsi)
set -euo pipefail
cd "$(dirname "$0")/../.."
fvfsi=${1:-build/fvfsi}
table=$(mktemp)
emit() { echo "$1" | tee -a "$table"; } # a table line, also kept for the plot
exact=$(python3 -c "print(5000/(1e7*0.7/(1.3*0.4)-5000))")
emit "| method | relaxation | reuse | d [m] | error | coupling iterations | max per step | wall [s] (median of 3) |"
emit "|---|---:|---:|---:|---:|---:|---:|---:|"
for setting in "fixed 0.4 0" "Aitken 0.4 0" "IQN-ILS 0.4 0" "IQN-ILS 0.4 3" "IQN-IMVJ 0.4 0" "fixed 1 0"; do
  set -- $setting
  walls=()
  for run in 1 2 3; do
    dir=$(mktemp -d)
    if "$fvfsi" prm/fsi_pressure_column.prm --set "Output directory=$dir" --set "Coupling/Method=$1" \
        --set "Coupling/Relaxation=$2" --set "Coupling/Reuse time steps=$3" > "$dir/log" 2>&1; then
      walls+=($(python3 -c "import json; print(json.load(open('$dir/summary.json'))['wall_seconds'])"))
      line=$(python3 - "$dir/summary.json" "$exact" <<'PY'
import json, sys
s = json.load(open(sys.argv[1])); r = s["results"]; exact = float(sys.argv[2])
d = -r["point_top_displacement"][1]
print(f"{d:.7e} | {abs(d - exact) / exact * 100:.4f}% | {r['coupling_iterations']} | {r['max_coupling_iterations_per_step']}")
PY
)
    else
      line="diverged: $(grep -o 'error: FSI: at time step [0-9]*' "$dir/log" | head -1 | sed 's/error: FSI: //') | - | - | -"
      walls+=(0)
    fi
    rm -rf "$dir"
  done
  median=$(printf '%s\n' "${walls[@]}" | sort -g | sed -n 2p)
  emit "| $1 | $2 | $3 | $line | $median |"
done
# The table as doc/results/fsi_coupling_methods.png.
/usr/bin/python3 doc/results/table_plot.py "$table" doc/results/fsi_coupling_methods.png --bar \
  --x method --group relaxation --group reuse --y "coupling iterations" \
  --y "wall [s] (median of 3)" --logy \
  --title "Coupling methods, prm/fsi_pressure_column.prm (label: method, relaxation, reuse)"
rm -f "$table"
