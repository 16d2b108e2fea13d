#!/usr/bin/env bash
# Reproduces every number of doc/results/solid_coupled.md: the same cases solved by the paper's
# segregated solid (Solid/Algorithm = segregated) and by Newton's method (coupled), one MPI rank.
#   doc/results/solid_coupled.sh [FVFSI [OUT]]      (default build/fvfsi, /tmp/solid_coupled)
# Every run goes to OUT/NAME/1 (and /2, /3 when it took less than 30 s: the tables give the median
# of the three); a run is stopped after CAP seconds of wall time (default 180; exit status 124 in
# NAME/1/rc). Each run's CPU time (user + system, /usr/bin/time) goes to NAME/i/cpu: on a shared
# machine it is the better measure of the work (wall times count the waiting for a core).
# The tables are printed by solid_coupled.py from the summary.json files. Run the script itself
# under `nice` if the machine is shared (its runs inherit the priority).
set -uo pipefail
cd "$(dirname "$0")/../.."
fvfsi=$(realpath "${1:-build/fvfsi}")
out=${2:-/tmp/solid_coupled}
python=${PYTHON:-/usr/bin/python3}
cap=${CAP:-180}
mkdir -p "$out"

# run NAME PRM SETTING...: fvfsi PRM --set SETTING ... into $out/NAME/i, repeated up to 3 times
# while a run succeeds in less than 30 s.
run() {
  local name=$1 prm=$2
  shift 2
  local settings=()
  for s in "$@"; do settings+=(--set "$s"); done
  for i in 1 2 3; do
    local dir=$out/$name/$i
    mkdir -p "$dir"
    # stdbuf: the log is line buffered, so a run stopped at the cap keeps its progress lines
    timeout "$cap" /usr/bin/time -f "%U %S" -o "$dir/cpu" stdbuf -oL \
      "$fvfsi" "$prm" "${settings[@]}" --set "Output directory=$dir" >"$dir/log" 2>&1
    echo $? >"$dir/rc"
    echo "$name/$i: exit $(cat "$dir/rc")"
    [ "$(cat "$dir/rc")" = 0 ] || break
    "$python" -c "import json, sys; sys.exit(json.load(open('$dir/summary.json'))['wall_seconds'] >= 30)" || break
  done
}

# Cantilever 40 x 2 ... 320 x 16 (prm/cantilever.prm is the coupled 40 x 2 case); the segregated
# runs are also limited to 100 000 outer iterations.
for r in 0 1 2 3; do
  run cantilever_r${r}_coupled prm/cantilever.prm "Mesh/Global refinements=$r"
  run cantilever_r${r}_segregated prm/cantilever.prm "Mesh/Global refinements=$r" \
    "Solid/Algorithm=segregated" "Solid/Max outer iterations=100000"
done

# CSM1 as shipped (280 x 16, outer tolerance 1e-9): both algorithms, and Jacobian-free Newton.
run csm1_coupled prm/turek_hron_csm1.prm "Solid/Algorithm=coupled"
run csm1_coupled_jfnk prm/turek_hron_csm1.prm "Solid/Algorithm=coupled" \
  "Solid/Jacobian-free Newton=true"
run csm1_segregated prm/turek_hron_csm1.prm "Solid/Algorithm=segregated"

# CSM3 as shipped (120 x 4, dt = 5 ms) over its first second (200 BDF2 steps).
for a in coupled segregated; do
  run csm3_$a prm/turek_hron_csm3.prm "Time/End time=1" "Solid/Algorithm=$a"
done

# Plate with a hole, 64 082 cells (n = 179), as shipped otherwise (Hessian correction, 1e-8).
for a in coupled segregated; do
  run plate_hole_64k_$a prm/plate_hole.prm "Mesh/Generator arguments=0.5: 2: 179" \
    "Solid/Algorithm=$a"
done

# The sparse direct solver of the Newton systems (Solid Newton linear solver/Method: UMFPACK,
# the default, or KLU): the plate with a hole at n = 90 (16 200 cells) and 179, the thick plate
# of doc/results/fsi_3d.md alone (3D, 2 048 cells, 10 Pa on its upstream face), CSM1.
run plate_hole_16k_coupled prm/plate_hole.prm "Mesh/Generator arguments=0.5: 2: 90" \
  "Solid/Algorithm=coupled"
run plate_hole_16k_klu prm/plate_hole.prm "Mesh/Generator arguments=0.5: 2: 90" \
  "Solid/Algorithm=coupled" "Solid Newton linear solver/Method=KLU"
run plate_hole_16k_segregated prm/plate_hole.prm "Mesh/Generator arguments=0.5: 2: 90" \
  "Solid/Algorithm=segregated"
run plate_hole_64k_klu prm/plate_hole.prm "Mesh/Generator arguments=0.5: 2: 179" \
  "Solid/Algorithm=coupled" "Solid Newton linear solver/Method=KLU"
plate=("Scene=solid" "Mesh/Generator=fvfsi_thick_plate" "Mesh/Generator arguments=0.0125"
       "Mesh/Patch names=0: clamped, 1: symmetry, 2: interface" "Solid/External traction="
       "Solid/Traction=interface: -10*(x<0.4501); 0; 0")
run thick_plate_coupled prm/thick_plate.prm "${plate[@]}" "Solid/Algorithm=coupled"
run thick_plate_klu prm/thick_plate.prm "${plate[@]}" "Solid/Algorithm=coupled" \
  "Solid Newton linear solver/Method=KLU"
run thick_plate_segregated prm/thick_plate.prm "${plate[@]}" "Solid/Algorithm=segregated"
run csm1_klu prm/turek_hron_csm1.prm "Solid/Algorithm=coupled" \
  "Solid Newton linear solver/Method=KLU"

# FSI3 (dt = 0.75 ms, shipped meshes): 10 fluid steps, then 10 coupled steps.
for a in segregated coupled; do
  run fsi3_$a prm/turek_hron_fsi3.prm "Coupling/Start time=0.0075" "Time/End time=0.015" \
    "Fluid scene/Output interval=0" "Solid/Algorithm=$a"
done

# A quasi-steady flag: the FSI3 set-up with FSI1's inflow (mean 0.2 m/s) and flag (E = 1.4 MPa),
# dt = 10 ms: 10 fluid steps, then 10 coupled steps.
for a in segregated coupled; do
  run fsi1_dt10ms_$a prm/turek_hron_fsi3.prm \
    "Fluid/Velocity inlet=inlet: 1.5*0.2*4*y*(0.41-y)/0.41^2; 0" "Solid/Young's modulus=1.4e6" \
    "Time/Time step=0.01" "Coupling/Start time=0.1" "Time/End time=0.2" \
    "Fluid scene/Output interval=0" "Solid/Algorithm=$a"
done

"$python" doc/results/solid_coupled.py "$out" | tee "$out/tables.md"
# The cantilever table as doc/results/solid_coupled.png (the segregated solid fails or reaches the
# cap on every mesh: only the coupled one has numbers).
/usr/bin/python3 doc/results/table_plot.py "$out/tables.md" doc/results/solid_coupled.png \
  --x cells --y "@5" --y "@4" --logx --logy \
  --title "Cantilever 2 m x 0.1 m, coupled (Newton) solid: wall time and tip error"
