#!/usr/bin/env bash
# Installs KSE from its update site into a stock Eclipse, as a user of an Eclipse IDE would:
# checks the site (no JRE unit, no root files, every third-party bundle KSE needs is in it),
# installs org.kse.ui.feature with the p2 director into the bare Eclipse platform product built
# in the same reactor, starts that IDE under Xvfb with a statechart named on its command line,
# and waits for the statechart editor's window title; then checks the IDE's .metadata/.log.
# Usage: tests/product/install-into-eclipse.sh <output-folder>
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
# shellcheck source=../../releng/stop-process.sh
. "$here/releng/stop-process.sh"
out="$(mkdir -p "$1" && cd "$1" && pwd)"
site="$here/releng/org.kse.updatesite/target/repository"
platform_archive=$(ls "$here"/releng/org.kse.product/target/products/eclipse-platform-*-linux.gtk.x86_64.tar.gz)
java="${JAVA_HOME:+$JAVA_HOME/bin/}java"
fail() { echo "install-into-eclipse: $*" >&2; exit 1; }

echo "-- the update site"
[ -f "$site/content.jar" ] || [ -f "$site/content.xml.xz" ] || fail "no update site at $site (build it first)"
content="$out/content.xml"
if [ -f "$site/content.xml.xz" ]; then xz -dc "$site/content.xml.xz" > "$content"; else unzip -p "$site/content.jar" content.xml > "$content"; fi
units=$(grep -o "<unit id='[^']*' version='[^']*'" "$content" | sed "s/<unit id='\([^']*\)' version='\([^']*\)'/\1 \2/")
if grep -E '^(a\.jre|config\.a\.jre)' <<< "$units"; then fail "the site publishes a JRE unit"; fi
if grep -E '\.rootfiles|_root\.' <<< "$units"; then fail "the site publishes root files, which would land in the IDE's folder"; fi
for bundle in org.kse.ui org.kse.diagram.server wrapped.org.eclipse.glsp.org.eclipse.glsp.server org.eclipse.xtext org.eclipse.xtext.ide \
              org.eclipse.lsp4j org.eclipse.elk.core org.eclipse.elk.alg.layered org.eclipse.emf.ecore \
              org.apache.commons.cli org.apache.logging.log4j.api org.apache.logging.log4j.core org.antlr.runtime \
              com.google.inject org.eclipse.jetty.ee10.websocket.jakarta.server; do
  grep -q -E "^$bundle " <<< "$units" || fail "the site lacks $bundle, which KSE needs and a stock Eclipse does not have"
  ls "$site"/plugins/"$bundle"_*.jar > /dev/null 2>&1 || fail "the site lists $bundle but has no artifact for it"
done
echo "   $(wc -l <<< "$units") units, $(ls "$site/plugins" | wc -l) bundles; no JRE unit, no root files; GLSP, Jetty, lsp4j, Log4j, Xtext, ELK, commons-cli inside"

echo "-- installed with the p2 director into a bare Eclipse platform"
ide="$out/eclipse"
rm -rf "$ide" "$out/workspace" "$out/models"
mkdir -p "$ide"
tar xzf "$platform_archive" -C "$ide"
if ls "$ide"/plugins/org.kse.* > /dev/null 2>&1; then fail "the bare platform already holds KSE bundles"; fi
launcher=$(ls "$ide"/plugins/org.eclipse.equinox.launcher_*.jar)
"$java" -jar "$launcher" -nosplash -consoleLog -application org.eclipse.equinox.p2.director \
  -repository "file:$site" -installIU org.kse.ui.feature.feature.group \
  -destination "$ide" -profile DefaultProfile > "$out/director.log" 2>&1 \
  || { cat "$out/director.log" >&2; fail "the p2 director could not install org.kse.ui.feature"; }
tail -n 3 "$out/director.log" | sed 's/^/   director: /'
ls "$ide"/plugins/org.kse.ui_*.jar > /dev/null 2>&1 || fail "no org.kse.ui in the IDE after the install"
if ls "$ide"/kse-workbench* "$ide"/kse-splash.png > /dev/null 2>&1; then fail "the install put KSE's start scripts into the IDE's folder"; fi
grep -q '^org.kse.ui,' "$ide/configuration/org.eclipse.equinox.simpleconfigurator/bundles.info" || fail "org.kse.ui is not in the IDE's bundles.info"

echo "-- the IDE started under Xvfb with a statechart on its command line"
mkdir -p "$out/models"
cp "$here/examples/Goalie/Goalie.stct" "$out/models/"
source "$here/tests/product/virtual-display.sh"
trap 'kill ${xvfb:-} 2>/dev/null || true; [ -n "${eclipse:-}" ] && kill $eclipse 2>/dev/null || true' EXIT
start_virtual_display "$out/xvfb.log"
(cd "$out/models" && DISPLAY="$display" exec "$java" -Xss16m -XX:ErrorFile="$out/hs_err_%p.log" -jar "$launcher" -data "$out/workspace" -consoleLog Goalie.stct) > "$out/eclipse.log" 2>&1 &
eclipse=$!
title=""
for _ in $(seq 1 1200); do
  title=$(DISPLAY="$display" xwininfo -root -tree 2>/dev/null | grep -o '"[^"]*Goalie.stct[^"]*"' | head -n 1 || true)
  [ -n "$title" ] && break
  kill -0 $eclipse 2>/dev/null || { cat "$out/eclipse.log" >&2; fail "the IDE exited"; }
  sleep 0.1
done
[ -n "$title" ] || { DISPLAY="$display" import -window root "$out/eclipse.png"; fail "no window titled with Goalie.stct after 120 s (screenshot $out/eclipse.png)"; }
sleep 3
DISPLAY="$display" import -window root "$out/eclipse.png"
echo "   window $title; screenshot $out/eclipse.png"
stop_process $eclipse
eclipse=""
[ -f "$out/workspace/Goalie/.project" ] || [ -f "$out/models/.project" ] || fail "the statechart's folder did not become a project"
if [ -s "$out/workspace/.metadata/.log" ]; then
  cat "$out/workspace/.metadata/.log" >&2
  fail "the IDE's .metadata/.log is not empty after opening the statechart"
fi
echo "   .metadata/.log clean"
