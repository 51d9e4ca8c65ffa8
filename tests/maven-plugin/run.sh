#!/usr/bin/env bash
# The KSE Maven plugin as a team uses it: a small project outside the repository (a KSE project
# layout, models/ and src/, with tests/maven-plugin/project/pom.xml naming the plugin by its
# coordinates org.kse:kse-maven-plugin:0.1.0-SNAPSHOT) built offline with the repository's Maven
# wrapper. Checks that
#   1. mvn kse:validate passes on the Goalie and fails on a broken copy, naming its file and
#      the diagnostic;
#   2. a build (validate + generate-sources) writes the Goalie's C++;
#   3. a second build logs the up-to-date lines and touches no file;
#   4. touching the model changes nothing (the stamp compares contents), changing it
#      regenerates: the changed guard is rewritten, an activity the user edited is kept.
# Needs the plugin and the KSE bundles in ~/.m2 (./mvnw install; test.sh's build installs them).
# Usage: tests/maven-plugin/run.sh [work-folder]   (default: a new temporary folder, removed after)
set -euo pipefail
repo="$(cd "$(dirname "$0")/../.." && pwd)"
if [ -z "${JAVA_HOME:-}" ]; then
  for candidate in /usr/lib/jvm/temurin-25-jdk-amd64 /usr/lib/jvm/java-21-openjdk-amd64 /usr/lib/jvm/default-java; do
    if [ -x "$candidate/bin/java" ]; then export JAVA_HOME="$candidate"; break; fi
  done
fi
m2="${MAVEN_REPOSITORY:-$HOME/.m2/repository}"
if [ ! -f "$m2/org/kse/kse-maven-plugin/0.1.0-SNAPSHOT/kse-maven-plugin-0.1.0-SNAPSHOT.jar" ]; then
  echo "maven-plugin: the plugin is not installed in $m2; run ./mvnw install first (or ./mvnw install -pl releng/kse-maven-plugin when the bundles are installed)" >&2
  exit 2
fi

