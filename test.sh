#!/usr/bin/env bash
# Runs every test: the Tycho build with all JUnit test bundles (inside OSGi), then a
# smoke run of the kse command on the bundled example.
set -euo pipefail
cd "$(dirname "$0")"
if [ -z "${JAVA_HOME:-}" ]; then
  for candidate in /usr/lib/jvm/temurin-25-jdk-amd64 /usr/lib/jvm/java-21-openjdk-amd64 /usr/lib/jvm/default-java; do
    if [ -x "$candidate/bin/java" ]; then export JAVA_HOME="$candidate"; break; fi
  done
fi
./mvnw -B clean verify
mkdir -p target
./kse transform -q examples/Goalie/Goalie.txt -o target/Goalie.stct
./kse validate target/Goalie.stct
./kse label target/Goalie.stct
./kse validate ../shared/legacy-kse/Goalie/Goalie.stct
