#!/usr/bin/env bash
# The engine conformance suite: generates every case's statechart with `kse generate`, builds
# them into the simulator (kse_add_simulator: the one the tool's simulation runs) against an
# installed KSE runtime, and runs every case twice: waking the engine as Monas did, and far more
# often (--eager), which must not change a single trace. Then a session of `kse simulate`, saved
# as a case, must pass as one.
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
"$work/build/kse_conformance" --activities "$activities" --check "$here"/cases/*.case | grep -v '^PASS ' || status=1
"$work/build/kse_conformance" --eager --activities "$activities" --check "$here"/cases/*.case | grep -v '^PASS ' || status=1

# A user's session in kse simulate (steps of time, a breakpoint, a refused command), saved as a
# case: the case passes, and it has the transition the session took.
rm -rf "$work/recorded"
printf 'start\nadvance 40\nbreakpoints state:0.3\nadvance 5000\nfinish Nobody\nactive\nsave %s\nquit\n' "$work/recorded/Recorded" |
  "$repo/kse" simulate -q "$here/cases/TimeoutWakesAtItsTime.stct" --runtime "$prefix" --build-dir "$work/simulate" > "$work/simulate.log" 2>&1 || {
  cat "$work/simulate.log"; status=1; }
if grep -q '^advance 100$' "$work/recorded/Recorded.case" && grep -q '^  0.2 -> 0.3$' "$work/recorded/Recorded.case" &&
  "$repo/kse" simulate -q "$work/recorded/Recorded.stct" --runtime "$prefix" --build-dir "$work/simulate-recorded" \
    --script "$work/recorded/Recorded.case" > "$work/simulate-recorded.log" 2>&1; then
  echo "a kse simulate session saved as a case passes as one"
else
  echo "FAIL the case saved by kse simulate:"; cat "$work/recorded/Recorded.case" "$work/simulate.log" "$work/simulate-recorded.log" 2>/dev/null; status=1
fi
exit $status
