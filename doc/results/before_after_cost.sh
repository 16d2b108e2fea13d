#!/usr/bin/env bash
# The cost of a change, side by side: two fvfsi binaries (BEFORE, AFTER: each next to its
# libfvfsi_lib.so) on the same cases, alternating BEFORE AFTER BEFORE AFTER ... ROUNDS times, so
# that a drift of the shared machine hits both; one rank each, nothing else should run.
#   pimple: prm/turek_hron_cfd3.prm at n = 40 (20 960 cells), full inflow from rest, 400 PISO
#           steps of 0.25 ms (the PISO cost case of doc/benchmarks/openfoam_cfd3_cost.sh);
#   fsi3:   the first 40 steps of prm/turek_hron_fsi3.prm as shipped (47 160 + 738 cells; 10
#           steps of the fluid alone, 30 coupled; common.sh's fsi3_first_steps).
# Prints the machine, each run's wall seconds, the medians and AFTER / BEFORE, and checks that the
# two give the same results (drag and lift in summary.json, printed with 10 digits).
#
#   usage (from the project root): [CASES="pimple fsi3"] [WORK=DIR] \
#     doc/results/before_after_cost.sh BEFORE AFTER [ROUNDS=3]
set -euo pipefail
source "$(dirname "$0")/common.sh"
BEFORE=$(realpath "$1"); AFTER=$(realpath "$2"); ROUNDS=${3:-3}
WORK=${WORK:-$(mktemp -d)}
mkdir -p "$WORK"
machine_line "before $BEFORE, after $AFTER"

cfd3_case=(prm/turek_hron_cfd3.prm --set "Mesh/Generator arguments=40" --set "Time/End time=0.1"
           --set "Time/Time step=0.00025" --set "Fluid scene/Output interval=0"
           --set "Fluid/Velocity inlet=inlet: 1.5*2*4*y*(0.41-y)/0.41^2; 0")

# run BINARY CASE LABEL: runs the case with the binary's own library; prints the wall seconds.
run() {
  local binary=$1 case_name=$2 out=$WORK/$2_$3
  if [ "$case_name" = pimple ]; then
    args=("${cfd3_case[@]}" --set "Output directory=$out")
  else
    fsi3_first_steps 0.03 "$out"
    args=("${fsi3_case[@]}")
  fi
  local start end
  start=$(date +%s.%N)
  LD_LIBRARY_PATH=$(dirname "$binary") "$binary" "${args[@]}" > "$out.log" 2>&1
  end=$(date +%s.%N)
  echo "$end - $start" | bc
}

for case_name in ${CASES:-pimple fsi3}; do
  before=(); after=()
  for r in $(seq "$ROUNDS"); do
    before+=("$(run "$BEFORE" $case_name before)")
    after+=("$(run "$AFTER" $case_name after)")
  done
  /usr/bin/python3 - "$case_name" "${before[*]}" "${after[*]}" "$WORK/${case_name}_before" \
    "$WORK/${case_name}_after" <<'EOP'
import json, statistics as st, sys
name, b, a = sys.argv[1], [float(x) for x in sys.argv[2].split()], [float(x) for x in sys.argv[3].split()]
def forces(d):
    r = json.load(open(d + "/summary.json"))["results"]
    return "drag %.10g, lift %.10g" % (r["drag"], r["lift"])
print("%s: before %s s (median %.2f), after %s s (median %.2f), after / before %.3f" %
      (name, " ".join("%.2f" % x for x in b), st.median(b), " ".join("%.2f" % x for x in a),
       st.median(a), st.median(a) / st.median(b)))
pairs = [y / x for x, y in zip(b, a)]
print("  after / before pair by pair: %s, median %.3f" % (" ".join("%.3f" % r for r in pairs),
                                                        st.median(pairs)))
print("  before: %s\n  after:  %s" % (forces(sys.argv[4]), forces(sys.argv[5])))
EOP
done
