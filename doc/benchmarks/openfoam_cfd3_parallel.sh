#!/usr/bin/env bash
# Two ranks against one, side by side: OpenFOAM's pimpleFoam and fvfsi on the Turek-Hron CFD3 channel
# of openfoam_cfd3_cost.sh (same PISO settings, same dt and step count), each on one rank (pinned to
# core 0) and on two (mpirun -np 2; pimpleFoam decomposed by decomposePar into two halves along x,
# method simple: the Debian build has no scotch; fvfsi by p4est), the four runs alternating in every
# round so that a drift of the machine hits all of them.
# Prints per round and as medians the wall seconds, the speed-up T1 / T2 and the parallel efficiency
# E = T1 / (2 T2) of each code, and writes them as JSON.
#
#   usage (from the project root):
#     openfoam_cfd3_parallel.sh FVFSI_EXECUTABLE [LEVEL=1] [STEPS=400] [DT=0.00025] [ROUNDS=3] [JSON]
#   LEVEL 1: pimpleFoam 20 280 cells, fvfsi n = 40 (20 960 cells); LEVEL 2: 81 120 against n = 80
#   (83 676 cells); LEVEL 1.5: 45 684 against n = 60 (47 160 cells, the shipped FSI3's fluid).
#   needs: apt-get install -y openfoam python3-numpy   (OpenFOAM v1912 from Debian)
set -euo pipefail
HERE=${PEER:-$(cd "$(dirname "$0")/../../../shared/peers/openfoam-cfd3" && pwd)}
FV=${1:?usage: openfoam_cfd3_parallel.sh FVFSI_EXECUTABLE [LEVEL] [STEPS] [DT] [ROUNDS] [JSON]}
LEVEL=${2:-1}; STEPS=${3:-400}; DT=${4:-0.00025}; ROUNDS=${5:-3}; JSON=${6:-}
case $LEVEL in 1) N=40 ;; 1.5) N=60 ;; 2) N=80 ;; *) echo "LEVEL must be 1, 1.5 or 2" >&2; exit 1 ;; esac
PRM=${PRM:-$(pwd)/prm/turek_hron_cfd3.prm}
END=$(python3 -c "print($STEPS*$DT)")
source "$(dirname "$0")/peer_common.sh"
openfoam_case "$C" transient pimpleFoam "$LEVEL" 2.0 "$END" "$DT"
of_cells=$OF_CELLS
cat > "$C/system/decomposeParDict" <<EOD
FoamFile { version 2.0; format ascii; class dictionary; object decomposeParDict; }
numberOfSubdomains 2; method simple; simpleCoeffs { n (2 1 1); delta 0.001; }
EOD
(cd "$C" && decomposePar -force > log.decomposePar 2>&1)
fvfsi_cfd3_args "$N" "$END" "$DT"
of1=(); of2=(); fv1=(); fv2=()
for r in $(seq "$ROUNDS"); do
  rm -rf "$C"/[1-9]* "$C"/0.[0-9]* "$C/postProcessing" "$C"/processor*/[1-9]* "$C"/processor*/0.[0-9]*
  t=$(cd "$C" && timed log.pimpleFoam.1 taskset -c 0 pimpleFoam) || exit 1; of1+=("$t")
  t=$(cd "$C" && timed log.pimpleFoam.2 mpirun -np 2 pimpleFoam -parallel) || exit 1; of2+=("$t")
  t=$(timed "$WORK/fv.1.log" taskset -c 0 "$FV" "$PRM" "${FVFSI_ARGS[@]}") || exit 1; fv1+=("$t")
  t=$(timed "$WORK/fv.2.log" mpirun -np 2 "$FV" "$PRM" "${FVFSI_ARGS[@]}") || exit 1; fv2+=("$t")
  echo "round $r: pimpleFoam ${of1[-1]} / ${of2[-1]} s, fvfsi ${fv1[-1]} / ${fv2[-1]} s (one / two ranks)"
done
fv_cells=$($PY -c "import json;print(json.load(open('$WORK/fv/summary.json'))['n_cells'])")
$PY - "$of_cells" "$fv_cells" "$STEPS" "${of1[*]}" "${of2[*]}" "${fv1[*]}" "${fv2[*]}" "$JSON" <<'EOP'
import json, sys, statistics as st
ofc, fvc, n = int(sys.argv[1]), int(sys.argv[2]), int(sys.argv[3])
t = {k: [float(x) for x in v.split()] for k, v in zip(("of1", "of2", "fv1", "fv2"), sys.argv[4:8])}
out = {"steps": n, "rounds": len(t["of1"])}
for code, cells, a, b in (("pimpleFoam", ofc, t["of1"], t["of2"]), ("fvfsi", fvc, t["fv1"], t["fv2"])):
    e = [x / (2 * y) for x, y in zip(a, b)]
    print(f"{code:10s} {cells} cells: one rank {['%.2f' % x for x in a]} (median {st.median(a):.2f} s), "
          f"two ranks {['%.2f' % x for x in b]} (median {st.median(b):.2f} s); efficiency per round "
          f"{['%.0f%%' % (100 * x) for x in e]}, median {100 * st.median(e):.0f}%, of the medians "
          f"{100 * st.median(a) / (2 * st.median(b)):.0f}%")
    out[code] = {"cells": cells, "one_rank_seconds": a, "two_ranks_seconds": b, "efficiency": e}
if sys.argv[8]:
    json.dump(out, open(sys.argv[8], "w"), indent=1)
EOP
