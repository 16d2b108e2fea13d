#!/bin/bash
# Build doc/benchmarks/core_performance in Release and run the FV-core benchmark cases on one core
# (one MPI rank, one thread), one process per case; print the machine and a Markdown table
# (the one in doc/results/core.md).
#
#   doc/benchmarks/run_core.sh [BUILD_DIR] [REPEATS]
#
# BUILD_DIR defaults to /work/build-bench, REPEATS (samples per timing; the median is reported)
# to 3. Raw `key value` results of every case are left in BUILD_DIR/core_results/.
# Every case runs twice: REPEATS samples with the process's normal malloc settings, then one
# sample with glibc's malloc defaults restored (--malloc-defaults 1, a memory experiment).
# Run time: about 3 minutes of CPU (the 1e6-cell case takes most of it), plus the build.
set -euo pipefail

SOURCE_DIR=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
BUILD_DIR=${1:-/work/build-bench}
REPEATS=${2:-3}
RESULTS=$BUILD_DIR/core_results

mkdir -p "$BUILD_DIR" "$RESULTS"
cmake -S "$SOURCE_DIR" -B "$BUILD_DIR" -DCMAKE_BUILD_TYPE=Release > "$RESULTS/cmake.log"
make -C "$BUILD_DIR" -j"$(nproc)" core_performance > "$RESULTS/make.log"

{
  echo "Machine: $(nproc) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2- | sed 's/^ *//')), \
$(awk '/MemTotal/ {printf "%.1f GiB", $2 / 1048576}' /proc/meminfo) RAM; \
$(uname -sr); deal.II $(sed -n 's/^#define DEAL_II_PACKAGE_VERSION "\(.*\)"/\1/p' /usr/include/deal.II/base/config.h 2>/dev/null); \
fvfsi $(git -C "$SOURCE_DIR" rev-parse --short HEAD 2>/dev/null)$(git -C "$SOURCE_DIR" diff --quiet HEAD -- source include 2>/dev/null || echo ' (with uncommitted changes in source/ or include/)')."
  echo -n "Date: $(date -u '+%Y-%m-%d %H:%M UTC'); load average (1, 5, 15 min) before the run: $(cut -d' ' -f1-3 /proc/loadavg)"
} > "$RESULTS/machine.txt"

export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
EXE=$BUILD_DIR/doc/benchmarks/core_performance

# name  dim  coarse subdivisions per direction  global refinements
CASES=(
  "2d_1e5 2 5 6"   # 320^2  =   102,400 cells
  "2d_1e6 2 1 10"  # 1024^2 = 1,048,576 cells
  "3d_1e5 3 3 4"   # 48^3   =   110,592 cells
)
for c in "${CASES[@]}"; do
  read -r name dim sub ref <<< "$c"
  echo "running $name: dim $dim, $sub^$dim coarse cells, $ref refinements, $REPEATS repeats" >&2
  "$EXE" --dim "$dim" --subdivisions "$sub" --refinements "$ref" --repeats "$REPEATS" \
    --out "$RESULTS/$name.txt" > "$RESULTS/$name.log"
  # The memory experiment: glibc's malloc defaults restored (one sample per timing).
  echo "running $name with --malloc-defaults 1, 1 repeat" >&2
  "$EXE" --dim "$dim" --subdivisions "$sub" --refinements "$ref" --repeats 1 --malloc-defaults 1 \
    --out "$RESULTS/${name}_malloc.txt" > "$RESULTS/${name}_malloc.log"
done
printf ', after: %s.\n\n' "$(cut -d' ' -f1-3 /proc/loadavg)" >> "$RESULTS/machine.txt"

python3 - "$RESULTS" "${CASES[@]%% *}" <<'EOF' | tee "$RESULTS/table.md"
import sys, os
results, names = sys.argv[1], sys.argv[2:]
data, malloc_data = {}, {}
def read(file):
    d = {}
    for line in open(file):
        k, v = line.split(None, 1)
        v = v.strip()
        try:
            d[k] = float(v)
        except ValueError:
            d[k] = v
    return d
for n in names:
    data[n] = read(os.path.join(results, n + ".txt"))
    malloc_data[n] = read(os.path.join(results, n + "_malloc.txt"))

def header():
    cols = []
    for n in names:
        d = data[n]
        cols.append(f"{int(d['dim'])}D, {int(d['cells']):,} cells")
    print("| | " + " | ".join(cols) + " |")
    print("|---|" + "---|" * len(names))

def time_row(label, key):
    cells = []
    for n in names:
        d = data[n]
        t, c = d[key], d[key + "_cpu"]
        s = [float(x) for x in str(d[key + "_samples"]).split(",")]
        spread = f" [{min(s) * 1e3:.3g}-{max(s) * 1e3:.3g}]" if len(s) > 1 else ""
        cells.append(f"**{c / d['cells'] * 1e9:.0f}** / {t / d['cells'] * 1e9:.0f} ns "
                     f"({c * 1e3:.4g} / {t * 1e3:.4g} ms{spread})")
    print(f"| {label} | " + " | ".join(cells) + " |")

def mem_row(label, key, baseline=None, source=data):
    cells = []
    for n in names:
        d = source[n]
        b = d[key] - (d[baseline] if baseline else 0)
        cells.append(f"**{b / d['cells']:.0f}** B ({b / 2**20:.1f} MiB)")
    print(f"| {label} | " + " | ".join(cells) + " |")

