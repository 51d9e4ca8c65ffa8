#!/usr/bin/env bash
# `kse demo`: the whole pipeline on a fresh machine. Validates the example models, builds the
# runtime and the examples with CMake (which generates their Monas C++ from the models), and plays
# a 3-against-3 match on the simulated field; prints the result and where the log and the picture are.
# Options: --seed N (default 1), --half SECONDS (default 600, a full SPL half: about a second on the simulator), --out DIR (default target/demo).
# KSE_RUNTIME_PREFIX=DIR reuses an installed runtime instead of building one.
set -euo pipefail
here="$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/.." && pwd)"
seed=1
half=600
out="$here/target/demo"
while [ $# -gt 0 ]; do
  case "$1" in
    --seed) seed="$2"; shift 2 ;;
    --half) half="$2"; shift 2 ;;
    --out) out="$(mkdir -p "$2" && cd "$2" && pwd)"; shift 2 ;;
    -h|--help) sed -n '2,7p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    *) echo "kse demo: unknown option '$1' (try --help)" >&2; exit 2 ;;
  esac
done
mkdir -p "$out"
step() { echo "== $*" >&2; }

"$here/releng/debian-packages.sh"

step "1/4 validating the example models"
"$here/kse" validate "$here"/examples/{Goalie/Goalie,Attacker/Attacker,Defender/Defender}.stct

prefix="${KSE_RUNTIME_PREFIX:-}"
own_prefix=""
if [ -z "$prefix" ]; then
  own_prefix=yes
  step "2/4 building and installing the C++ runtime (log: $out/runtime.log)"
  prefix="$out/runtime-prefix"
  {
    cmake -S "$here/runtime" -B "$out/runtime" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF \
      -DKSE_BUILD_BENCHMARKS=OFF -DCMAKE_INSTALL_PREFIX="$prefix"
    cmake --build "$out/runtime" -j 2
    cmake --install "$out/runtime"
  } > "$out/runtime.log" 2>&1 || { tail -n 30 "$out/runtime.log" >&2; exit 1; }
else
  step "2/4 using the runtime installed in $prefix"
fi

step "3/4 building the examples against it, their statecharts generated from the models (log: $out/examples.log)"
{
  cmake -S "$here/examples" -B "$out/examples" -G Ninja -DCMAKE_BUILD_TYPE=Release -DBUILD_TESTING=OFF \
    -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_INSTALL_PREFIX="$prefix"
  cmake --build "$out/examples" -j 2
  # the examples installed beside the runtime it built (never into a prefix it was given), so that
  # a project of one's own (kse new-behaviour, docs/getting-started.md) plays against them
  if [ -n "$own_prefix" ]; then cmake --install "$out/examples"; fi
} > "$out/examples.log" 2>&1 || { tail -n 30 "$out/examples.log" >&2; exit 1; }

step "4/4 playing Goalie, Defender and Attacker against themselves: a ${half}-second half, seed $seed"
"$out/examples/kse-match" --seed "$seed" --half "$half" \
  --home Goalie:1,Defender:2,Attacker:3 --away Goalie:1,Defender:2,Attacker:3 \
  --log "$out/match.jsonl" --svg "$out/match.svg"
echo "Open $out/match.svg to see the match; $out/match.jsonl is its log."
if [ -n "$own_prefix" ]; then
  echo "The runtime and the examples are installed in $prefix: docs/getting-started.md builds a behaviour of your own against them."
fi
