#!/usr/bin/env bash
# The whole shipped FSI3 run (prm/turek_hron_fsi3.prm, 0-5 s) before and after the self-converging
# PISO correctors (hard_cases.md, section 4): with `Fluid/Max pressure correctors = 2` (two
# correctors in every step, the arithmetic of fvfsi before them) and at the defaults, the two runs
# side by side on two cores (one rank each, started together, so that the machine's drift and any
# other load fall on both). Writes RUNS/shipped_fixed2.json and RUNS/shipped_default.json
# (fsi_benchmark.py records: statistics over [4, 5] s, errors, cost), appends them to
# doc/results/hard_cases_fsi3_whole.jsonl and prints the table. About 60-70 minutes.
#
#   usage (from the project root): doc/results/hard_cases_fsi3_whole.sh [FVFSI [RUNS]]
set -euo pipefail
cd "$(dirname "$0")/../.."
python=${PYTHON:-/usr/bin/python3} # Debian's, with python3-numpy and python3-matplotlib
source doc/results/fsi_runs.sh
study_arguments build/fsi3_whole "$@" # fvfsi, runs; the machine line
run_fsi fsi3 shipped_fixed2 4 5 "Fluid/Max pressure correctors=2" &
run_fsi fsi3 shipped_default 4 5 &
wait
machine
"$python" -c 'import json, sys; [print(json.dumps(json.load(open(f)))) for f in sys.argv[1:]]' \
  "$runs/shipped_fixed2.json" "$runs/shipped_default.json" >> doc/results/hard_cases_fsi3_whole.jsonl
"$python" doc/results/fsi_benchmark.py table fsi3 "$runs/shipped_fixed2.json" "$runs/shipped_default.json"
