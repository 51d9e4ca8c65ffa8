#!/usr/bin/env bash
# kse: the KSE command line on a plain class path (ADR 0023). Its folder holds lib/ (the jars,
# their order in lib/classpath, the JVM options in lib/jvm-options) and lib/kse.aot, the
# ahead-of-time cache recorded by the build, used when this JDK is the one that recorded it.
set -euo pipefail
home="$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")/.." && pwd)"
lib="$home/lib"

java_home=""
for candidate in "${JAVA_HOME:-}" /usr/lib/jvm/temurin-25-jdk-amd64; do
  if [ -n "$candidate" ] && [ -x "$candidate/bin/java" ] && [ -r "$candidate/release" ]; then
    version=$(sed -n 's/^JAVA_VERSION="\([0-9]*\).*/\1/p' "$candidate/release")
    if [ "${version:-0}" -ge 21 ] 2>/dev/null; then java_home="$candidate"; break; fi
  fi
done
if [ -z "$java_home" ]; then
  echo "kse: needs a JDK 21 or newer (JDK 25 recommended); set JAVA_HOME" >&2
  exit 2
fi

classpath=""
while IFS= read -r jar; do classpath="$classpath${classpath:+:}$lib/$jar"; done < "$lib/classpath"
options=()
while IFS= read -r option; do
  # the option that lets Guice use sun.misc.Unsafe without a warning is JDK 24's
  if [ "$option" = --sun-misc-unsafe-memory-access=allow ] && [ "$version" -lt 24 ]; then continue; fi
  # a server lives long enough for the optimizing compiler to pay; a command does not
  if [ "$option" = -XX:TieredStopAtLevel=1 ] && { [ "${1:-}" = serve ] || [ "${1:-}" = lsp ]; }; then continue; fi
  options+=("$option")
done < "$lib/jvm-options"
cache=()
if [ -r "$lib/kse.aot" ] && grep -qxF "$(grep '^JAVA_RUNTIME_VERSION=' "$java_home/release")" "$lib/kse.aot.jdk" 2>/dev/null; then
  # a cache that still does not fit (another CPU, say) is skipped silently: it only costs time
  cache=("-XX:AOTCache=$lib/kse.aot" "-Xlog:aot=off" "-Xlog:cds=off")
fi
exec "$java_home/bin/java" ${options[@]+"${options[@]}"} ${cache[@]+"${cache[@]}"} \
  -Dlog4j2.configurationFile="$lib/log4j2.properties" -Dlog4j.configuration="file:$lib/log4j.properties" \
  -cp "$classpath" org.kse.cli.Kse "$@"
