#!/usr/bin/env bash
# How often the ranks meet, and where in fvfsi (doc/results/performance.md, section 8, "Meetings
# that carried nothing"). Runs a case on two ranks with rank 0 under `perf record` on three
# uprobes of Open MPI: MPI_Allreduce (sums, norms, min/max), MPI_Waitall (the end of a ghost or
# boundary-face exchange, Epetra's imports) and MPI_Barrier. Every call is recorded with its
# stack; each is counted against the innermost fvfsi source line on its stack (addr2line with
# inlining, from the -g of the build). Prints the totals per kind and, per call site, the count
# (with PER: divided by the number in summary.json's results under that key, e.g.
# outer_iterations for the solid scene, solid_outer_iterations for FSI). Needs perf with uprobes
# (root) and a build with debug information (the Release flags of Debian's deal.II carry -g).
# FVFSI and RUN_DIRECTORY may be relative to the current directory; PRM is relative to the
# project root. perf drops a few calls when its buffers fill (repeated counts differ by ~1%).
#   usage: doc/results/mpi_meetings.sh FVFSI RUN_DIRECTORY [PER] -- PRM [--set ...]
#   e.g.:  doc/results/mpi_meetings.sh build/fvfsi build/meet outer_iterations -- \
#            prm/turek_hron_csm3.prm --set "Mesh/Generator arguments=123: 6" \
#            --set "Time/End time=0.05"
set -euo pipefail
fvfsi=$(realpath "$1")
runs=$(realpath -m "$2")
cd "$(dirname "$0")/../.."
per=""
[[ $3 != -- ]] && { per=$3; shift; }
shift 3
mkdir -p "$runs"
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
libmpi=$(ldd "$fvfsi" | awk '/libmpi\.so/ {print $3}' | head -1)
[[ -n $libmpi ]] ||
  libmpi=$(ldd "$(dirname "$fvfsi")/libfvfsi_lib.so" | awk '/libmpi\.so/ {print $3}' | head -1)
for f in MPI_Allreduce MPI_Waitall MPI_Barrier; do
  perf probe -q -x "$(realpath "$libmpi")" "$f" 2> /dev/null || true
done
cat > "$runs/wrap.sh" << WRAP
#!/bin/bash
if [ "\$OMPI_COMM_WORLD_RANK" = 0 ]; then
  exec perf record -q -e probe_libmpi:MPI_Allreduce -e probe_libmpi:MPI_Waitall \
    -e probe_libmpi:MPI_Barrier --call-graph dwarf,16384 -o $runs/perf.data "\$@"
fi
exec "\$@"
WRAP
chmod +x "$runs/wrap.sh"
# The library beside FVFSI (a build copied out of build/ runs its own copy).
export LD_LIBRARY_PATH=$(dirname "$fvfsi")${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
mpirun -np 2 -x LD_LIBRARY_PATH "$runs/wrap.sh" "$fvfsi" "$@" --set "Output directory=$runs/out" \
  > "$runs/log" 2>&1
perf script -i "$runs/perf.data" -F event,ip,sym,dso 2> /dev/null > "$runs/script"
/usr/bin/python3 - "$runs" "$per" "$(dirname "$fvfsi")/libfvfsi_lib.so" << 'PY'
import collections, json, re, subprocess, sys
runs, per, lib = sys.argv[1:4]
n = json.load(open(runs + "/out/summary.json"))["results"][per] if per else 1
kinds, sites = collections.Counter(), collections.Counter()
for block in open(runs + "/script").read().split("\n\n"):
    lines = [l.strip() for l in block.strip().split("\n") if l.strip()]
    if not lines:
        continue
    kind = lines[0].split(":")[1]
    kinds[kind] += 1
    for l in lines[1:]:  # the innermost frame in fvfsi's library
        m = re.match(r"(\S+) .* \((.*)\)$", l)
        if m and "libfvfsi" in m.group(2):
            sites[(kind, m.group(1))] += 1
            break
    else:
        sites[(kind, "")] += 1
def where(ip):
    if not ip:
        return "(outside fvfsi: set-up, deal.II, Trilinos)"
    out = subprocess.run(["addr2line", "-i", "-f", "-C", "-e", lib, "0x" + ip],
                         capture_output=True, text=True).stdout.strip().split("\n")
    chain = []
    for k in range(0, len(out) - 1, 2):
        function = re.sub(r"<.*?>", "", re.sub(r"\(.*", "", out[k])).split("::")[-1]
        chain.append(function + " " + out[k + 1].split("/")[-1].split(" ")[0])
    return " < ".join(chain[:3])
print("meetings of rank 0: " + ", ".join("%s %d" % kv for kv in sorted(kinds.items())) +
      ("; per %s (%d): %.1f" % (per, n, sum(kinds.values()) / n) if per else ""))
print("| count | per %s | call | innermost fvfsi source line (< its callers) |" % (per or "run"))
print("|---|---|---|---|")
for (kind, ip), c in sites.most_common(40):
    print("| %d | %.2f | %s | %s |" % (c, c / n, kind, where(ip)))
PY
