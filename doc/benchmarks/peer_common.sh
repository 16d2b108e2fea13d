# What the peer comparisons share (sourced by openfoam_cfd2_cost.sh, openfoam_cfd3_cost.sh and
# openfoam_cfd3_parallel.sh, after they set HERE, the peer folder ../shared/peers/openfoam-cfd3):
# the work directory WORK (a new temporary one unless set), the OpenFOAM case directory C in it,
# the environment OpenFOAM and mpirun need as root, and the functions below.
WORK=${WORK:-$(mktemp -d)}
C=$WORK/of
PY=/usr/bin/python3
export WM_PROJECT_DIR=/usr/share/openfoam OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

now() { date +%s.%N; }

# timed LOG COMMAND...: prints the wall seconds of COMMAND (its output goes to LOG); fails, naming
# the command and its log, if COMMAND fails. Use as  t=$(timed LOG ...) || exit 1.
timed() {
  local log=$1 s
  shift
  s=$(now)
  "$@" > "$log" 2>&1 || { echo "failed: $* (see $log)" >&2; return 1; }
  echo "$(now) - $s" | bc
}

# fvfsi_cfd3_args N END_TIME DELTA_T: FVFSI_ARGS, the settings that make prm/turek_hron_cfd3.prm
# the peer's case (channel n, full parabolic inflow from rest, no field output, output in $WORK/fv).
fvfsi_cfd3_args() {
  FVFSI_ARGS=(--set "Mesh/Generator arguments=$1" --set "Time/End time=$2" --set "Time/Time step=$3"
              --set "Fluid/Velocity inlet=inlet: 1.5*2*4*y*(0.41-y)/0.41^2; 0"
              --set "Fluid scene/Output interval=0" --set "Output directory=$WORK/fv")
}

# openfoam_case CASE KIND APPLICATION LEVEL UBAR END_TIME DELTA_T [CONTROLDICT_EXTRA]: the
# Turek-Hron channel case of the peer folder written into CASE. KIND: transient or steady (which
# fvSchemes and fvSolution of the template); LEVEL: the mesh of gen_mesh.py (1: 20 280 cells, 2:
# 81 120), or 1.5: gen_mesh.py's blocks with 3 instead of 2 or 4 times its base cell counts
# (45 684 cells; beside fvfsi's n = 60, the shipped FSI3's fluid); UBAR: the mean inflow velocity
# [m/s] (set_inlet.py); CONTROLDICT_EXTRA: appended to controlDict (e.g. the forces function).
# Sets OF_CELLS.
openfoam_case() {
  local c=$1 kind=$2 application=$3 level=$4 ubar=$5 end=$6 dt=$7 extra=${8:-}
  mkdir -p "$c/system"
  cp -r "$HERE/template/constant" "$c/"; cp -r "$HERE/template/0" "$c/0"
  cp "$HERE/template/system/fvSchemes.$kind" "$c/system/fvSchemes"
  cp "$HERE/template/system/fvSolution.$kind" "$c/system/fvSolution"
  cp "$HERE/template/system/forces" "$c/system/forces"
  cat > "$c/system/controlDict" <<EOD
FoamFile { version 2.0; format ascii; class dictionary; object controlDict; }
application $application; startFrom startTime; startTime 0; stopAt endTime; endTime $end; deltaT $dt;
writeControl timeStep; writeInterval 100000; purgeWrite 0; writeFormat ascii; writePrecision 12;
writeCompression off; timeFormat general; timePrecision 10; runTimeModifiable false;
$extra
EOD
  if [ "$level" = 1.5 ]; then # gen_mesh.py takes whole levels (2^level); its counts() times 3
    $PY - "$HERE" "$c/system/blockMeshDict" > "$c/log.gen_mesh" <<'EOP'
import math, sys
sys.path.insert(0, sys.argv[1])
import gen_mesh
counts_of = gen_mesh.counts
def counts_times_3(level):
    n, g = counts_of(math.log2(3))
    return {k: int(round(v)) for k, v in n.items()}, g
gen_mesh.counts = counts_times_3
sys.argv = ["gen_mesh.py", "0", sys.argv[2]]
gen_mesh.main()
EOP
  else
    $PY "$HERE/gen_mesh.py" "$level" "$c/system/blockMeshDict" > "$c/log.gen_mesh"
  fi
  (cd "$c" && blockMesh > log.blockMesh 2>&1 && checkMesh > log.checkMesh 2>&1)
  $PY "$HERE/set_inlet.py" "$c" "$ubar" 0 > "$c/log.set_inlet"
  OF_CELLS=$(grep -m1 "^ *cells:" "$c/log.checkMesh" | awk '{print $2}')
}
