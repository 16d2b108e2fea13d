#!/usr/bin/env bash
# Bad input stays a clear error (issue 15, item 6), the whole sweep: every mutation kind on every
# `set` line of every shipped prm/*.prm file (nan, negated numbers, zero, 1e300, empty, a value of
# the wrong type, the line deleted; unknown patch names; interface patches that do not face each
# other), each run for two steps (`fvfsi --steps 2`) by the test program tests/core/prm_mutations
# with `--all`. The ctest `core/prm_mutations` runs one kind per line (rotating) of the same.
# Writes doc/results/prm_mutations.md: per file the mutations, how many ran normally, how many
# stopped with a message naming the parameter, and every run that ended otherwise (none is the
# pass); plus the wall time and the machine.
#
# Usage: doc/results/prm_mutations.sh [BUILD_DIR]   (BUILD_DIR: a configured Release build of
#        this tree, default build/; the test program is made in it)
set -euo pipefail
script_dir=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
repo=$(cd "$script_dir/../.." && pwd)
build=$(cd "${1:-$repo/build}" && pwd)
export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMP_NUM_THREADS=1
make -C "$build" core.prm_mutations.release > /dev/null
program=$build/tests/core/prm_mutations.release/prm_mutations.release
work=$(mktemp -d)
start=$(date +%s)
(cd "$work" && "$program" --all > log.txt 2> stderr.txt) || true
seconds=$(($(date +%s) - start))
{
  echo "# Mutated .prm files: every kind on every line"
  echo
  echo "\`doc/results/prm_mutations.sh\` on $(date -u +%Y-%m-%d), commit $(git -C "$repo" rev-parse --short HEAD),"
  echo "$(nproc --all) cores ($(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ //')), one rank:"
  echo "each mutated file run for two steps (\`--steps 2\`), in one process. Wall time ${seconds} s."
  echo
  echo "| file | mutations | ran normally | stopped, message names the parameter |"
  echo "|---|---|---|---|"
  sed -n 's/^\(.*\.prm\): \([0-9]*\) mutations: \([0-9]*\) ran, \([0-9]*\) stopped.*/| \1 | \2 | \3 | \4 |/p' "$work/output"
  echo
  grep '^total' "$work/output" | sed 's/^/**/; s/$/**/'
  if grep -q '^FAILED' "$work/output" || grep -q 'FAILED by' "$work/stderr.txt"; then
    echo
    echo "Runs that ended otherwise:"
    echo '```'
    grep -A1 '^FAILED' "$work/output" || true
    grep 'FAILED by' "$work/stderr.txt" || true
    echo '```'
  fi
} > "$script_dir/prm_mutations.md"
cat "$script_dir/prm_mutations.md"
rm -rf "$work"
