#!/usr/bin/env bash
# Hard cases of the solid solver (doc/results/solid_stability.md):
#   nu        plate with a hole, nu = 0.3, 0.45, 0.49 (+ 0.499 plane strain), plane stress and plane
#             strain, n = 22 and 45, outer tolerance 1e-8 (the .prm's) and 1e-10; the exact
#             displacement is regenerated for each nu / plane (mu = E/(2(1+nu)), kappa = (3-nu)/(1+nu)
#             plane stress, 3-4nu plane strain) from the .prm's expression;
#   nu499     nu = 0.499 plane strain, n = 22, tolerance 1e-10 with 20000 outer iterations allowed;
#   distortion plate with a hole (nu = 0.3, plane stress) with Mesh/Distortion = 0 and 0.3 (seeds 1,
#             2), n = 22 and 45; Turek-Hron CSM1 on the 140 x 8 mesh, Distortion 0 and 0.3;
#   csm1tight CSM1 140 x 8, Distortion 0 and 0.3, outer tolerance 1e-10 (20000 outer iterations);
#   gravity   CSM1 (70 x 4 mesh) in one steady step with g = 2, 4, ..., 8192 m/s^2.
# Every run: one MPI rank, one at a time, stopped after TIMEOUT s (default 180) by `timeout`.
# Prints one markdown table row per run (rc = exit code; 124 = stopped by the timeout) and, for
# runs that did not end with rc 0, the last progress line and the error message; then checks that
# every run either converged with finite results (summary.json, solid_history.txt and every VTU
# field) or exited non-zero with a message naming the time step (no silent NaN).
# The binary is built from `git archive` of the commit REV (default HEAD) in BUILD_DIR/src-<commit>,
# BUILD_DIR/build-<commit>; needs cmake, make, jq, /usr/bin/time and /usr/bin/python3.
#
# Usage: doc/results/solid_stability.sh [BUILD_DIR [SECTION...]]
#   BUILD_DIR default /work/build-hard; SECTION: machine nu nu499 distortion csm1tight gravity (default: all).
set -uo pipefail

