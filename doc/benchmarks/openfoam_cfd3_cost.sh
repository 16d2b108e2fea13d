#!/usr/bin/env bash
# (fvfsi copy of ../shared/peers/openfoam-cfd3/cost.sh with the parameter names of subsection Time;
# the mesh and inflow tools and the OpenFOAM case template stay in the peer folder, PEER=...)
# Cost of a PISO time step, side by side: OpenFOAM's pimpleFoam and fvfsi on the Turek-Hron CFD3 channel
# (rigid cylinder and flag, Re = 200, full parabolic inflow from rest, no ramp), same dt, same step count,
# similar cell counts (pimpleFoam: one-cell-thick blockMesh, 20 280 cells; fvfsi: its n = 40 channel,
# 20 960 cells). Prints wall seconds and microseconds per cell and time step for each, and their ratio.
#
#   usage (from the project root): cost.sh FVFSI_EXECUTABLE [STEPS=400] [DT=0.00025] [REPEATS=3]
#   environment: LEVEL (pimpleFoam's mesh, peer_common.sh's openfoam_case: 1, 1.5 or 2) and N
#   (fvfsi's channel n) for the larger pairs: LEVEL=1.5 N=60 (45 684 / 47 160 cells), LEVEL=2
#   N=80 (81 120 / 83 676 cells); default LEVEL=1 N=40. Prints the machine's CPU model first.
#   needs: apt-get install -y openfoam python3-numpy   (OpenFOAM v1912 from Debian)
# pimpleFoam settings: PISO (1 outer, 2 pressure correctors, 1 non-orthogonal corrector), backward,
# Gauss linearUpwind, GAMG for p (relTol 0.01, final 0, tolerance 1e-7), symGaussSeidel for U (1e-8).
# fvfsi runs prm/turek_hron_cfd3.prm with the mesh, dt, end time and inflow overridden (edit fvfsi_cfd3_args
# in peer_common.sh if the parameter names change).
set -euo pipefail
HERE=${PEER:-$(cd "$(dirname "$0")/../../../shared/peers/openfoam-cfd3" && pwd)}
FV=${1:?usage: cost.sh FVFSI_EXECUTABLE [STEPS] [DT] [REPEATS]}
STEPS=${2:-400}; DT=${3:-0.00025}; REPEATS=${4:-3}
PRM=${PRM:-$(pwd)/prm/turek_hron_cfd3.prm}   # run from the project root, or set PRM
END=$(python3 -c "print($STEPS*$DT)")
source "$(dirname "$0")/peer_common.sh"
echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//'), $(nproc) cores"
openfoam_case "$C" transient pimpleFoam "${LEVEL:-1}" 2.0 "$END" "$DT"
of_cells=$OF_CELLS
fvfsi_cfd3_args "${N:-40}" "$END" "$DT"
of_t=(); fv_t=()
for r in $(seq "$REPEATS"); do            # alternate the two, so that a drift of the machine hits both
  rm -rf "$C"/[1-9]* "$C"/0.[0-9]* "$C/postProcessing"
  t=$(cd "$C" && timed log.pimpleFoam pimpleFoam) || exit 1; of_t+=("$t")
  t=$(timed "$WORK/fv.log" "$FV" "$PRM" "${FVFSI_ARGS[@]}") || exit 1; fv_t+=("$t")
done
fv_cells=$($PY -c "import json;print(json.load(open('$WORK/fv/summary.json'))['n_cells'])")
$PY - "$of_cells" "$fv_cells" "$STEPS" "${of_t[*]}" "${fv_t[*]}" "${N:-40}" <<'EOP'
import sys, statistics as st
ofc, fvc, n = int(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3])
of = [float(x) for x in sys.argv[4].split()]; fv = [float(x) for x in sys.argv[5].split()]
ratios = [(b / fvc) / (a / ofc) for a, b in zip(of, fv)]
print(f"pimpleFoam: {ofc} cells, {n} steps, wall s {['%.2f' % x for x in of]}, median {st.median(of):.2f} s, "
      f"{st.median(of) / (ofc * n) * 1e6:.3f} us per cell-step")
print(f"fvfsi:      {fvc} cells, {n} steps, wall s {['%.2f' % x for x in fv]}, median {st.median(fv):.2f} s, "
      f"{st.median(fv) / (fvc * n) * 1e6:.3f} us per cell-step")
print(f"fvfsi / pimpleFoam cost per cell-step, pair by pair: {['%.3f' % r for r in ratios]}, median {st.median(ratios):.3f}")
# The pairs as a PNG next to the tables (run from the project root).
import subprocess
png = "doc/results/openfoam_cfd3_cost%s.png" % ("" if sys.argv[6] == "40" else "_n" + sys.argv[6])
subprocess.run([sys.executable, "doc/benchmarks/pair_plot.py", png,
                "Turek-Hron CFD3: fvfsi beside OpenFOAM's pimpleFoam", "pimpleFoam (%d cells)" % ofc, "fvfsi (%d cells)" % fvc,
                "fvfsi / pimpleFoam cost per cell-step", " ".join(map(str, of)), " ".join(map(str, fv)),
                " ".join(map(str, ratios))], check=True)
EOP
