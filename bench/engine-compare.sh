#!/usr/bin/env bash
# The engine against a hand-written switch, Boost.Statechart and Qt SCXML on the same two charts
# (runtime/bench/engine_compare.cpp): transitions per second of thread CPU time in interleaved
# rounds, and bytes per chart instance. Figures only: a slow figure is never a failure.
#   usage: bench/engine-compare.sh [runtime-build-dir] [kse_engine_compare options]
# With a build directory of the runtime (test.sh passes its plain build) the program is built
# there; without one the runtime is built in Release under target/bench/compare.
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-}"
[ $# -gt 0 ] && shift
if [ -z "$build" ]; then
  build="$here/target/bench/compare"
  mkdir -p "$build"
  cmake -S "$here/runtime" -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF \
    > "$build/configure.log"
fi
if ! cmake --build "$build" -j 2 --target kse_engine_compare > "$build/compare.build.log" 2>&1; then
  echo "   kse_engine_compare could not be built (needs libboost-dev and qt6-scxml-dev): see $build/compare.build.log"
  exit 0
fi
type=$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$build/CMakeCache.txt")
echo "   (runtime built as ${type:-?} in $build)"
# Qt needs no display for a QCoreApplication; keep it from looking for one.
QT_QPA_PLATFORM=offscreen "$build/bench/kse_engine_compare" "$@"
