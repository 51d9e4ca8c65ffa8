#!/usr/bin/env bash
# Follows docs/getting-started.md command by command in a fresh folder (issue 18, item 5): the
# commands are the page's own ```sh blocks, extracted here, so the page cannot drift from what
# works. Blocks the page marks `<!-- getting-started test: not run ... -->` (where the user's
# clone and prefix are, installing the runtime) are replaced by this script's settings: the
# runtime comes installed (<runtime-prefix>, copied, so the examples' install does not touch it).
# Then checks the outcome: the examples installed as a package, the project made, validated with
# 0 errors and 0 warnings, built, both matches played with their result line and log, the
# Strikers took transitions; and that activity names cannot clash silently (ADR 0029): one named
# like an example's stops the configuration naming both, and one registered under an example's
# name stops kse-match naming both files.
#   usage: tests/getting-started/run.sh <runtime-prefix> <out-folder>
#   KSE_BIN=DIR: the folder of the kse command to put on the PATH (default: the repository's ./kse)
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
page="$here/docs/getting-started.md"
given="$(cd "$1" && pwd)"
out="$2"
rm -rf "$out"
mkdir -p "$out/work"
out="$(cd "$out" && pwd)"
fail() { echo "getting-started: $*" >&2; exit 1; }

# the runtime as given, without examples a previous install may have put beside it
cp -a "$given" "$out/prefix"
rm -rf "$out/prefix"/lib*/kse_examples "$out/prefix"/lib*/cmake/kse_examples

# the page's sh blocks, each with its line number, the marked ones left out
python3 - "$page" "$out/page.sh" <<'PY'
import re, sys
text = open(sys.argv[1], encoding="utf-8").read()
blocks, skipped = [], 0
for match in re.finditer(r"(?m)^```sh\n(.*?)^```$", text, re.S):
    before = text[:match.start()].rstrip("\n").splitlines()
    line = text.count("\n", 0, match.start()) + 1
    if before and before[-1].startswith("<!-- getting-started test: not run"):
        skipped += 1
        continue
    blocks.append("echo '== docs/getting-started.md:%d' >&2\n%s" % (line, match.group(1)))
if skipped != 2 or len(blocks) < 8:
    sys.exit("getting-started: expected 2 blocks marked not run and the rest to run, found %d and %d" % (skipped, len(blocks)))
open(sys.argv[2], "w").write("set -ex\n" + "\n".join(blocks))
PY

echo "   running $(grep -c '^echo .== docs' "$out/page.sh") blocks of docs/getting-started.md in $out/work (log: $out/page.log)"
# what the page's first block sets, for this script's folders (kse also for the builds below)
export KSE_HOME="$here" KSE_PREFIX="$out/prefix" PATH="${KSE_BIN:-$here}:$PATH"
(
  cd "$out/work"
  bash "$out/page.sh"
) > "$out/page.log" 2>&1 || { tail -40 "$out/page.log"; fail "a command of the page failed (above; whole log: $out/page.log)"; }

project="$out/work/Striker"
[ -f "$out/prefix/lib/cmake/kse_examples/kse_examplesConfig.cmake" ] || fail "the examples were not installed as a package"
for file in Striker.liveness Striker.stct CMakeLists.txt README.md src/activities/Chase/Chase.cpp src/activities/Wait/Wait.cpp \
    src/activities/Shoot/Shoot.cpp Striker.svg; do
  [ -f "$project/$file" ] || fail "the project has no $file"
done
[ "$(grep -c 'Striker.stct: 0 errors, 0 warnings' "$out/page.log")" = 2 ] \
  || fail "kse validate did not find 0 errors and 0 warnings twice (as made, and after the guards)"