if [ $# -ge 1 ]; then
  work="$1"; rm -rf "$work"; mkdir -p "$work"
else
  work="$(mktemp -d "${TMPDIR:-/tmp}/kse-maven-plugin.XXXXXX")"
  trap 'rm -rf "$work"' EXIT
fi
case "$work" in "$repo"/*) echo "maven-plugin: the project must be outside the repository" >&2; exit 2 ;; esac

passed=0; failed=0
pass() { passed=$((passed + 1)); echo "   ok: $1"; }
fail() { failed=$((failed + 1)); echo "   FAILED: $1"; }
check() { # description, command...
  local what="$1"; shift
  if "$@"; then pass "$what"; else fail "$what"; fi
}
has() { grep -qF -- "$2" "$1"; }
lacks() { ! grep -qF -- "$2" "$1"; }

# The repository's settings name the one mirror the artifacts in ~/.m2 came through; offline
# Maven only takes an artifact from the repository it was downloaded from.
build() { # log-name, maven arguments...: runs Maven offline on the project, returns its exit code
  local log="$work/$1.log"; shift
  local start=$SECONDS
  set +e
  "$repo/mvnw" -B -o -s "$repo/.mvn/settings.xml" -f "$work/project/pom.xml" "$@" > "$log" 2>&1
  local code=$?
  set -e
  echo "   (mvn $* : exit $code, $((SECONDS - start)) s)"
  return $code
}
mtimes() { (cd "$work/project" && find src -type f -printf '%p %T@\n' | sort); }

project="$work/project"
mkdir -p "$project/models"
cp "$repo/tests/maven-plugin/project/pom.xml" "$project/pom.xml"
cp "$repo/examples/Goalie/Goalie.stct" "$project/models/Goalie.stct"
total_start=$SECONDS

echo "== 1. mvn -o kse:validate on the Goalie, then with a broken model beside it"
if build validate-good kse:validate; then pass "kse:validate passes on the Goalie"; else fail "kse:validate passes on the Goalie"; fi
check "the model's result is in the log" has "$work/validate-good.log" "models/Goalie.stct: 0 errors"
# the Goalie with a misspelt message type in one guard, under its own model name
sed -e 's/GameStateMessage.player_state()==PLAYER_PLAYING\]/GameStateMesage.player_state()==PLAYER_PLAYING]/' \
    -e 's/name="Goalie"/name="Broken"/' "$project/models/Goalie.stct" > "$project/models/Broken.stct"
if build validate-broken kse:validate; then fail "kse:validate fails on the broken model"; else pass "kse:validate fails on the broken model"; fi
log="$work/validate-broken.log"
check "the failure names the model file and the diagnostic" \
  grep -qE "^\[ERROR\] .*models/Broken\.stct: .*\(0\.2\.2\.2_TO_playing\): error: .*unknown message type 'GameStateMesage'; did you mean 'GameStateMessage'\?" "$log"
check "the build fails with the plugin's message" has "$log" "validate (default-cli) on project goalie-behaviour: KSE: 1 of 2 models has errors"
check "the good model is still reported valid" has "$log" "models/Goalie.stct: 0 errors"
rm "$project/models/Broken.stct"

echo "== 2. a build generates the Goalie's C++"
if build generate generate-sources; then pass "the build succeeds"; else fail "the build succeeds"; fi
check "the generator ran once for the model" has "$work/generate.log" "generated Goalie into $project/src"
for file in statecharts/Goalie/Goalie.h statecharts/Goalie/Goalie.cpp statecharts/Goalie/CMakeLists.txt \
            statecharts/Goalie/transitions/TrCond_0_2_TO_0_3.h activities/Kick/Kick.cpp activities/Kick/Kick.h; do
  check "src/$file exists" test -s "$project/src/$file"
done
transitions=$(find "$project/src/statecharts/Goalie/transitions" -name '*.h' | wc -l)
check "the Goalie's guards and actions are generated ($transitions files)" test "$transitions" -ge 20

echo "== 3. a second build: up to date, nothing touched"
before="$(mtimes)" # to the nanosecond: a rewrite shows even within the same second
if build again generate-sources; then pass "the second build succeeds"; else fail "the second build succeeds"; fi
check "generate logs the up-to-date line" has "$work/again.log" "KSE: 1 model up to date, nothing to generate"
check "validate logs the up-to-date line" has "$work/again.log" "KSE: 1 model up to date, nothing to validate"
check "the generator did not run" lacks "$work/again.log" "generated Goalie"
check "no file under src/ changed its modification time" test "$before" = "$(mtimes)"

echo "== 4. the model touched, then changed"
touch "$project/models/Goalie.stct"
if build touched generate-sources; then pass "the build after touch succeeds"; else fail "the build after touch succeeds"; fi
check "a touched but unchanged model is still up to date" has "$work/touched.log" "KSE: 1 model up to date, nothing to generate"
echo "// the team's own kick" >> "$project/src/activities/Kick/Kick.cpp"
sed -i 's/player_state()==PLAYER_FINISHED\]/player_state()==PLAYER_PENALISED]/' "$project/models/Goalie.stct"
if build changed generate-sources; then pass "the build after the change succeeds"; else fail "the build after the change succeeds"; fi
check "the changed model is validated again" has "$work/changed.log" "models/Goalie.stct: 0 errors"
check "the changed model is generated again" grep -qE "generated Goalie into .*: [1-9][0-9]* written" "$work/changed.log"
check "the changed guard is rewritten" grep -q "PLAYER_PENALISED" "$project/src/statecharts/Goalie/transitions/TrCond_0_2_TO_0_3.h"
check "the edited activity is kept" has "$project/src/activities/Kick/Kick.cpp" "// the team's own kick"

echo "   $((SECONDS - total_start)) s for all builds"
if [ "$failed" -gt 0 ]; then
  echo "   logs: $work/*.log"
  trap - EXIT
fi
echo "maven-plugin: $passed passed, $failed failed"
[ "$failed" -eq 0 ]
