#!/usr/bin/env bash
# Integration test: generate a model with `kse generate`, build the test project in
# tests/integration/<project> against an installed KSE runtime, and run its tests.
#   usage: tests/integration/run.sh <project> <model.stct> <runtime-install-prefix> <work-dir>
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
project="$1"
model="$2"
prefix="$3"
work="$4"
rm -rf "$work/src" "$work/build"
mkdir -p "$work"
"$repo/kse" generate --quiet "$model" "$work/src"
cmake -S "$here/$project" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_PREFIX_PATH="$prefix" -DKSE_SOURCE_FOLDER="$work/src" > "$work/configure.log"
cmake --build "$work/build" -j 2
ctest --test-dir "$work/build" --output-on-failure
