#!/usr/bin/env bash
# Two builds of fvfsi side by side on one and two ranks (doc/results/log.md, "Where the two ranks
# met and waited"): the first 40 steps of prm/turek_hron_fsi3.prm (10 steps
# of the fluid alone, 30 coupled), REPEATS rounds, each round running build A on 1 and 2 ranks,
# then build B on 1 and 2 ranks. Prints per build the coupled-step seconds of every run, the
# efficiency T1 / (2 T2) from the medians and the median of the pairs of one round, and the
# medians of some timer sections on 1 and 2 ranks. A build directory holds `fvfsi` and
# `libfvfsi_lib.so` (copy both out of build/ to keep a build while the tree changes). Arguments
# after the two directories go to every run. A completed run in RUN_DIRECTORY is not run again.
#   usage: doc/results/fsi_parallel_ab.sh RUN_DIRECTORY REPEATS BUILD_A BUILD_B [--set ...]
set -euo pipefail
cd "$(dirname "$0")/../.."
source doc/results/common.sh
runs=$1 repeats=$2 a=$3 b=$4
shift 4
mkdir -p "$runs"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
machine_line
for r in $(seq 1 "$repeats"); do
  for build in A B; do
    dir=$a; [[ $build == B ]] && dir=$b
    for np in 1 2; do
      out=$runs/${build}_np${np}_$r
      completed "$out" && continue
      fsi3_first_steps 0.03 "$out"
      LD_LIBRARY_PATH=$dir mpirun -np "$np" "$dir/fvfsi" "${fsi3_case[@]}" "$@" > "$out.log" 2>&1
    done
  done
done
/usr/bin/python3 - "$runs" "$repeats" "$a" "$b" <<'PY'
import json, statistics, sys
runs, repeats = sys.argv[1], int(sys.argv[2])
for build, name in (("A", sys.argv[3]), ("B", sys.argv[4])):
    s = {(np, r): json.load(open("%s/%s_np%d_%d/summary.json" % (runs, build, np, r)))
         for np in (1, 2) for r in range(1, repeats + 1)}
    t = {np: [s[(np, r)]["results"]["coupled_wall_seconds"] for r in range(1, repeats + 1)]
         for np in (1, 2)}
    m = {np: statistics.median(t[np]) for np in (1, 2)}
    pairs = statistics.median(a / (2 * b) for a, b in zip(t[1], t[2]))
    print("%s (%s): one rank %s, two ranks %s; efficiency %.0f%% (medians) / %.0f%% (pairs)" % (
        build, name, ", ".join("%.2f" % x for x in t[1]), ", ".join("%.2f" % x for x in t[2]),
        50 * m[1] / m[2], 100 * pairs))
    for section in ("fluid", "fluid: pressure solve", "fluid: momentum solve", "solid",
                    "mesh motion", "geometry"):
        one, two = (statistics.median(s[(np, r)]["timing"][section]
                                      for r in range(1, repeats + 1)) for np in (1, 2))
        print("   %-24s %7.2f -> %7.2f s (%.0f%%)" % (section, one, two, 50 * one / two))
PY
