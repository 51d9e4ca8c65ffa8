#!/usr/bin/env bash
# Live monitor benchmark (figures only): a 5-against-5 match of the given kse-match (the examples'
# one: build/examples/kse-match, in CI $out/examples/kse-match) watched through kse serve in
# headless Chromium on a board of all 10 robots, at --speed 1 (a 20 s half) and at --speed 10 (a
# 60 s half). Per speed: the transitions a second the match takes, the transitions a second the
# board draws, the delay from a transition taken to drawn (median, p95, max) and whether the board
# fell behind. KSE_MONITOR_BENCH_HALF_1 and KSE_MONITOR_BENCH_HALF_10 change the halves.
#   bench/monitor.sh <kse-match>
set -euo pipefail
match="${1:?usage: bench/monitor.sh <kse-match>}"
here="$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")" && pwd)"
KSE_MATCH="$(readlink -f "$match")" exec "$here/../tests/org.kse.diagram.e2e/run.sh" --script bench/monitor.bench.mjs
