#!/bin/bash
# The heavy flap of doc/results/hard_cases.md (section 8): prm/wall_plate_flap_vacuo.prm (the solid alone)
# and prm/wall_plate_flap.prm (the flap in the flow) on the fluid meshes r = 1, 2, 3 of the
# hard-case blocks, with the ramped inflow as shipped and with an impulsive start, and the ramped
# series again at rho_s / rho_f = 10 000 (rho_s = 1e4 kg/m^3, E = 1e9 Pa: the same in-vacuo
# period). Then heavy_flap.py fits periods and amplitudes and writes heavy_flap.json.
#   bash doc/results/heavy_flap.sh build/fvfsi [WORK]
set -e
FVFSI=$(realpath "$1")
WORK=${2:-/tmp/heavy_flap}
ROOT=$(cd "$(dirname "$0")/../.." && pwd)
CPU=$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')
mkdir -p "$WORK"
cd "$WORK"
echo "[" > runs.json
sep=""
run() { # name kind ratio inflow r prm settings...
  local name=$1 kind=$2 ratio=$3 inflow=$4 r=$5 prm=$6
  shift 6
  local start=$(date +%s.%N)
  "$FVFSI" "$ROOT/prm/$prm" "$@" --set "Output directory=$WORK/$name" > "$name.log" 2>&1
  local wall=$(echo "$(date +%s.%N) - $start" | bc)
  local its=$(grep -o '[0-9.]* coupling iterations per coupled step' "$name.log" | cut -d' ' -f1)
  local cells=$(grep -o 'fluid [0-9]* cells' "$name.log" | cut -d' ' -f2)
  echo "$sep{\"name\": \"$name\", \"kind\": \"$kind\", \"ratio\": $ratio, \"inflow\": \"$inflow\"," \
    "\"r\": $r, \"cells\": ${cells:-null}, \"iterations\": ${its:-null}, \"wall_s\": $wall, \"cpu\": \"$CPU\"}" >> runs.json
  sep=","
  echo "$name: $(tail -3 "$name.log" | head -1)"
}
heavy=(--set "Solid/Density=1e4" --set "Solid/Young's modulus=1e9")
impulsive=(--set "Fluid/Velocity inlet=inlet: 10; 0")
run vacuo_1000 vacuo 1000 - 0 wall_plate_flap_vacuo.prm
run vacuo_10000 vacuo 10000 - 0 wall_plate_flap_vacuo.prm "${heavy[@]}"
for r in 1 2 3; do
  mesh=(--set "Mesh/Generator arguments=$((30 * r)): $((3 * r)): $((15 * r)): $((30 * r))")
  run ramped_1000_r$r fsi 1000 ramped $r wall_plate_flap.prm "${mesh[@]}"
  run impulsive_1000_r$r fsi 1000 impulsive $r wall_plate_flap.prm "${mesh[@]}" "${impulsive[@]}"
  run ramped_10000_r$r fsi 10000 ramped $r wall_plate_flap.prm "${mesh[@]}" "${heavy[@]}"
done
echo "]" >> runs.json
${PYTHON:-python3} "$ROOT/doc/results/heavy_flap.py" "$WORK"  # PYTHON: one with numpy and scipy
