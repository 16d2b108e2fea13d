#!/usr/bin/env bash
# What a test file's compile costs with and without debug information and precompiled deal.II
# headers (doc/results/performance.md, section 11): two test files compiled by hand, one compile at
# a time, with the flags of their CMake target (-g0 taken out) and the headers CMakeLists.txt
# precompiles (FVFSI_PRECOMPILED_DEAL_II_HEADERS).
#   usage: doc/results/compile_times.sh BUILD_DIRECTORY   (configured with the default options)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
flags=$(sed -n 's/^CXX_DEFINES = //p;s/^CXX_INCLUDES = //p;s/^CXX_FLAGS = //p' \
  "$build/tests/core/CMakeFiles/core.geometry.release.dir/flags.make" | tr '\n' ' ' | sed 's/ -g0//')
sed -n '/^set(FVFSI_PRECOMPILED_DEAL_II_HEADERS/,/)$/p' CMakeLists.txt | grep -o '<deal.II/[^>]*>' |
  sed 's/^/#include /' > "$work/headers.h"
seconds() { /usr/bin/time -f %e "$@" 2>&1 >/dev/null | tail -1; }
for debug in -g -g0; do
  # shellcheck disable=SC2086
  seconds c++ $flags $debug -x c++-header "$work/headers.h" -o "$work/headers$debug.h.gch" > /dev/null
done
echo "file  -g [s]  -g0 [s]  precompiled, -g [s]  precompiled, -g0 [s]"
for file in tests/core/quadratic_fit.cc tests/core/geometry.cc; do
  line="$file"
  for pch in no yes; do
    for debug in -g -g0; do
      include=()
      if [ $pch = yes ]; then
        cp "$work/headers.h" "$work/pch$debug.h"
        ln -sf "$work/headers$debug.h.gch" "$work/pch$debug.h.gch"
        include=(-Winvalid-pch -include "$work/pch$debug.h")
      fi
      # shellcheck disable=SC2086
      line="$line  $(seconds c++ $flags $debug "${include[@]}" -c "$file" -o "$work/x.o")"
    done
  done
  echo "$line"
done
