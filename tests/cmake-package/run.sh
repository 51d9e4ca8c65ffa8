#!/usr/bin/env bash
# A project outside the repository builds a behaviour with the runtime's CMake package:
# find_package(kse_runtime) and kse_add_statechart(Goalie models/Goalie.stct), which runs
# `kse generate` at build time. Checks that (1) it builds and plays a match with the Goalie,
# (2) a build with nothing changed does nothing, (3) a changed model is generated and compiled
# again, (4) a model with an error stops the build with the model's diagnostic, (5) a call named
# otherwise than the model says which name to use; and (6) the activity skeletons `kse generate`
# writes for every example compile and link as written, untouched (issue 18, item 3); and (7) the
# complete activity of docs/writing-activities.md builds as the page says and chases the ball.
#   usage: tests/cmake-package/run.sh <runtime-prefix> <out-folder>
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
prefix="$(cd "$1" && pwd)"
out="$2"
rm -rf "$out"
mkdir -p "$out"
out="$(cd "$out" && pwd)"
fail() { echo "cmake-package: $*" >&2; exit 1; }

project="$out/team"
mkdir -p "$project/models"
cp "$here/tests/cmake-package/project/CMakeLists.txt" "$project/"
cp "$here/examples/Goalie/Goalie.stct" "$project/models/"
cp -r "$here/examples/src/activities" "$project/activities"

cmake -S "$project" -B "$out/build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
  -DKSE_EXECUTABLE="$here/kse" > "$out/configure.log" || { cat "$out/configure.log"; fail "configure failed"; }
cmake --build "$out/build" -j 2 > "$out/build1.log" 2>&1 || { tail -30 "$out/build1.log"; fail "the first build failed"; }
grep -q "kse generate Goalie from models/Goalie.stct" "$out/build1.log" || fail "the first build did not run kse generate"
[ -f "$out/build/kse_Goalie/statecharts/Goalie/Goalie.cpp" ] || fail "no generated Goalie.cpp in the build tree"
[ ! -e "$out/build/kse_Goalie/activities" ] || fail "activity skeletons were written into the build tree"
"$out/build/team-match" --list | grep -qx "Goalie" || { "$out/build/team-match" --list; fail "the program does not list the Goalie"; }
"$out/build/team-match" --home Goalie:1 --away Goalie:1 --half 20 --seed 3 --quiet --log "$out/match1.jsonl" > "$out/match1.txt" \
  || { cat "$out/match1.txt"; fail "the match with the Goalie failed"; }
echo "   built and played: $(head -n 1 "$out/match1.txt")"

cmake --build "$out/build" -j 2 > "$out/build2.log" 2>&1
grep -q "no work to do" "$out/build2.log" || { cat "$out/build2.log"; fail "a build with nothing changed did work"; }
echo "   nothing changed: no work"

# a change a user makes: the goalie's wait before it scans again (the first TimeoutAction)
grep -q 'TimeoutAction.behavior.250' "$project/models/Goalie.stct" || fail "the Goalie has no TimeoutAction.behavior.250 to change"
sed -i '0,/TimeoutAction.behavior.250/s//TimeoutAction.behavior.4321/' "$project/models/Goalie.stct"
cmake --build "$out/build" -j 2 > "$out/build3.log" 2>&1 || { tail -30 "$out/build3.log"; fail "the build after a change failed"; }
grep -q "kse generate Goalie" "$out/build3.log" || fail "the changed model was not generated again"
grep -q "Goalie.cpp.o" "$out/build3.log" || fail "the changed statechart was not compiled again"
grep -rq "4321" "$out/build/kse_Goalie/statecharts/Goalie" || fail "the change is not in the generated C++"
echo "   model changed: generated and compiled again"

cp "$project/models/Goalie.stct" "$out/Goalie.good"
sed -i '0,/TimeoutAction.behavior.4321/s//TimeoutAction.behavior.4321(/' "$project/models/Goalie.stct"
if cmake --build "$out/build" -j 2 > "$out/build4.log" 2>&1; then fail "a model with an error built"; fi
grep -q "models/Goalie.stct: .*error: expression" "$out/build4.log" || { cat "$out/build4.log"; fail "the build failed without the model's diagnostic"; }
grep -q "kse_add_statechart(Goalie): kse generate refused" "$out/build4.log" || fail "the failure does not name the call"
echo "   model with an error: $(grep -m 1 'error: expression' "$out/build4.log" | sed "s#$project/##")"
cp "$out/Goalie.good" "$project/models/Goalie.stct"

