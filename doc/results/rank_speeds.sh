#!/usr/bin/env bash
# Was one core slower than the other during a two-rank run? (doc/results/log.md, "An eleventh pass,
# and what each core did in the disturbed runs".)
# The first 40 steps of prm/turek_hron_fsi3.prm (10 fluid alone, 30 coupled) on two ranks, each
# under `perf record` (flat, 999 samples per second of its core's time), ROUNDS times. Both ranks
# hold the same number of fluid cells (p4est's even split), so the loops that touch only a rank's
# own cells - Epetra's matrix-vector products, the face loops of the fluid and the mesh motion, the
# gradients and the geometry (`local` below) - do the same work on both; the samples each rank
# spends in them are its core's time for that work, and their ratio (rank 1 / rank 0) is how much
# slower core 1 ran than core 0 (1.00: the same speed), whatever the ranks waited. Per round: the
# two-rank run's coupled-step wall time, each rank's samples in those loops (l0, l1) and in Open MPI
# (mostly waiting), the ratio, and what a partition in proportion to the two cores' speeds would
# save at most on those loops, free of any cost of moving cells:
# 1 - 2 l0 l1 / ((l0 + l1) max(l0, l1)). Needs perf (Debian: linux-perf) and two free cores.
#   usage: doc/results/rank_speeds.sh [path/to/fvfsi [RUN_DIRECTORY [ROUNDS]]]
set -euo pipefail
cd "$(dirname "$0")/../.."
source doc/results/common.sh
fvfsi=$(realpath "${1:-build/fvfsi}")
runs=$(realpath -m "${2:-build/rank_speeds}")
rounds=${3:-3}
mkdir -p "$runs"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
machine_line "binary $fvfsi"
perf_each_rank "$runs/wrap.sh" -q -F 999
echo -n "round  coupled steps [s]  local loops: rank 0, rank 1 [samples]  "
echo "Open MPI: rank 0, rank 1  rank 1 / rank 0  saving"
for round in $(seq 1 "$rounds"); do
  dir="$runs/round$round"
  mkdir -p "$dir"
  fsi3_first_steps 0.03 "$dir/out"
  mpirun -np 2 "$runs/wrap.sh" "$dir" "$fvfsi" "${fsi3_case[@]}" > "$dir/log" 2>&1
  for r in 0 1; do
    perf report -i "$dir/perf.$r" --no-children --sort dso,sym -n --stdio 2> /dev/null \
      > "$dir/report.$r"
  done
  /usr/bin/python3 - "$dir" "$round" <<'PY'
import json, re, sys
directory, round_ = sys.argv[1], sys.argv[2]
# Loops over a rank's own cells and faces: Epetra's matrix-vector product, fvfsi's face loops.
local = ("epetra_dcrsmv_", "Laplacian", "VertexInterpolation::interpolate", "GaussGreenGradient",
         "compute_predicted_fluxes", "assemble_momentum", "FVGeometry")
mpi = ("libmpi", "libopen-pal", "mca_")
def samples(rank):
    loops = waits = 0
    for line in open(f"{directory}/report.{rank}"):
        m = re.match(r"\s*[\d.]+%\s+(\d+)\s+(\S+)\s+\[.\]\s+(.*)$", line)
        if not m:
            continue
        n, dso, sym = int(m.group(1)), m.group(2), m.group(3)
        loops += n if any(s in sym for s in local) else 0
        waits += n if any(s in dso for s in mpi) else 0
    return loops, waits
(l0, w0), (l1, w1) = samples(0), samples(1)
wall = json.load(open(f"{directory}/out/summary.json"))["results"]["coupled_wall_seconds"]
saving = 1 - 2 * l0 * l1 / ((l0 + l1) * max(l0, l1))
print(f"{round_:>5}  {wall:17.2f}  {l0:>20d}, {l1:<16d} {w0:>10d}, {w1:<10d} {l1 / l0:15.2f}  "
      f"{100 * saving:5.1f}%")
PY
done