script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$script_dir/../.." && pwd)
build=${1:-/work/build-hard}
shift || true
sections=("$@")
[[ ${#sections[@]} -eq 0 ]] && sections=(machine nu nu499 distortion csm1tight gravity)
timeout_s=${TIMEOUT:-180}
mkdir -p "$build"
build=$(cd "$build" && pwd)
runs=$build/solid_stability_runs
export OMP_NUM_THREADS=1
checks=$runs/checks.txt
exec > >(tee "$runs/output.md") # the tables, also for the plot at the end
mkdir -p "$runs" && : > "$checks"

# Build from the committed tree (git archive of REV, default HEAD), not from the working tree:
# other work may be editing source/ while this script runs.
rev=$(git -C "$repo" rev-parse "${REV:-HEAD}")
src=$build/src-${rev:0:12}
if [[ ! -f $src/CMakeLists.txt ]]; then
  mkdir -p "$src" && git -C "$repo" archive "$rev" | tar -x -C "$src"
fi
bin=$build/build-${rev:0:12}
mkdir -p "$bin"
echo "== building fvfsi (Release) from commit $rev in $bin"
(cd "$bin" && cmake -DCMAKE_BUILD_TYPE=Release "$src" > cmake.log && make -j1 fvfsi > make.log) ||
  { echo "solid_stability.sh: build failed, see $bin/cmake.log and $bin/make.log" >&2; exit 1; }
plate=$src/prm/plate_hole.prm
csm1=$src/prm/turek_hron_csm1.prm

# nonfinite DIR: the non-finite values in DIR's summary.json, solid_history.txt and VTU fields
# (deal.II's zlib-compressed base64 arrays), as `name count` pairs; empty if all are finite.
nonfinite() {
  /usr/bin/python3 - "$1" << 'EOF'
import base64, glob, math, re, struct, sys, zlib
d = sys.argv[1]
bad = {}
for f in ('summary.json', 'solid_history.txt'):
    try:
        text = open(f'{d}/{f}').read()
    except OSError:
        continue
    n = len(re.findall(r'(?i)\b(?:nan|inf|infinity)\b', text))
    if n:
        bad[f] = n
for f in glob.glob(f'{d}/*.vtu'):
    text = open(f).read()
    for typ, name, data in re.findall(
            r'<DataArray type="(Float32|Float64)" Name="([^"]+)"[^>]*format="binary">\s*(\S+)\s*</DataArray>', text):
        nb = struct.unpack('<I', base64.b64decode(data[:8])[:4])[0]
        hl = 4 * (3 + nb)
        hl64 = (hl + 2) // 3 * 4
        raw = zlib.decompress(base64.b64decode(data[hl64:]))
        fmt = 'f' if typ == 'Float32' else 'd'
        vals = struct.unpack(f'<{len(raw) // struct.calcsize(fmt)}{fmt}', raw)
        n = sum(1 for v in vals if not math.isfinite(v))
        if n:
            bad[name] = bad.get(name, 0) + n
print(', '.join(f'{k} {v}' for k, v in bad.items()))
EOF
}

# run NAME PRM [--set ...]...: one run in $runs/NAME; prints a table row
#   | NAME | rc | cells | max u error | max hole stress error | point A u | F_y clamped | outer it. |
#     wall s | CPU s | non-finite output values |
# (wall s: summary.json's wall_seconds; CPU s: user + system time of the process; F_y clamped: the
# last column of solid_history.txt for CSM1 runs)
run() {
  local name=$1 prm=$2
  shift 2
  local dir=$runs/$name
  rm -rf "$dir" && mkdir -p "$dir"
  local t0 t1 rc
  t0=$(date +%s.%N)
  /usr/bin/time -f '%U %S' -o "$dir/time.txt" timeout "$timeout_s" "$bin/fvfsi" "$prm" --set "Output directory=$dir" "$@" > "$dir/stdout.txt" 2> "$dir/stderr.txt"
  rc=$?
  t1=$(date +%s.%N)
  local elapsed
  elapsed=$(python3 -c "print(f'{$t1 - $t0:.1f}')")
  local cpu
  cpu=$(awk 'END { printf "%.1f", $1 + $2 }' "$dir/time.txt")
  local bad
  bad=$(nonfinite "$dir")
  if [[ $rc -eq 0 ]]; then
    local s=$dir/summary.json fy=-
    [[ $prm == "$csm1" ]] && fy=$(tail -1 "$dir/solid_history.txt" | awk '{ print $NF }')
    printf '| %s | %d | %s | %s | %s | %s | %s | %s | %s | %s | %s |\n' "$name" "$rc" "$(jq -r .n_cells "$s")" \
      "$(jq -r '.results.max_displacement_error // "-" | if type=="number" then (.*1e10|round/1e10) else . end' "$s")" \
      "$(jq -r '.results.max_hole_stress_error // "-" | if type=="number" then (.*1e3|round/1e3) else . end' "$s")" \
      "$(jq -rc '.results.point_A_displacement // "-"' "$s")" "$fy" \
      "$(jq -r .results.outer_iterations "$s")" "$(jq -r '.wall_seconds*10|round/10' "$s")" "$cpu" "${bad:-none}"
    if [[ -n $bad ]]; then
      echo "SILENT-NON-FINITE $name: rc 0 (converged) but non-finite output: $bad" | tee -a "$checks"
    else
      echo "ok $name: rc 0, all outputs finite" >> "$checks"
    fi
  else
    local progress msg
    progress=$(grep 'outer iteration' "$dir/stdout.txt" | tail -1)
    msg=$(grep -m1 'fvfsi: error' "$dir/stderr.txt")
    local detail
    detail=$(grep -A1 -m1 'Additional information' "$dir/stderr.txt" | tail -1 | sed 's/^ *//')
    [[ -n $detail ]] && msg="$msg [$detail]"
    printf '| %s | %d | - | - | - | - | - | %s | %s (elapsed) | %s | %s |\n' "$name" "$rc" \
      "$(grep -c 'outer iteration' "$dir/stdout.txt") progress lines" "$elapsed" "$cpu" "${bad:-none}"
    echo "    last progress: ${progress:-none}"
    echo "    stderr: ${msg:-none}"
    if [[ $rc -eq 124 ]]; then
      echo "ok $name: stopped by timeout after ${timeout_s} s (last progress: ${progress:-none})" >> "$checks"
    elif grep -q 'at time step' "$dir/stderr.txt"; then
      echo "ok $name: rc $rc, message names the time step" >> "$checks"
    else
      echo "NO-TIME-STEP $name: rc $rc, message: $msg" | tee -a "$checks"
    fi
  fi
}

# exact_u NU PLANE: the plate's exact displacement for NU and PLANE (stress|strain), built from the
# .prm's expression (written for nu = 0.3, plane stress: mu = (1e7/2.6), kappa = (2.7/1.3)).
exact_u() {
  python3 - "$1" "$2" "$plate" << 'EOF'
import sys
nu, plane, prm = float(sys.argv[1]), sys.argv[2], sys.argv[3]
line = next(l for l in open(prm) if l.strip().startswith('set Exact displacement'))
expr = line.split('=', 1)[1].strip()
assert expr.count('(1e7/2.6)') == 2 and expr.count('(2.7/1.3)') == 4, 'unexpected expression'
mu = f'(1e7/{2 * (1 + nu)!r})'
kappa = f'({3 - nu!r}/{1 + nu!r})' if plane == 'stress' else f'({3 - 4 * nu!r})'
print(expr.replace('(1e7/2.6)', mu).replace('(2.7/1.3)', kappa))
EOF
}

header() {
  echo
  echo "load average before the table: $(cut -d' ' -f1-3 /proc/loadavg)"
  echo
  echo "| run | rc | cells | max u error [m] | max hole stress error [Pa] | point A u [m] | F_y clamped [N] | outer it. | wall s | CPU s | non-finite output values |"
  echo "|---|---|---|---|---|---|---|---|---|---|---|"
}

# CSM1 on 140 x 8 cells, undistorted and distorted by 0.3: csm1_distorted RUN_PREFIX OUTER_TOLERANCE
csm1_distorted() {
  header
  for d in 0 0.3; do
    run "$1/140x8/d$d" "$csm1" --set "Mesh/Generator arguments=140: 8" \
      --set "Mesh/Distortion=$d" --set "Mesh/Distortion seed=1" --set "Solid/Body force=0; -2" \
      --set "Solid/Outer tolerance=$2" --set "Solid/Max outer iterations=20000"
  done
}

for section in "${sections[@]}"; do
  case $section in
  machine)
    echo "== machine"
    echo "CPU: $(grep -m1 'model name' /proc/cpuinfo | sed 's/^model name[[:space:]]*:[[:space:]]*//'), nproc $(env -u OMP_NUM_THREADS nproc)"
    echo "load average: $(cut -d' ' -f1-3 /proc/loadavg)"
    echo "built and run from commit $rev ($(git -C "$repo" log -1 --format=%cd --date=iso "$rev"))"
    echo "compiler: $(grep -m1 CMAKE_CXX_COMPILER_VERSION "$bin/CMakeFiles"/*/CMakeCXXCompiler.cmake 2>/dev/null | sed 's/.*"\(.*\)".*/g++ \1/')"
    # the regenerated expression for nu = 0.3, plane stress must be the .prm's own
    [[ "$(exact_u 0.3 stress)" == "$(sed -n 's/^ *set Exact displacement *= *//p' "$plate" | sed 's/ *$//')" ]] &&
      echo "exact_u 0.3 stress reproduces the .prm's Exact displacement: yes" ||
      echo "exact_u 0.3 stress reproduces the .prm's Exact displacement: NO"
    ;;
  nu)
    echo "== near-incompressibility: plate with a hole (exact u regenerated per nu and plane)"
    for tol in 1e-8 1e-10; do
      header
      for plane in stress strain; do
        for n in 22 45; do
          nus=(0.3 0.45 0.49)
          [[ $plane == strain ]] && nus+=(0.499)
          for nu in "${nus[@]}"; do
            run "nu/tol$tol/plane_$plane/n$n/nu$nu" "$plate" \
              --set "Mesh/Generator arguments=0.5: 2: $n" --set "Mesh/Distortion=0" \
              --set "Solid/Plane=plane $plane" --set "Solid/Poisson's ratio=$nu" \
              --set "Solid/Outer tolerance=$tol" --set "Solid/Max outer iterations=5000" \
              --set "Solid scene/Exact displacement=$(exact_u "$nu" "$plane")"
          done
        done
      done
    done
    ;;
  nu499)
    echo "== nu = 0.499, plane strain, n = 22: tolerance 1e-10 with Max outer iterations 20000"
    header
    run "nu/tol1e-10/plane_strain/n22/nu0.499_max20000" "$plate" \
      --set "Mesh/Generator arguments=0.5: 2: 22" --set "Mesh/Distortion=0" \
      --set "Solid/Plane=plane strain" --set "Solid/Poisson's ratio=0.499" \
      --set "Solid/Outer tolerance=1e-10" --set "Solid/Max outer iterations=20000" \
      --set "Solid scene/Exact displacement=$(exact_u 0.499 strain)"
    ;;
  distortion)
    echo "== distorted meshes: plate with a hole (nu = 0.3, plane stress, tolerance 1e-8)"
    header
    for n in 22 45; do
      for d in 0 0.3; do
        seeds=(1)
        [[ $d != 0 ]] && seeds=(1 2)
        for seed in "${seeds[@]}"; do
          run "distortion/plate/n$n/d$d/seed$seed" "$plate" \
            --set "Mesh/Generator arguments=0.5: 2: $n" --set "Mesh/Distortion=$d" \
            --set "Mesh/Distortion seed=$seed" --set "Solid/Plane=plane stress" \
            --set "Solid/Poisson's ratio=0.3" --set "Solid/Outer tolerance=1e-8" \
            --set "Solid/Max outer iterations=5000"
        done
      done
    done
    echo "== distorted meshes: CSM1, 140 x 8 cells, g = 2, outer tolerance 1e-7, max 20000 outer iterations"
    csm1_distorted distortion/csm1 1e-7
    ;;
  csm1tight)
    echo "== CSM1, 140 x 8 cells, g = 2, outer tolerance 1e-10, max 20000 outer iterations"
    csm1_distorted csm1tight 1e-10
    ;;
  gravity)
    echo "== load step: CSM1, 70 x 4 cells, one steady step, outer tolerance 1e-7, max 20000 outer iterations"
    header
    for g in 2 4 8 16 32 64 128 256 512 1024 2048 4096 8192; do
      run "gravity/70x4/g$g" "$csm1" --set "Mesh/Generator arguments=70: 4" --set "Mesh/Distortion=0" \
        --set "Solid/Body force=0; -$g" --set "Solid/Outer tolerance=1e-7" \
        --set "Solid/Max outer iterations=20000"
    done
    ;;
  *)
    echo "solid_stability.sh: unknown section $section" >&2
    exit 1
    ;;
  esac
done

echo
echo "== checks (every run: converged with a finite summary, or non-zero exit naming the time step)"
cat "$checks"
# Every table's runs as doc/results/solid_stability.png (runs that stopped are listed under it).
sleep 1 # tee has written the tables
/usr/bin/python3 "$repo/doc/results/table_plot.py" "$runs/output.md" \
  "$repo/doc/results/solid_stability.png" --all --bar --x run --y "outer it." \
  --y "max u error [m]" --logy --title "Solid hard cases (rc != 0: not plotted, listed below)"
