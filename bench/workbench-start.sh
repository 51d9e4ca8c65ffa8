#!/usr/bin/env bash
# Start benchmark: what a user waits for from starting the KSE workbench to its window, beside a
# bare Eclipse platform IDE with no KSE bundle built in the same reactor (the baseline), each
# started warm (a first start of each is not counted) on a virtual display. Also the time to
# KSE's splash. Prints medians and the ratio. Figures only: never a failure on speed.
# Usage: bench/workbench-start.sh [runs, default 3]
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
# shellcheck source=../releng/stop-process.sh
. "$here/releng/stop-process.sh"
runs="${1:-3}"
products="$here/releng/org.kse.product/target/products"
out="$here/target/bench/workbench-start"
java="${JAVA_HOME:+$JAVA_HOME/bin/}java"
rm -rf "$out" && mkdir -p "$out/kse" "$out/platform"
tar xzf "$(ls "$products"/kse-workbench-*-linux.gtk.x86_64.tar.gz)" -C "$out/kse"
tar xzf "$(ls "$products"/eclipse-platform-*-linux.gtk.x86_64.tar.gz)" -C "$out/platform"

source "$here/tests/product/virtual-display.sh"
trap 'kill ${xvfb:-} 2>/dev/null || true; [ -n "${pid:-}" ] && kill $pid 2>/dev/null || true' EXIT
start_virtual_display "$out/xvfb.log"

# $1: which product; sets $splash and $window (ms from the start command, splash -1 when none)
start() {
  local started now tree
  started=$(date +%s%N)
  if [ "$1" = kse ]; then
    DISPLAY="$display" XDG_CACHE_HOME="$out/cache" "$out/kse/kse-workbench" -data "$out/kse-workspace" > "$out/kse.log" 2>&1 &
  else
    # the JVM options KSE's start script gives, its own class data sharing archive included
    DISPLAY="$display" "$java" -Xss16m -XX:+AutoCreateSharedArchive -XX:SharedArchiveFile="$out/platform.jsa" \
      -jar "$(ls "$out"/platform/plugins/org.eclipse.equinox.launcher_*.jar)" -data "$out/platform-workspace" > "$out/platform.log" 2>&1 &
  fi
  pid=$!
  splash=-1 window=-1
  for _ in $(seq 1 3000); do
    tree=$(DISPLAY="$display" xwininfo -root -children 2>/dev/null || true)
    now=$(( ($(date +%s%N) - started) / 1000000 ))
    [ "$splash" -lt 0 ] && grep -q ' 480x280+' <<< "$tree" && splash=$now
    # the workbench window: a top-level window at least 640 pixels wide
    if grep -q -E ' (6[4-9][0-9]|[7-9][0-9]{2}|[1-9][0-9]{3})x[0-9]+\+' <<< "$tree"; then window=$now; break; fi
    kill -0 $pid 2>/dev/null || { cat "$out/$1.log" >&2; echo "workbench-start: $1 exited" >&2; exit 1; }
    sleep 0.02
  done
  stop_process $pid
  pid=""
  sleep 1 # the disk settles after the workbench's exit
}

median() { sort -n | awk '{ v[NR] = $1 } END { print v[int((NR + 1) / 2)] }'; }
start kse; start platform # first starts: workspaces and class data sharing archives made
: > "$out/kse.ms"; : > "$out/platform.ms"; : > "$out/splash.ms"
for run in $(seq 1 "$runs"); do
  start kse; echo "$window" >> "$out/kse.ms"; echo "$splash" >> "$out/splash.ms"
  start platform; echo "$window" >> "$out/platform.ms"
  echo "   run $run: KSE window ${window} ms after start" >&2
done
kse=$(median < "$out/kse.ms"); platform=$(median < "$out/platform.ms"); splash=$(median < "$out/splash.ms")
echo "workbench start, warm, median of $runs: KSE splash ${splash} ms, KSE window ${kse} ms; bare Eclipse platform window ${platform} ms (baseline); ratio $(awk -v a="$kse" -v b="$platform" 'BEGIN { printf "%.2f", a / b }')"