sed -i 's/kse_add_statechart(Goalie models\/Goalie.stct)/kse_add_statechart(Keeper models\/Goalie.stct)/; s/statechart_Goalie/statechart_Keeper/' "$project/CMakeLists.txt"
if cmake --build "$out/build" -j 2 > "$out/build5.log" 2>&1; then fail "a call named otherwise than its model built"; fi
grep -q "holds the statechart 'Goalie', not 'Keeper'" "$out/build5.log" || { tail -20 "$out/build5.log"; fail "no word of the model's name"; }
echo "   call named otherwise: $(grep -m 1 -o "holds the statechart.*" "$out/build5.log")"
skeletons="$out/skeletons"
"$here/kse" generate -q "$here"/examples/*/*.stct -o "$skeletons/src" > "$out/skeletons.log"
cat > "$skeletons/CMakeLists.txt" <<'CMAKE'
# every example's statechart from the models, each activity as `kse generate` wrote its skeleton
cmake_minimum_required(VERSION 3.20)
project(skeletons LANGUAGES CXX)
find_package(kse_runtime REQUIRED)
set(targets "")
foreach(model Goalie Attacker Defender)
  kse_add_statechart(${model} ${CMAKE_CURRENT_SOURCE_DIR}/models/${model}.stct)
  list(APPEND targets statechart_${model})
endforeach()
file(GLOB folders LIST_DIRECTORIES true ${CMAKE_CURRENT_SOURCE_DIR}/src/activities/*)
foreach(folder IN LISTS folders)
  get_filename_component(name ${folder} NAME)
  add_subdirectory(${folder})
  list(APPEND targets activity_${name})
endforeach()
add_executable(skeleton-match)
target_link_libraries(skeleton-match PRIVATE kse::sim_main ${targets})
CMAKE
mkdir -p "$skeletons/models"
cp "$here"/examples/*/*.stct "$skeletons/models/"
cmake -S "$skeletons" -B "$out/skeletons-build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" \
  -DKSE_EXECUTABLE="$here/kse" > "$out/skeletons.configure.log" || { cat "$out/skeletons.configure.log"; fail "the skeletons' project did not configure"; }
cmake --build "$out/skeletons-build" -j 2 > "$out/skeletons.build.log" 2>&1 || { tail -30 "$out/skeletons.build.log"; fail "the generated skeletons do not compile"; }
"$out/skeletons-build/skeleton-match" --list > "$out/skeletons.list"
for model in Goalie Attacker Defender; do grep -qx "$model" "$out/skeletons.list" || fail "skeleton-match does not list $model"; done
echo "   skeletons: the $(ls "$skeletons/src/activities" | wc -l) activities of the three examples compile and link as generated"

# (7) The complete activity of docs/writing-activities.md (tests/cmake-package/chaser holds the
# files the page prints; DocumentationPagesTest checks that the page prints them and these
# commands as they are): the page's commands make the model, the project builds, and the robot
# chases the ball in a match.
chaser="$out/chaser"
cp -r "$here/tests/cmake-package/chaser" "$chaser"
(
  cd "$chaser"
  kse() { "$here/kse" "$@"; }
  mkdir -p models
  printf 'chaser = ChaseBall~\n' > models/chaser.liveness
  kse transform models/chaser.liveness -o models/chaser.stct
  kse edit-transition models/chaser.stct 0.1 ChaseBall --expression '/TimeoutAction.behavior.100'
  kse edit-transition models/chaser.stct ChaseBall ChaseBall --expression '[TimeoutCheck(behavior)]/TimeoutAction.behavior.100'
  kse validate models/chaser.stct
  cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" -DKSE_EXECUTABLE="$here/kse"
  cmake --build build -j 2
  ./build/chaser-match --home chaser:2 --away none --half 30 --start-playing --log chase.jsonl
) > "$out/chaser.log" 2>&1 || { tail -30 "$out/chaser.log"; fail "the example of docs/writing-activities.md did not build or play"; }
# the robot walks while in ChaseBall, and has pushed the ball 0.3 m or more up the field by the end
grep -q '"motion":"walk","penalty":0,"ballSeen":[a-z]*,"active":\["Node_chaser","Node_ChaseBall"\]' "$chaser/chase.jsonl" \
  || fail "the chaser's robot never walked in ChaseBall ($chaser/chase.jsonl)"
ball_x="$(grep '"type":"frame"' "$chaser/chase.jsonl" | tail -n 1 | sed 's/.*"ball":\[\([-0-9.]*\),.*/\1/')"
awk -v x="$ball_x" 'BEGIN { exit !(x >= 0.3) }' || fail "the chaser did not push the ball up the field (ball at x = $ball_x m at the end)"
echo "   docs/writing-activities.md: ChaseBall built and played, the ball pushed to x = $ball_x m"
echo "cmake-package: an outside project builds its behaviour with kse_add_statechart"
