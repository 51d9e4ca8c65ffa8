#!/usr/bin/env bash
# Smoke test of the KSE workbench archives: unpacks the Linux one, starts it with its start
# script under Xvfb, waits for the workbench window (screenshot), times a warm start, runs the
# headless CLI inside the same product; lists the Windows archive for its SWT and launcher
# fragments and its start script (it cannot run here).
# Usage: tests/product/smoke.sh <output-folder>
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
# shellcheck source=../../releng/stop-process.sh
. "$here/releng/stop-process.sh"
out="$(mkdir -p "$1" && cd "$1" && pwd)"
products="$here/releng/org.kse.product/target/products"
linux=$(ls "$products"/kse-workbench-*-linux.gtk.x86_64.tar.gz)
windows=$(ls "$products"/kse-workbench-*-win32.win32.x86_64.zip)
fail() { echo "smoke: $*" >&2; exit 1; }

echo "-- the Windows archive"
listing=$(unzip -l "$windows")
for part in 'plugins/org.eclipse.swt.win32.win32.x86_64_' 'plugins/org.eclipse.equinox.launcher.win32.win32.x86_64_' \
            ' kse-workbench.cmd$' 'plugins/org.kse.ui_' 'plugins/org.kse.cli_' 'plugins/org.kse.doc_' 'plugins/org.eclipse.help.webapp_'; do
  grep -q -E "$part" <<< "$listing" || fail "$(basename "$windows") has no ${part}"
  echo "   has ${part}"
done
if grep -q 'swt.gtk' <<< "$listing"; then fail "the Windows archive carries the Linux SWT"; fi

echo "-- the start scripts"
"$here/tests/product/start-scripts.sh" "$windows"

echo "-- the Linux archive, started under Xvfb"
rm -rf "$out/kse-workbench" "$out/workspace" "$out"/hs_err_*
mkdir -p "$out/kse-workbench"
tar xzf "$linux" -C "$out/kse-workbench"
[ -x "$out/kse-workbench/kse-workbench" ] || fail "no executable start script kse-workbench"
for part in org.kse.doc_ org.eclipse.help.ui_ org.eclipse.help.webapp_ org.eclipse.equinox.http.jetty_; do
  ls "$out/kse-workbench/plugins/$part"* > /dev/null 2>&1 || fail "the Linux archive has no $part (the user manual in Eclipse help)"
done

source "$here/tests/product/virtual-display.sh"
trap 'kill ${xvfb:-} 2>/dev/null || true; [ -n "${workbench:-}" ] && kill $workbench 2>/dev/null || true' EXIT
start_virtual_display "$out/xvfb.log"

# starts the workbench ($workbench: its pid) and waits for its window titled with the product
# name ($elapsed: milliseconds since the start script ran; $splash: whether KSE's splash, a
# 480x280 window, showed before it)
start_workbench() {
  local started tree
  started=$(date +%s%N)
  splash=no
  DISPLAY="$display" XDG_CACHE_HOME="$out/cache" KSE_JAVA_OPTS="-XX:ErrorFile=$out/hs_err_%p.log" "$out/kse-workbench/kse-workbench" -data "$out/workspace" -consoleLog > "$out/workbench-$1.log" 2>&1 &
  workbench=$!
  for _ in $(seq 1 2400); do
    tree=$(DISPLAY="$display" xwininfo -root -tree 2>/dev/null || true)
    grep -q ' 480x280+' <<< "$tree" && splash=yes
    if grep -q ' - KSE' <<< "$tree"; then
      elapsed=$(( ($(date +%s%N) - started) / 1000000 ))
      return 0
    fi
    kill -0 $workbench 2>/dev/null || { cat "$out/workbench-$1.log" >&2; fail "the workbench exited"; }
    sleep 0.05
  done
  fail "no workbench window after 120 s"
}
start_workbench cold
first=$elapsed
[ "$splash" = yes ] || fail "no splash before the workbench window"
sleep 3
if DISPLAY="$display" xwininfo -root -tree | grep -q ' 480x280+'; then fail "the splash is still up 3 s after the workbench window"; fi
echo "   the splash showed, and closed when the workbench window was up"
DISPLAY="$display" import -window root "$out/workbench.png"
echo "   window after ${first} ms (first start); screenshot $out/workbench.png"
if [ -s "$out/workspace/.metadata/.log" ]; then
  cat "$out/workspace/.metadata/.log" >&2
  fail "the workbench's .metadata/.log is not empty after a start"
fi
echo "   .metadata/.log clean after the start"
DISPLAY="$display" xwininfo -root -tree | grep -o '"[^"]* - KSE[^"]*"' | head -1
stop_process $workbench
start_workbench warm
warm=$elapsed
echo "   window after ${warm} ms (warm start)"
stop_process $workbench
workbench=""

echo "-- the headless CLI inside the workbench product"
launcher=$(ls "$out"/kse-workbench/plugins/org.eclipse.equinox.launcher_*.jar)
java="${JAVA_HOME:+$JAVA_HOME/bin/}java"
"$java" -jar "$launcher" -nosplash -application org.kse.cli.kse --version
"$java" -jar "$launcher" -nosplash -application org.kse.cli.kse validate "$here/examples/Goalie/Goalie.stct"
echo "workbench start to a visible window: ${first} ms first, ${warm} ms warm"
