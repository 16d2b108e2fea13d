# Shared by the scripts of doc/results (sourced, not run; their working directory is the
# project root).

# machine_line [MORE]: the machine a measurement ran on, for the record: cores, CPU model, load
# average, the time (UTC), then MORE (e.g. the commit of the binary).
machine_line() {
  echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs);" \
    "load: $(cut -d' ' -f1-3 /proc/loadavg); $(date -u +%FT%TZ)${1:+; $1}"
}

# study_arguments DEFAULT_RUN_DIRECTORY [FVFSI [RUN_DIRECTORY]]: the two arguments every study
# script takes, with their defaults: sets fvfsi (build/fvfsi) and runs (DEFAULT_RUN_DIRECTORY),
# makes the run directory and prints the machine line with the commit.
study_arguments() {
  fvfsi=${2:-build/fvfsi}
  runs=${3:-$1}
  mkdir -p "$runs"
  machine_line "commit $(git rev-parse --short HEAD)"
}

# table_study: for a script that prints a markdown table and plots it (table_plot.py): sets repo
# (the project root) and out (a new temporary directory), and defines emit LINE, which prints a
# table line and keeps it in $out/table.md for the plot.
table_study() {
  repo=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
  out=$(mktemp -d)
  table="$out/table.md"
  emit() { echo "$1" | tee -a "$table"; }
}

# completed RUN_DIRECTORY: true if a run wrote RUN_DIRECTORY/summary.json with status "completed"
# (a failed run writes "failed"), so that a study resumes where it stopped.
completed() {
  grep -qs '"completed"' "$1/summary.json"
}

# perf_each_rank WRAPPER PERF_RECORD_OPTION...: writes the script WRAPPER, which runs its
# arguments after the first under `perf record PERF_RECORD_OPTION... -o DIRECTORY/perf.RANK`
# (RANK: Open MPI's rank, DIRECTORY: its first argument), so that `mpirun -np 2 WRAPPER DIRECTORY
# fvfsi ...` profiles each rank on its own.
perf_each_rank() {
  local wrapper=$1
  shift
  printf '#!/bin/bash\nout=$1\nshift\nexec perf record %s -o "$out/perf.$OMPI_COMM_WORLD_RANK" "$@"\n' \
    "$*" > "$wrapper"
  chmod +x "$wrapper"
}

# fsi3_first_steps END_TIME OUTPUT_DIRECTORY: sets the array fsi3_case to the arguments of
# fvfsi that run the first steps of prm/turek_hron_fsi3.prm as shipped (fluid n = 60: 47 160
# cells, flag 123 x 6: 738 cells, dt = 0.75 ms): the fluid alone for 10 steps (Coupling/Start
# time = 0.0075 s), then coupled up to END_TIME (0.03: 40 steps; 0.0825: 110), no field output,
# the results into OUTPUT_DIRECTORY. The two-rank probes of log.md (once performance.md section 8)
# all ran this case.
fsi3_first_steps() {
  fsi3_case=(prm/turek_hron_fsi3.prm --set "Coupling/Start time=0.0075" --set "Time/End time=$1"
             --set "Fluid scene/Output interval=0" --set "Output directory=$2")
}