[ "$(grep -o 'TE="' "$project/Striker.stct" | wc -l)" = 5 ] || fail "Striker.stct does not hold the page's 5 expressions"
results="$(grep -cE '^home [0-9]+ : [0-9]+ away after .* FINISHED' "$out/page.log" || true)"
[ "$results" = 2 ] || fail "expected the result lines of 2 matches, found $results"
grep -q '"type":"result"' "$project/match.jsonl" || fail "the log has no result line"
grep -q 'activity_Shoot' "$out/page.log" || fail "the second build did not compile the new activity"
python3 - "$project/match.jsonl" <<'PY' || fail "the Strikers did not play their statechart"
import json, sys
taken = {"home-2": 0, "home-3": 0}
states = set()
for line in open(sys.argv[1]):
    record = json.loads(line)
    if record["type"] != "frame":
        continue
    for robot in record["robots"]:
        if robot["id"] in taken:
            taken[robot["id"]] += len(robot["taken"])
            states.update(robot["active"])
print("   Strikers: %s transitions taken; states %s" % (taken, ", ".join(sorted(s for s in states if s in ("Node_Wait", "Node_Chase", "Node_Shoot")))))
if min(taken.values()) < 100 or not {"Node_Wait", "Node_Chase"} <= states:
    sys.exit(1)
PY
echo "   $(grep -m 1 -E '^home [0-9]+ : [0-9]+ away after' "$out/page.log") (first match); $(grep -E '^home [0-9]+ : [0-9]+ away after' "$out/page.log" | tail -1) (after the kick)"

# an activity named like one of the examples' stops the configuration, naming both
clash="$out/clash"
cp -r "$project" "$clash"
rm -rf "$clash/build"
cp -r "$clash/src/activities/Shoot" "$clash/src/activities/Scan"
(cd "$clash/src/activities/Scan" && for f in Shoot.h Shoot.cpp; do sed 's/Shoot/Scan/g' "$f" > "${f/Shoot/Scan}"; rm "$f"; done \
  && sed -i 's/Shoot/Scan/g' CMakeLists.txt)
if cmake -S "$clash" -B "$clash/build" -DCMAKE_PREFIX_PATH="$out/prefix" > "$out/clash.log" 2>&1; then
  fail "an activity named Scan beside the examples' Scan configured"
fi
# CMake wraps its messages: the words joined again
said="$(tr -s ' \n' ' ' < "$out/clash.log")"
grep -q "the activity 'Scan' of $clash/src/activities/Scan has the name of the activity 'Scan' of the installed examples ($out/prefix/lib/kse_examples/objects)" <<< "$said" \
  || { cat "$out/clash.log"; fail "the clash does not name both activities"; }
echo "   an activity named like an example's: $(grep -o "the activity 'Scan' of .*installed examples" <<< "$said" | sed "s#$out/##")"

# registered under an example's name from a folder of another name: kse-match stops naming both files
rm -rf "$clash/src/activities/Scan"
cp -r "$clash/src/activities/Shoot" "$clash/src/activities/Sweep"
(cd "$clash/src/activities/Sweep" && sed 's/Shoot/Sweep/g' Shoot.h > Sweep.h && sed 's/Shoot/Sweep/g; s/registrar("Sweep")/registrar("Scan")/' Shoot.cpp > Sweep.cpp \
  && rm Shoot.h Shoot.cpp && sed -i 's/Shoot/Sweep/g' CMakeLists.txt)
grep -q 'registrar("Scan")' "$clash/src/activities/Sweep/Sweep.cpp" || fail "the test did not make Sweep register as Scan"
cmake -S "$clash" -B "$clash/build" -DCMAKE_PREFIX_PATH="$out/prefix" > "$out/clash2.log" 2>&1 || { cat "$out/clash2.log"; fail "the project with Sweep did not configure"; }
cmake --build "$clash/build" -j 2 >> "$out/clash2.log" 2>&1 || { tail -30 "$out/clash2.log"; fail "the project with Sweep did not build"; }
if "$clash/build/kse-match" --half 10 > "$out/clash-match.log" 2>&1; then fail "kse-match played with two activities named Scan"; fi
grep -q "kse-match: error: activity 'Scan' is registered twice: by .*/src/activities/.*\.cpp and by .*/src/activities/.*\.cpp" "$out/clash-match.log" \
  || { cat "$out/clash-match.log"; fail "kse-match did not name both registrations"; }
grep -q "$clash/src/activities/Sweep/Sweep.cpp" "$out/clash-match.log" || { cat "$out/clash-match.log"; fail "kse-match did not name Sweep.cpp"; }
echo "   registered under an example's name: $(grep -m 1 -o "activity 'Scan' is registered twice.*" "$out/clash-match.log" | sed "s#$out/##; s#$here/##")"
echo "getting-started: the page's commands make, build and play a behaviour of one's own"