def plain_row(label, f):
    print(f"| {label} | " + " | ".join(f(data[n]) for n in names) + " |")

print(open(os.path.join(results, "machine.txt")).read(), end="")
print("Times per cell: **median CPU time** of the process / median wall-clock time, in ns per cell; in brackets")
print("the same totals in ms and [min-max] of the wall-clock samples. Wall-clock > CPU time means the process")
print("waited for a core (other jobs on the machine). Memory: bytes per cell (total MiB).")
print()
header()
plain_row("faces / matrix nonzeros", lambda d: f"{int(d['faces']):,} / {int(d['matrix_nnz']):,}")
time_row("FVGeometry construction", "geometry_construct")
time_row("- of which deal.II DoF numbering (DoFHandler, relevant DoFs, partitioner)", "dof_numbering")
time_row("FVGeometry::reinit (mesh motion)", "geometry_reinit")
time_row("VertexInterpolation::reinit (mesh motion)", "vertex_interp_reinit")
time_row("Laplacian::reinit_matrix (sparsity)", "matrix_sparsity")
time_row("Laplacian::assemble + compress", "assemble")
time_row("linear solve: AMG setup + CG solve", "linear_solve_total")
time_row("- AMG setup (LinearSolver::initialize)", "amg_setup")
time_row("- CG solve (LinearSolver::solve), reduction 1e-6", "cg_solve")
plain_row("CG iterations", lambda d: f"{int(d['cg_iterations'])}")
time_row("deferred-correction sweep (total)", "sweep")
time_row("- Laplacian::boundary_values", "sweep_boundary_values")
time_row("- VertexInterpolation::interpolate", "sweep_interpolate")
time_row("- gauss_green_gradient", "sweep_gauss_green")
time_row("- rhs copy + Laplacian::add_correction", "sweep_rhs_copy_add_correction")
time_row("experiment: row-wise assembly + compress", "assemble_rowwise")
mem_row("peak RSS (VmHWM)", "peak_rss")
mem_row("peak RSS - RSS at start (libraries)", "peak_rss", baseline="rss_start")
mem_row("peak RSS after FVGeometry construction - RSS at start", "peak_rss_after_geometry", baseline="rss_start")
mem_row("heap: Triangulation (p4est + deal.II)", "mem_tria_heap")
mem_row("heap: FVGeometry (incl. DoFHandler)", "mem_geometry_heap")
mem_row("- of which the faces array (capacity)", "mem_faces_array")
mem_row("- of which the faces array (size: faces x sizeof)", "mem_faces_used")
mem_row("heap: VertexInterpolation", "mem_vertex_interp_heap")
mem_row("heap: Trilinos matrix", "mem_matrix_heap")
mem_row("heap: AMG hierarchy (+ solver vectors)", "mem_amg_heap")
mem_row("RSS growth during the first FVGeometry construction", "geometry_first_rss_growth")
mem_row("- of which freed but kept by malloc (arena free bytes after it)", "malloc_arena_free_after_geometry")
mem_row("experiment, glibc malloc defaults: peak RSS - RSS at start", "peak_rss",
        baseline="rss_start", source=malloc_data)
mem_row("experiment, glibc malloc defaults: RSS growth during the first FVGeometry construction",
        "geometry_first_rss_growth", source=malloc_data)
mem_row("experiment, glibc malloc defaults: peak RSS growth during it", "geometry_first_peak_rss_growth",
        source=malloc_data)
def single_row(label, key):
    cells = []
    for n in names:
        d, m = data[n], malloc_data[n]
        cells.append(f"**{m[key + '_cpu'] / d['cells'] * 1e9:.0f}** ns (default run: {d[key + '_cpu'] / d['cells'] * 1e9:.0f})")
    print(f"| {label} | " + " | ".join(cells) + " |")
single_row("experiment, glibc malloc defaults: FVGeometry construction, CPU (1 sample)", "geometry_construct")
single_row("experiment, glibc malloc defaults: assemble + compress, CPU (1 sample)", "assemble")
single_row("experiment, glibc malloc defaults: correction sweep, CPU (1 sample)", "sweep")
plain_row("sizeof(FaceGeometry<dim>)", lambda d: f"{int(d['sizeof_face'])} B")
plain_row("RSS at start (MPI, deal.II, Trilinos loaded)",
          lambda d: f"{d['rss_start'] / 2**20:.0f} MiB")
plain_row("max cell error after 5 corrections (sanity)",
          lambda d: f"{d['max_cell_error_after_5_corrections']:.2e}")
EOF
echo
echo "Reproduce: doc/benchmarks/run_core.sh $BUILD_DIR $REPEATS"
# The times per cell as doc/results/core_performance.png.
/usr/bin/python3 "$SOURCE_DIR/doc/results/table_plot.py" "$RESULTS/table.md" \
  "$SOURCE_DIR/doc/results/core_performance.png" --bar --x "" --y "2D, 102,400 cells" \
  --y "2D, 1,048,576 cells" --y "3D, 110,592 cells" --match " ns" --logy \
  --title "FV core: median CPU time per cell [ns] (doc/benchmarks/run_core.sh)"
