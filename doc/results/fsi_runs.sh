# Shared by doc/results/fsi3.sh and fsi2.sh (sourced): one Turek-Hron FSI run and its record.
#   run_fsi CASE NAME T0 T1 [SET...]
# runs prm/turek_hron_CASE.prm with the --set overrides SET into $runs/NAME (unless
# $runs/NAME/summary.json of a completed run exists already: a study can be resumed; $launcher,
# if set, goes before the command, e.g. "taskset -c 1"; $prm_file, if set, replaces the case's
# file, e.g. prm/turek_hron_fsi3_fast.prm), then writes $runs/NAME.json
# (doc/results/fsi_benchmark.py record: statistics over [T0, T1], errors, cost) and
# $runs/NAME.png. Needs $fvfsi, $runs and $python; $FVFSI_COMMIT names the commit $fvfsi was
# built from (default: the tree's), recorded in $runs/NAME/commit.txt.
source doc/results/common.sh

run_fsi() {
  local case=$1 name=$2 t0=$3 t1=$4
  shift 4
  local out=$runs/$name args=()
  for s in "$@"; do args+=(--set "$s"); done
  if ! completed "$out"; then
    echo "$(date -u +%H:%M) $case $name: running (log $out.log)"
    mkdir -p "$out" && echo "${FVFSI_COMMIT:-$(git rev-parse --short HEAD)}" > "$out/commit.txt"
    ${launcher:-} "$fvfsi" "${prm_file:-prm/turek_hron_$case.prm}" "${args[@]}" --set "Fluid scene/Output interval=0" \
      --set "Output directory=$out" > "$out.log" 2>&1 || { echo "$case $name failed, see $out.log"; return 1; }
  fi
  "$python" doc/results/fsi_benchmark.py record "$case" "$out" "$t0" "$t1" \
    "${prm_file:-prm/turek_hron_$case.prm}" "$@" > "$out.json"
  "$python" doc/results/fsi_benchmark.py plot "$case" "$out.png" "$out" "$t0" "$t1"
}

# The machine, for the record.
machine() {
  machine_line "commit $(git rev-parse --short HEAD)"
}
