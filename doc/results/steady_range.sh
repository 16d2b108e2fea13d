#!/usr/bin/env bash
# The steady fluid mode across the steady range without retuning (issue 15, item 2;
# doc/results/fluid_stability.md): prm/turek_hron_cfd2.prm as shipped (Momentum relaxation 0.95,
# steady tolerance 5e-5) with the mean inflow U = Re nu / D (D = 0.1 m, nu = 1e-3 m^2/s) on
#   - the Turek-Hron channel with the rigid flag (fvfsi_turek_hron_channel 32, 13 409 cells), and
#   - deal.II's channel_with_cylinder (no flag; 0.03: 2: 2.0: true, refined 4 times: 27 648 cells),
# Re = 1, 5, 10, 20, 40, 60, 100 (MESHES="turek_hron channel_with_cylinder" by default). Prints a
# table: pseudo steps, final Momentum relaxation, drag, wall time, or the message the run stopped
# with; writes doc/results/steady_range.png. One rank, one run at a time, about 10 minutes.
#   usage: doc/results/steady_range.sh [path/to/fvfsi [RUN_DIRECTORY]]
set -uo pipefail
cd "$(dirname "$0")/../.."
source doc/results/common.sh
study_arguments build/steady_range "$@"
echo
echo "| mesh | Re | cells | pseudo steps | alpha at the end | drag [N/m] | wall [s] | stopped with |"
echo "|---|---|---|---|---|---|---|---|"
for mesh in ${MESHES:-turek_hron channel_with_cylinder}; do
  if [[ $mesh == turek_hron ]]; then
    geometry=(--set "Mesh/Generator arguments=32")
  else
    geometry=(--set "Mesh/Generator=channel_with_cylinder"
              --set "Mesh/Generator arguments=0.03: 2: 2.0: true"
              --set "Mesh/Global refinements=4"
              --set "Mesh/Patch names=0: inlet, 1: outlet, 2: cylinder, 3: walls"
              --set "Fluid/Wall=walls, cylinder" --set "Fluid scene/Force patches=cylinder")
  fi
  for re in 1 5 10 20 40 60 100; do
    out=$runs/${mesh}_re$re
    U=$(/usr/bin/python3 -c "print($re * 1e-3 / 0.1)")
    start=$(date +%s.%N)
    "$fvfsi" prm/turek_hron_cfd2.prm "${geometry[@]}" \
      --set "Fluid/Velocity inlet=inlet: 1.5*$U*4*y*(0.41-y)/0.41^2; 0" \
      --set "Output directory=$out" > "$out.log" 2>&1
    wall=$(/usr/bin/python3 -c "print('%.1f' % ($(date +%s.%N) - $start))")
    /usr/bin/python3 - "$mesh" "$re" "$out" "$wall" <<'PY'
import json, re, sys
mesh, Re, out, wall = sys.argv[1:]
log = open(out + ".log").read()
alphas = re.findall(r"lowered from \S+ to (\S+)", log)
alpha = alphas[-1] if alphas else "0.95"
try:
    s = json.load(open(out + "/summary.json"))
except FileNotFoundError:
    s = {"status": "failed", "error": "no summary.json"}
if s.get("status") == "completed":
    r = s["results"]
    print("| %s | %s | %d | %d | %s | %.6g | %s | |" % (mesh, Re, s["n_cells"], r["time_steps"], alpha, r["drag"], wall))
else:
    steps = re.findall(r"to (\d+)\) the relative change", s.get("error", ""))
    message = s.get("error", "").replace("|", "/")
    print("| %s | %s | | %s | %s | | %s | %s |" % (mesh, Re, steps[0] if steps else "", alpha, wall, message))
PY
  done
done

# The plot: pseudo steps per Re for each mesh (a run that stopped: a cross at its last step).
/usr/bin/python3 - "$runs" doc/results/steady_range.png ${MESHES:-turek_hron channel_with_cylinder} <<'PY'
import json, os, re, sys
import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
runs, png, meshes = sys.argv[1], sys.argv[2], sys.argv[3:]
fig, ax = plt.subplots(figsize=(6, 3.5))
for mesh in meshes:
    done, stopped = [], []
    for Re in (1, 5, 10, 20, 40, 60, 100):
        path = "%s/%s_re%d/summary.json" % (runs, mesh, Re)
        if not os.path.exists(path):
            continue
        s = json.load(open(path))
        if s.get("status") == "completed":
            done.append((Re, s["results"]["time_steps"]))
        else:
            steps = re.findall(r"to (\d+)\) the relative change", s.get("error", ""))
            if steps:
                stopped.append((Re, int(steps[0])))
    line, = ax.plot(*zip(*done), "o-", label=mesh + " (converged)") if done else (None,)
    if stopped:
        ax.plot(*zip(*stopped), "x", ms=10, color=line.get_color() if line else None,
                label=mesh + " (stopped: no steady state)")
ax.set_xscale("log")
ax.set_xlabel("Re = U D / nu")
ax.set_ylabel("pseudo time steps")
ax.grid(alpha=0.3)
ax.legend(fontsize=8)
fig.tight_layout()
fig.savefig(png, dpi=100)
print("wrote", png)
PY
