#!/usr/bin/env bash
# Integration test: generate the legacy Goalie with `kse generate`, build it against an
# installed KSE runtime, and run the scripted-message test.
#   usage: tests/integration/goalie/run.sh <runtime-install-prefix> <work-dir>
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../../.." && pwd)"
prefix="$1"
work="$2"
rm -rf "$work/src" "$work/build"
"$repo/kse" generate --quiet "$repo/../shared/legacy-kse/Goalie/Goalie.stct" "$work/src"
cmake -S "$here" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_PREFIX_PATH="$prefix" -DKSE_SOURCE_FOLDER="$work/src" > "$work/configure.log"
cmake --build "$work/build" -j 2
ctest --test-dir "$work/build" --output-on-failure
