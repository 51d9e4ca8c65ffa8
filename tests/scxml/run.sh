#!/usr/bin/env bash
# The conformance cases exported as SCXML and run in Qt SCXML: `kse export-scxml` writes every
# case's statechart, each document is checked against the W3C SCXML schema, and the driver
# (driver/, Qt6::Scxml, the runtime's script parser and messages) plays each case's script on it;
# the traces must be the case's. The export refuses some cases per element (REFUSED below, with the
# reason; docs/adr/0038-scxml-mapping.md): for those, the refusal itself is what is checked.
#   usage: tests/scxml/run.sh <runtime-install-prefix> <work-dir>
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
repo="$(cd "$here/../.." && pwd)"
prefix="$1"
work="$2"
kse="${KSE:-$repo/kse}"
# case -> why the export refuses it: "<transition name>: <reason>" (none today)
declare -A REFUSED=()
rm -rf "$work/charts"
mkdir -p "$work/charts"
status=0
cases=()
# one call for every case (one JVM); a refused case's errors name its file
"$kse" export-scxml "$here"/../conformance/cases/*.stct -o "$work/charts" > "$work/export.log" 2> "$work/export.err" || true
for model in "$here"/../conformance/cases/*.stct; do
  name="$(basename "$model" .stct)"
  if [ -f "$work/charts/$name.scxml" ]; then
    if [ -n "${REFUSED[$name]:-}" ]; then echo "FAIL $name: exported, but listed as refused"; status=1; fi
    cases+=("$here/../conformance/cases/$name.case")
  elif [ -z "${REFUSED[$name]:-}" ]; then
    echo "FAIL $name: refused:"; grep "/$name.stct" "$work/export.err"; status=1
  elif ! grep -q "/$name.stct: ERROR .*'${REFUSED[$name]%%:*}'" "$work/export.err"; then
    echo "FAIL $name: refused for another reason than listed:"; grep "/$name.stct" "$work/export.err"; status=1
  fi
done
echo "exported ${#cases[@]} cases, ${#REFUSED[@]} refused per element"
java="${JAVA_HOME:-/usr/lib/jvm/temurin-25-jdk-amd64}/bin/java"
"$java" "$here/ValidateScxml.java" "$repo/tests/data/scxml-schema/scxml.xsd" "$work/charts"/*.scxml || status=1
cmake -S "$here/driver" -B "$work/build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_PREFIX_PATH="$prefix" > "$work/configure.log" || { cat "$work/configure.log"; exit 1; }
cmake --build "$work/build" -j 2 > "$work/build.log" || { cat "$work/build.log"; exit 1; }
QT_QPA_PLATFORM=offscreen "$work/build/kse_scxml_driver" --charts "$work/charts" "${cases[@]}" | grep -v '^PASS ' || status=1
exit $status
