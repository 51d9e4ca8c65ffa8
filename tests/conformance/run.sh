#!/usr/bin/env bash
# The engine conformance suite: generates every case's statechart with `kse generate`, builds
# the driver against an installed KSE runtime, and runs every case twice: waking the engine as
# Monas did, and far more often (--eager), which must not change a single trace.
#   usage: tests/conformance/run.sh <runtime-install-prefix> <work-dir>
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
prefix="$1"
work="$2"
rm -rf "$work/src"
mkdir -p "$work"
models=("$here"/cases/*.stct)
echo "generating ${#models[@]} statecharts"
"$repo/kse" generate --quiet "${models[@]}" "$work/src" > "$work/generate.log"
cmake -S "$here/driver" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_PREFIX_PATH="$prefix" -DKSE_SOURCE_FOLDER="$work/src" > "$work/configure.log"
cmake --build "$work/build" -j 2 > "$work/build.log" || { cat "$work/build.log"; exit 1; }
activities=$(cd "$work/src/activities" && ls | paste -sd, -)
status=0
"$work/build/kse_conformance" --activities "$activities" "$here"/cases/*.case | grep -v '^PASS ' || status=1
"$work/build/kse_conformance" --eager --activities "$activities" "$here"/cases/*.case | grep -v '^PASS ' || status=1
exit $status
