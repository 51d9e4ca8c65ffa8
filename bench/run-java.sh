#!/usr/bin/env bash
# Runs a Java benchmark main class of tests/org.kse.benchmarks on the KSE product's plugins.
# Builds the product and the benchmark bundle first when they are missing.
#   usage: bench/run-java.sh <main class>
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
java_home="${JAVA_HOME:-/usr/lib/jvm/temurin-25-jdk-amd64}"
plugins="$here/releng/org.kse.product/target/products/org.kse.cli.product/linux/gtk/x86_64/plugins"
classes="$here/tests/org.kse.benchmarks/target/classes"
if [ ! -d "$plugins" ] || [ ! -d "$classes/org" ]; then
  (cd "$here" && JAVA_HOME="$java_home" ./mvnw -B -q verify -DskipTests >&2)
fi
classpath="$(ls "$plugins"/*.jar | tr '\n' ':')$classes"
exec "$java_home/bin/java" -Xss16m -Xmx2g --sun-misc-unsafe-memory-access=allow \
  -Dlog4j.configuration="file:$here/releng/log4j.properties" \
  -Dlog4j2.configurationFile="file:$here/releng/log4j2.properties" \
  -cp "$classpath" "$1"
