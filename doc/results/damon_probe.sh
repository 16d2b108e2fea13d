#!/usr/bin/env bash
# Does the guest kernel's DAMON page reclaim (the kernel thread kdamond, which samples the
# accessed bits of physical pages every 0.5 s and pages out cold ones) disturb the
# two-rank runs (doc/results/performance.md, section 8, "A coarse solve on both ranks, coupled
# aggregation and the guest's page reclaim")? The first 40 steps of prm/turek_hron_fsi3.prm (10
# steps of the fluid alone, 30 coupled), rounds FIRST_ROUND to LAST_ROUND; each runs one rank on
# core 0 and two ranks with kdamond on, then the same two with it off. Prints each run's
# coupled-step seconds and geometry section (local loops: the check on the moment) and the
# efficiency T1 / (2 T2) of every round in each state. Needs root and a kernel with DAMON's sysfs
# interface; leaves kdamond on at the end. A completed run in RUN_DIRECTORY is not run again.
#   usage: doc/results/damon_probe.sh BUILD RUN_DIRECTORY FIRST_ROUND LAST_ROUND
#   (BUILD holds `fvfsi` and `libfvfsi_lib.so`, e.g. build/)
set -euo pipefail
cd "$(dirname "$0")/../.."
source doc/results/common.sh
dir=$1 runs=$2 first=$3 last=$4
state=/sys/kernel/mm/damon/admin/kdamonds/0/state
if [[ ! -w $state ]]; then
  echo "damon_probe.sh: $state is not writable (no DAMON, or not root)" >&2
  exit 1
fi
mkdir -p "$runs"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
trap 'echo on > $state 2> /dev/null || true' EXIT
machine_line
for r in $(seq "$first" "$last"); do
  for st in on off; do
    [[ $(cat $state) == "$st" ]] || echo $st > $state
    for np in 1 2; do
      out=$runs/${st}_${np}_$r
      completed "$out" && continue
      if [[ $np == 1 ]]; then launch=(taskset -c 0); else launch=(mpirun -np 2); fi
      fsi3_first_steps 0.03 "$out"
      LD_LIBRARY_PATH=$dir "${launch[@]}" "$dir/fvfsi" "${fsi3_case[@]}" > "$out.log" 2>&1
    done
  done
done
/usr/bin/python3 - "$runs" "$first" "$last" <<'PY'
import json, statistics, sys
runs, rounds = sys.argv[1], range(int(sys.argv[2]), int(sys.argv[3]) + 1)
for st in ("on", "off"):
    s = {(np, r): json.load(open("%s/%s_%d_%d/summary.json" % (runs, st, np, r)))
         for np in (1, 2) for r in rounds}
    t = {np: [s[(np, r)]["results"]["coupled_wall_seconds"] for r in rounds] for np in (1, 2)}
    for np in (1, 2):
        print("kdamond %-3s %d rank(s): coupled steps [s] %s (median %.2f); geometry [s] %s" % (
            st, np, ", ".join("%.2f" % x for x in t[np]), statistics.median(t[np]),
            ", ".join("%.2f" % s[(np, r)]["timing"]["geometry"] for r in rounds)))
    e = [a / (2 * b) for a, b in zip(t[1], t[2])]
    print("kdamond %-3s E per round: %s; median %.1f%%" % (
        st, ", ".join("%.0f%%" % (100 * x) for x in e), 100 * statistics.median(e)))
PY
