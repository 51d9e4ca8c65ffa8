#!/usr/bin/env bash
# Simulation benchmark: what a user waits for in `kse simulate` (and KSE > Simulate, which runs
# the same builder and session) on the Goalie. Whole processes:
#   - ready, first time: the simulator built from nothing (generate, CMake, compile) and started;
#   - ready, again: the model unchanged, the build up to date (what every later start costs);
#   - a command's round trip in a session (the tool -> the simulator's pipe -> the engine -> JSON
#     back), against the engine's own time for the same commands in the simulator alone
#     (`--show` of the same script, no pipe, no Java), its baseline, measured in the same run.
#   usage: bench/simulation.sh <runtime-install-prefix> [commands]   (default 20000)
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
prefix="$1"
commands="${2:-20000}"
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
model="$here/examples/Goalie/Goalie.stct"
now() { date +%s%N; }
ms() { echo $(( ($2 - $1) / 1000000 )); }

printf 'start\n' > "$scratch/ready.case"
{
  printf 'model Goalie\nstart\npublish worldstate State GameStateMessage { player_state: 3 }\nfinish NoPlay\n'
  for ((i = 0; i < commands; i++)); do printf 'advance 250\n'; done
} > "$scratch/long.case"

t0=$(now); "$here/kse" simulate -q "$model" --runtime "$prefix" --build-dir "$scratch/build" --script "$scratch/ready.case" > /dev/null; t1=$(now)
cold=$(ms "$t0" "$t1")
warm_runs=()
for _ in 1 2 3; do
  t0=$(now); "$here/kse" simulate -q "$model" --runtime "$prefix" --build-dir "$scratch/build" --script "$scratch/ready.case" > /dev/null; t1=$(now)
  warm_runs+=("$(ms "$t0" "$t1")")
done
warm=$(printf '%s\n' "${warm_runs[@]}" | sort -n | sed -n 2p)

t0=$(now); "$here/kse" simulate -q "$model" --runtime "$prefix" --build-dir "$scratch/build" --script "$scratch/long.case" > "$scratch/session.out"; t1=$(now)
session=$(ms "$t0" "$t1")
activities=$(grep -o 'PartNamed("[A-Za-z0-9_]*")' "$scratch/build/src/statecharts/Goalie/Goalie.cpp" | sed 's/PartNamed("\(.*\)")/\1/' | sort -u | paste -sd, -)
t0=$(now); "$scratch/build/build/kse-simulator" --activities "$activities" --show "$scratch/long.case" > "$scratch/alone.out"; t1=$(now)
alone=$(ms "$t0" "$t1")
per_session=$(awk -v s="$session" -v w="$warm" -v n="$commands" 'BEGIN { printf "%.0f", (s - w) * 1000 / n }')
per_alone=$(awk -v a="$alone" -v n="$commands" 'BEGIN { printf "%.0f", a * 1000 / n }')
steps=$(grep -c ' -> ' "$scratch/session.out" || true)
alone_steps=$(grep -c ' -> ' "$scratch/alone.out" || true)
if [ "$steps" != "$alone_steps" ]; then
  echo "bench/simulation.sh: the session gave $steps trace lines and the simulator alone $alone_steps: they must agree" >&2
  exit 1
fi
echo "simulation of the Goalie (47 states), $(nproc) cores:"
echo "  ready, first time (kse generate, CMake, compile, start):  ${cold} ms"
echo "  ready, again (model unchanged):                          ${warm} ms (median of 3: ${warm_runs[*]})"
echo "  a command's round trip in a session:                     ${per_session} us per command (${commands} x advance 250, ${steps} trace lines)"
echo "  the same commands in the simulator alone (baseline):     ${per_alone} us per command"
awk -v s="$per_session" -v a="$per_alone" 'BEGIN { if (a > 0) printf "  ratio session / alone:                                   %.1fx\n", s / a }'
