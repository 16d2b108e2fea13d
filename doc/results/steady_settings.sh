#!/usr/bin/env bash
# The steady settings (issue 56, item 5; source/app/steady_settings.cc): each steady case run twice
# side by side, alternating, with the same binary: "as given" (the transient defaults set
# explicitly with --set, as every run took them before the steady settings existed) and "steady
# settings" (the file as it is: every steady setting the file does not give is taken). Cases:
#   fsi3_as_fsi1  the issue's case: prm/turek_hron_fsi3.prm with FSI1's data (E = 1.4e6 Pa, mean
#                 inflow 0.2 m/s) and Fluid/Transient = Solid/Transient = false, as a user would
#                 switch it, and Coupling/Start time = 0 (the file's 2 s stops a steady run with
#                 an error that says to set 0); the reference values of FSI1
#   cfd2, cavity, kovasznay, thick_plate   the shipped steady files that leave some unset
#   thick_plate_h025   the 3D thick plate one refinement below its shipped meshes
# Prints one JSON line per run (case, variant, wall s, pseudo steps or coupling iterations,
# results) and appends it to doc/results/steady_settings.jsonl.
#   usage: doc/results/steady_settings.sh [path/to/fvfsi [RUN_DIRECTORY [REPEATS [CASES...]]]]
#   environment: VARIANTS (default "as_given steady_settings"); LIMIT: stop a run after this many
#   seconds (recorded as "stopped at LIMIT s" with the last progress line of its log)
set -euo pipefail
cd "$(dirname "$0")/../.."
source doc/results/common.sh
study_arguments build/steady_settings "${1:-}" "${2:-}"
repeats=${3:-3}
shift $(( $# < 3 ? $# : 3 ))
cases=("$@")
[ ${#cases[@]} -gt 0 ] || cases=(fsi3_as_fsi1 cfd2 cavity kovasznay thick_plate)
jsonl=doc/results/steady_settings.jsonl

# The transient defaults of the parameters the steady settings set (fluid_parameters.cc,
# linear_solver.cc), for the "as given" runs; a file's own values are not overridden.
before_momentum="Fluid momentum solver/Residual reduction=1e-3"
before_pressure="Fluid pressure solver/Residual reduction=1e-6"
before_corrector="Fluid pressure solver/Corrector residual reduction=0"
before_simple="Fluid/Consistent pressure coupling=false"
before_tolerance="Fluid/Steady tolerance=1e-8"

case_arguments() { # CASE: sets prm and args (the case) and before (its "as given" overrides)
  case $1 in
    fsi3_as_fsi1)
      prm=prm/turek_hron_fsi3.prm
      args=(--set "Fluid/Transient=false" --set "Solid/Transient=false"
            --set "Solid/Young's modulus=1.4e6"
            --set "Fluid/Velocity inlet=inlet: 1.5*0.2*4*y*(0.41-y)/0.41^2; 0"
            --set "Fluid scene/Output interval=0" --set "Coupling/Start time=0")
      before=("$before_momentum" "$before_pressure" "$before_simple" "$before_tolerance") ;;
    cfd2) prm=prm/turek_hron_cfd2.prm; args=(); before=("$before_corrector" "$before_simple") ;;
    cavity) prm=prm/cavity_rigid_bottom.prm; args=(); before=("$before_corrector" "$before_simple") ;;
    kovasznay)
      prm=prm/kovasznay.prm; args=()
      before=("$before_momentum" "$before_pressure" "$before_corrector" "$before_simple") ;;
    thick_plate) prm=prm/thick_plate.prm; args=(); before=("$before_corrector" "$before_simple") ;;
    thick_plate_h025) # one refinement below the shipped meshes (fsi_3d.md's middle row)
      prm=prm/thick_plate.prm
      args=(--set "Mesh/Generator arguments=0.025" --set "Solid mesh/Generator arguments=0.0125")
      before=("$before_corrector" "$before_simple") ;;
    *) echo "unknown case $1" >&2; exit 1 ;;
  esac
}

for r in $(seq "$repeats"); do
  for c in "${cases[@]}"; do
    case_arguments "$c"
    for variant in ${VARIANTS:-as_given steady_settings}; do
      dir="$runs/$c-$variant-$r"
      extra=()
      if [ $variant = as_given ]; then for b in "${before[@]}"; do extra+=(--set "$b"); done; fi
      limit=(); [ -z "${LIMIT:-}" ] || limit=(timeout "$LIMIT")
      "${limit[@]}" "$fvfsi" "$prm" "${args[@]}" "${extra[@]}" --set "Output directory=$dir" \
        --set "Plot history=false" > "$dir.log" 2>&1 || true
      /usr/bin/python3 - "$dir" "$c" "$variant" "$r" "$(machine_line)" "${LIMIT:-}" <<'EOP' | tee -a "$jsonl"
import json, sys
d, case, variant, r, machine, limit = sys.argv[1:7]
try:
    s = json.load(open(d + "/summary.json"))
except Exception:
    progress = [l.strip() for l in open(d + ".log") if "pseudo" in l or "coupling iteration" in l]
    s = {"status": "stopped at %s s" % limit if limit else "no summary",
         "error": progress[-1] if progress else None, "wall_seconds": float(limit) if limit else None}
res = s.get("results", {})
keep = {k: res[k] for k in ("drag", "lift", "coupling_iterations", "fluid_pseudo_steps",
                           "time_steps", "point_A_displacement", "max_velocity_error",
                           "l2_velocity_error", "continuity_error") if k in res}
print(json.dumps({"case": case, "variant": variant, "repeat": int(r), "status": s.get("status"),
                  "error": s.get("error"), "wall_seconds": s.get("wall_seconds"),
                  "cells": s.get("n_cells"), "results": keep, "machine": machine}))
EOP
    done
  done
done
