#!/usr/bin/env bash
# Where each of two ranks waits in MPI (doc/results/performance.md, section 8, "Who waits for
# whom"): the first 40 steps of prm/turek_hron_fsi3.prm (10 fluid alone, 30 coupled) on two
# ranks under `perf record --call-graph dwarf`, one profile per rank; then, per rank, the share of
# samples inside Open MPI (btl, pml, coll, opal, libmpi) and, for those, the first caller outside
# MPI and the innermost fvfsi function on the stack. `perf script` on the call-graph profiles is
# slow (about 50 minutes per rank on a 2-core AMD EPYC VM).
#   usage: doc/results/mpi_waits.sh [path/to/fvfsi [RUN_DIRECTORY]]
set -euo pipefail
cd "$(dirname "$0")/../.."
source doc/results/common.sh
fvfsi=$(realpath "${1:-build/fvfsi}")
runs=$(realpath -m "${2:-build/mpi_waits}")
mkdir -p "$runs"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
perf_each_rank "$runs/wrap.sh" -q --call-graph dwarf,16384 -F 499
fsi3_first_steps 0.03 "$runs/out"
mpirun -np 2 "$runs/wrap.sh" "$runs" "$fvfsi" "${fsi3_case[@]}" > "$runs/log" 2>&1
for r in 0 1; do perf script -i "$runs/perf.$r" -F ip,sym,dso 2> /dev/null > "$runs/script.$r"; done
/usr/bin/python3 - "$runs/script.0" "$runs/script.1" <<'PY'
import collections, re, sys
mpi = ("mca_btl_", "libopen-pal", "mca_coll", "mca_pml", "libmpi.so")
for name in sys.argv[1:]:
    total, waits, who, stack = 0, 0, collections.Counter(), []
    def flush():
        global total, waits
        if not stack:
            return
        total += 1
        if any(m in stack[0][1] for m in mpi):  # the sample's own frame is in MPI
            waits += 1
            caller = next((s for s, d in stack if not any(m in d for m in mpi)), "?")
            fv = [s for s, d in stack if "libfvfsi" in d]
            who[(caller[:60], fv[0][:70] if fv else "-")] += 1
    for line in open(name):
        line = line.strip()
        if not line:
            flush()
            stack = []
            continue
        m = re.match(r"(\S+) (.*) \((.*)\)$", line)
        if m:
            stack.append((m.group(2), m.group(3)))
    flush()
    print("== %s: %d samples, %.1f%% in MPI" % (name, total, 100.0 * waits / total))
    for (caller, fv), n in who.most_common(12):
        print("%6.2f%%  %-60s %s" % (100.0 * n / total, caller, fv))
PY
