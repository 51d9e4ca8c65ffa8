#!/usr/bin/env bash
# Replay benchmark (figures only): makes a 10-minute 5-against-5 match log with the given kse-match
# (the examples' one: build/examples/kse-match, in CI $out/examples/kse-match), opens it in the
# diagram page's replay in headless Chromium through kse serve, and prints the log's size, the time
# to ready (goal < 2 s) and scrubbing (100 jumps to random times: median and p95 to the frame
# painted), beside baselines of the same run (fetching and parsing the log, an idle frame).
#   bench/replay.sh <kse-match> [half seconds, default 600]
set -euo pipefail
match="${1:?usage: bench/replay.sh <kse-match> [half seconds]}"
half="${2:-600}"
here="$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")" && pwd)"
work="$(mktemp -d "${TMPDIR:-/tmp}/kse-replay-bench.XXXXXX")"
trap 'rm -rf "$work"' EXIT
team="Goalie:1,Defender:2,Defender:3,Attacker:4,Attacker:5"
start=$(date +%s%N)
"$match" --seed 1 --half "$half" --start-playing --home "$team" --away "$team" --quiet --log "$work/match.jsonl" >/dev/null
echo "replay benchmark: the match log made by $match in $(( ($(date +%s%N) - start) / 1000000 )) ms"
KSE_REPLAY_LOG="$work/match.jsonl" "$here/../tests/org.kse.diagram.e2e/run.sh" --script bench/replay.bench.mjs
