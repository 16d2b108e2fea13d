#!/usr/bin/env bash
# Turek-Hron CFD2 (steady, Re = 100) and CFD3 (periodic, Re = 200) with the rigid flag: the
# tables of doc/results/cfd.md. Every run: one MPI rank, Release build, one run at a time.
#   CFD2: prm/turek_hron_cfd2.prm with Mesh/Generator arguments n = 16, 24, 32, 48.
#   CFD2-speed: prm/turek_hron_cfd2.prm as shipped, 3 runs, median wall time.
#   CFD3: prm/turek_hron_cfd3.prm with the (n, dt, end time) of the cfd.md table (about 2.5 h).
# Prints markdown table rows (cells, drag, lift, errors against the reference, pseudo or time
# steps, wall seconds) and writes doc/results/cfd3_forces.png from the CFD3 histories.
# Usage: doc/results/cfd.sh [BUILD_DIR [cfd2|cfd2-speed|cfd3 ...]]   (BUILD_DIR must hold a Release fvfsi)
set -uo pipefail
script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$script_dir/../.." && pwd)
source "$repo/doc/results/common.sh"
build=${1:-$repo/build}
shift || true
sections=("$@")
[[ ${#sections[@]} -eq 0 ]] && sections=(cfd2 cfd3)
runs=$build/cfd_runs
mkdir -p "$runs"
fvfsi=$build/fvfsi
machine_line

field() { /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))" "$@"; }

for section in "${sections[@]}"; do
  case $section in
    cfd2)
      # n = 48 needs Momentum relaxation 0.9 (0.95 oscillates there); the file's value otherwise.
      echo "| n | cells | drag [N/m] | error | lift [N/m] | error | pseudo steps | wall [s] | peak memory [MB] |"
      echo "|---|---|---|---|---|---|---|---|---|"
      for n in 16 24 32 48; do
        out=$runs/cfd2_$n
        relax=0.95; [[ $n == 48 ]] && relax=0.9
        "$fvfsi" "$repo/prm/turek_hron_cfd2.prm" --set "Mesh/Generator arguments=$n" \
          --set "Fluid/Momentum relaxation=$relax" \
          --set "Output directory=$out" > "$out.log" 2>&1 || { echo "| $n | failed, see $out.log |"; continue; }
        s=$out/summary.json
        echo "| $n | $(field $s "d['n_cells']") | $(field $s "'%.3f' % d['results']['drag']") | $(field $s "'%+.2f%%' % (100*(d['results']['drag']/136.7-1))") | $(field $s "'%.3f' % d['results']['lift']") | $(field $s "'%+.2f%%' % (100*(d['results']['lift']/10.53-1))") | $(field $s "d['results']['time_steps']") | $(field $s "'%.2f' % d['wall_seconds']") | $(field $s "'%.0f' % d['peak_memory_mb']") |"
      done ;;
    cfd2-speed)
      # The speed target: prm/turek_hron_cfd2.prm as shipped (n = 32), 3 runs, the median.
      walls=()
      for k in 1 2 3; do
        out=$runs/cfd2_speed_$k
        "$fvfsi" "$repo/prm/turek_hron_cfd2.prm" --set "Output directory=$out" > "$out.log" 2>&1
        walls+=("$(field $out/summary.json "'%.2f' % d['wall_seconds']")")
      done
      echo "CFD2 as shipped: drag error $(field $out/summary.json "'%+.3f%%' % (100*(d['results']['drag']/136.7-1))"), wall times ${walls[*]} s, median $(printf '%s\n' "${walls[@]}" | sort -n | sed -n 2p) s" ;;
    cfd3)
      # n, dt [s], end time [s]: the rows of cfd.md (each run 2-60 min on one core).
      echo "| n | cells | dt [s] | max Courant | end [s] | drag mean | drag amplitude | lift amplitude | frequency [Hz] | wall [s] |"
      echo "|---|---|---|---|---|---|---|---|---|---|"
      for case in "24 0.00075 16" "24 0.0037 16" "32 0.002 16" "32 0.001 13" "48 0.002 11" "48 0.001 11"; do
        set -- $case
        out=$runs/cfd3_$1_$2
        "$fvfsi" "$repo/prm/turek_hron_cfd3.prm" --set "Mesh/Generator arguments=$1" \
          --set "Time/Time step=$2" --set "Time/End time=$3" --set "Fluid scene/Output interval=0" \
          --set "Output directory=$out" > "$out.log" 2>&1 || { echo "| $1 | failed, see $out.log |"; continue; }
        s=$out/summary.json
        d="d['results']['drag_mean_amplitude_frequency']"; l="d['results']['lift_mean_amplitude_frequency']"
        echo "| $1 | $(field $s "d['n_cells']") | $2 | $(awk '!/^#/ {if ($4 > m) m = $4} END {printf "%.1f", m}' $out/fluid_history.txt) | $3 | $(field $s "'%.2f (%+.2f%%)' % ($d[0], 100*($d[0]/439.45-1))") | $(field $s "'%.3f (%+.1f%%)' % ($d[1], 100*($d[1]/5.6183-1))") | $(field $s "'%.2f (%+.1f%%)' % ($l[1], 100*($l[1]/437.81-1))") | $(field $s "'%.4f (%+.2f%%)' % ($l[2], 100*($l[2]/4.3956-1))") | $(field $s "'%.0f' % d['wall_seconds']") |"
      done
      /usr/bin/python3 "$script_dir/cfd3_plot.py" "$script_dir/cfd3_forces.png" "$runs"/cfd3_32_*/fluid_history.txt "$runs"/cfd3_48_*/fluid_history.txt ;;
  esac
done
