#!/usr/bin/env bash
# Turek-Hron CFD2 (steady, Re = 100), side by side: OpenFOAM v1912's simpleFoam on the peer's
# 20 280-cell one-cell-thick mesh (../shared/peers/openfoam-cfd3: template/system/fvSolution.steady,
# SIMPLEC with U relaxation 0.9, GAMG, residualControl p 1e-7, U 1e-8) and fvfsi on
# prm/turek_hron_cfd2.prm as shipped (13 409 cells), each to its own convergence criterion,
# alternating the two REPEATS times. Prints wall seconds, iterations, drag (cylinder + flag, N/m)
# with its error against the reference 136.7 N/m (Turek-Hron), the medians and the wall-time
# ratio pair by pair.
#   usage (from the project root): doc/benchmarks/openfoam_cfd2_cost.sh FVFSI_EXECUTABLE [REPEATS=3]
#   needs: apt-get install -y openfoam   (Debian's OpenFOAM v1912)
set -euo pipefail
HERE=${PEER:-$(cd "$(dirname "$0")/../../../shared/peers/openfoam-cfd3" && pwd)}
FV=${1:?usage: openfoam_cfd2_cost.sh FVFSI_EXECUTABLE [REPEATS]}
REPEATS=${2:-3}
source "$(dirname "$0")/peer_common.sh"
openfoam_case "$C" steady simpleFoam 1 1.0 20000 1 'functions { #include "forces" }'
of_cells=$OF_CELLS
LZ=$(grep -m1 "^LZ" "$HERE/gen_mesh.py" | awk '{print $3}')
of_t=(); fv_t=(); of_drag=(); fv_drag=(); of_it=(); fv_it=()
for r in $(seq "$REPEATS"); do # alternate the two, so that a drift of the machine hits both
  rm -rf "$C"/[1-9]* "$C/postProcessing"
  t=$(cd "$C" && timed log.simpleFoam simpleFoam) || exit 1; of_t+=("$t")
  # force.dat: Time ((total) (pressure) (viscous)); drag = total x / LZ
  last=$(grep -v '^#' "$C"/postProcessing/forces/0/force.dat | tail -1 | tr -d '()')
  of_it+=($(echo "$last" | awk '{print $1}'))
  of_drag+=($(echo "$last" | awk -v lz="$LZ" '{printf "%.7g", $2 / lz}'))
  t=$(timed "$WORK/fv.log" "$FV" prm/turek_hron_cfd2.prm --set "Output directory=$WORK/fv") || exit 1
  fv_t+=("$t")
  fv_drag+=($($PY -c "import json;print(json.load(open('$WORK/fv/summary.json'))['results']['drag'])"))
  fv_it+=($($PY -c "import json;print(json.load(open('$WORK/fv/summary.json'))['results']['time_steps'])"))
done
fv_cells=$($PY -c "import json;print(json.load(open('$WORK/fv/summary.json'))['n_cells'])")
$PY - "$of_cells" "$fv_cells" "${of_t[*]}" "${fv_t[*]}" "${of_drag[*]}" "${fv_drag[*]}" "${of_it[*]}" "${fv_it[*]}" <<'EOP'
import sys, statistics as st
ofc, fvc = int(sys.argv[1]), int(sys.argv[2])
of, fv, od, fd = ([float(x) for x in a.split()] for a in sys.argv[3:7])
oi, fi = sys.argv[7].split(), sys.argv[8].split()
ref = 136.7
print(f"simpleFoam: {ofc} cells, {oi[-1]} iterations, wall s {['%.2f' % x for x in of]}, median {st.median(of):.2f} s, "
      f"drag {od[-1]:.6g} N/m ({100 * (od[-1] - ref) / ref:+.2f}%)")
print(f"fvfsi:      {fvc} cells, {fi[-1]} pseudo time steps, wall s {['%.2f' % x for x in fv]}, median {st.median(fv):.2f} s, "
      f"drag {fd[-1]:.6g} N/m ({100 * (fd[-1] - ref) / ref:+.2f}%)")
print(f"fvfsi / simpleFoam wall time, pair by pair: {['%.3f' % (b / a) for a, b in zip(of, fv)]}, "
      f"median {st.median([b / a for a, b in zip(of, fv)]):.3f}")
# The pairs as a PNG next to the tables (run from the project root).
import subprocess
subprocess.run([sys.executable, "doc/benchmarks/pair_plot.py", "doc/results/openfoam_cfd2_cost.png",
                "Turek-Hron CFD2: fvfsi beside OpenFOAM's simpleFoam", "simpleFoam (%d cells)" % ofc, "fvfsi (%d cells)" % fvc,
                "fvfsi / simpleFoam wall time", " ".join(map(str, of)), " ".join(map(str, fv)),
                " ".join(map(str, [b / a for a, b in zip(of, fv)]))], check=True)
EOP
