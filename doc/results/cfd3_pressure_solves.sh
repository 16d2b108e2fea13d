#!/usr/bin/env bash
# The shipped CFD3 run (prm/turek_hron_cfd3.prm: n = 48, dt = 1 ms, to 11 s) as shipped and with
# fewer pressure solves per step (performance.md, section 15): OPTIONS (--set arguments, default
# no non-orthogonal corrector) against the file as it is, side by side on two cores (one rank
# each, started together, so that the machine's drift and any other load fall on both). Prints
# cfd.md's table rows (mean, amplitude and frequency of the last 1 s against the reference) and
# appends both summaries to doc/results/cfd3_pressure_solves.jsonl. About 40 minutes.
#
#   usage (from the project root): doc/results/cfd3_pressure_solves.sh [FVFSI [RUNS]]
#   e.g. OPTIONS='--set "Fluid/Non-orthogonal correctors=1"' doc/results/cfd3_pressure_solves.sh
set -euo pipefail
cd "$(dirname "$0")/../.."
source doc/results/common.sh
study_arguments build/cfd3_pressure_solves "$@" # fvfsi, runs; the machine line
eval "options=(${OPTIONS:---set \"Fluid/Non-orthogonal correctors=0\"})"
run() { # NAME [--set ...]
  local name=$1
  shift
  "$fvfsi" prm/turek_hron_cfd3.prm --set "Fluid scene/Output interval=0" \
    --set "Output directory=$runs/$name" "$@" > "$runs/$name.log" 2>&1
}
run shipped &
run fewer_solves "${options[@]}" &
wait
field() { /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); print(eval(sys.argv[2]))" "$@"; }
echo "options: ${options[*]}"
echo "| run | drag mean | drag amplitude | lift amplitude | frequency [Hz] | pressure solves | wall [s] |"
echo "|---|---|---|---|---|---|---|"
for name in shipped fewer_solves; do
  s=$runs/$name/summary.json
  d="d['results']['drag_mean_amplitude_frequency']"; l="d['results']['lift_mean_amplitude_frequency']"
  echo "| $name | $(field $s "'%.2f (%+.2f%%)' % ($d[0], 100*($d[0]/439.45-1))") | $(field $s "'%.3f (%+.1f%%)' % ($d[1], 100*($d[1]/5.6183-1))") | $(field $s "'%.2f (%+.2f%%)' % ($l[1], 100*($l[1]/437.81-1))") | $(field $s "'%.4f (%+.2f%%)' % ($l[2], 100*($l[2]/4.3956-1))") | $(grep -o 'fluid pressure: [0-9]* linear solves' $runs/$name.log | grep -o '[0-9]*') | $(field $s "'%.0f' % d['wall_seconds']") |"
  /usr/bin/python3 -c "import json,sys; d=json.load(open(sys.argv[1])); d['run']=sys.argv[2]; d['options']=sys.argv[3]; print(json.dumps(d))" \
    "$s" "$name" "$([[ $name == shipped ]] && echo '' || echo "${options[*]}")" >> doc/results/cfd3_pressure_solves.jsonl
done
