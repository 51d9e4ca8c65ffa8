#!/usr/bin/env bash
# Simulator benchmark: the real-time factor of a 5-against-5 ten-minute half of the example
# behaviours on one core, the share of the time spent in their statecharts, and the same match
# with scripted players (no statecharts) as the baseline of the same run. Release build in
# target/bench. Argument: number of runs (default 3; the median is reported).
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
out="$here/target/bench"
mkdir -p "$out"
# shellcheck source=runtime-prefix.sh
. "$here/bench/runtime-prefix.sh"
# the examples' build generates their statecharts from the models with this repository's ./kse
cmake -S "$here/examples" -B "$out/examples" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF \
  -DCMAKE_PREFIX_PATH="$out/prefix" > "$out/examples.configure.log"
cmake --build "$out/examples" -j 2 --target match_bench > "$out/examples.build.log"
taskset -c 0 "$out/examples/match_bench" "${1:-3}"
