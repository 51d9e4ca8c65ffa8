#!/usr/bin/env bash
# Tests the start scripts. The Linux one runs from a fake product folder (a path with a space and
# parentheses) under fake java executables, and under the real Java 17 when there is one. The
# Windows one cannot run here (no cmd.exe): its text is checked (CRLF line ends, which cmd.exe
# needs for labels and for loops; goto targets; no multi-line blocks), and the Windows archive,
# when there is one, for the script, the splash and the native fragments.
# Usage: tests/product/start-scripts.sh [kse-workbench-*-win32.win32.x86_64.zip]
set -euo pipefail
here="$(cd "$(dirname "$0")/../.." && pwd)"
rootfiles="$here/features/org.kse.workbench.feature/rootfiles"
fail() { echo "start-scripts: $*" >&2; exit 1; }

tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
product="$tmp/KSE (test) folder"
log="$product/kse-workbench.log"
launcher="$product/plugins/org.eclipse.equinox.launcher_1.0.0.jar"
mkdir -p "$product/plugins"
cp "$rootfiles/linux/kse-workbench" "$rootfiles/common/kse-splash.png" "$product/"
: > "$launcher"

# a fake java: reports the java.specification.version written in <its JDK folder>/version (none
# for "broken") and writes the arguments of any other call to <its JDK folder>/arguments
cat > "$tmp/java" <<'EOF'
#!/bin/sh
jdk="$(cd "$(dirname "$0")/.." && pwd)"
if [ "$1" = -XshowSettings:properties ]; then
  version=$(cat "$jdk/version")
  if [ "$version" != broken ]; then
    printf '    %s\n' "java.home = $jdk" "java.specification.version = $version" "java.vm.specification.version = $version" >&2
  fi
  exit 0
fi
printf '%s\n' "$@" > "$jdk/arguments"
EOF
fake_java() {
  mkdir -p "$tmp/jdk-$1/bin"
  echo "$1" > "$tmp/jdk-$1/version"
  cp "$tmp/java" "$tmp/jdk-$1/bin/java"
  chmod +x "$tmp/jdk-$1/bin/java"
}
for version in 1.8 17 21 25 broken; do fake_java "$version"; done
mkdir -p "$tmp/jdk-empty"
# a PATH with what the script needs, and no java
mkdir -p "$tmp/tools"
for tool in dirname sed date; do ln -s "$(command -v "$tool")" "$tmp/tools/$tool"; done

# run <env arguments>...: runs the Linux script under env with these settings and the given
# script arguments; sets $code and $output (stdout and stderr)
run() {
  set +e
  output=$(env "$@" "$product/kse-workbench" -data "$tmp/work space" -consoleLog 2>&1)
  code=$?
  set -e
}

# refused <case> <text>...: the last run exited with 2 and a message with each text, and logged it
refused() {
  local case=$1 text
  shift
  [ "$code" = 2 ] || fail "$case: exit code $code, expected 2; output: $output"
  for text in "$@" "(also in $log)"; do
    grep -qF -- "$text" <<< "$output" || fail "$case: the message does not say '$text': $output"
  done
  [ -f "$log" ] || fail "$case: no $log"
  grep -qF -- "${output% (also in*}" "$log" || fail "$case: the log does not hold the message; it holds: $(cat "$log")"
  echo "   ok $case: $output"
  rm -f "$log"
}

# started <case> <jdk> <arguments expected before -jar>...: the last run exited with 0 and
# started that JDK's java with these arguments, the launcher, -name KSE and the script's arguments
started() {
  local case=$1 jdk=$2 expected
  shift 2
  [ "$code" = 0 ] || fail "$case: exit code $code, expected 0; output: $output"
  [ -f "$jdk/arguments" ] || fail "$case: $jdk/bin/java was not started; output: $output"
  expected=$(printf '%s\n' "$@" -jar "$launcher" -name KSE -data "$tmp/work space" -consoleLog)
  [ "$(cat "$jdk/arguments")" = "$expected" ] || fail "$case: java was started with
$(cat "$jdk/arguments")
expected
$expected"
  [ ! -e "$log" ] || fail "$case: a start that worked logged $(cat "$log")"
  echo "   ok $case: $(tr '\n' ' ' < "$jdk/arguments")"
}

echo "-- the Linux start script"
[ -x "$rootfiles/linux/kse-workbench" ] || fail "the Linux start script is not executable"
if grep -q $'\r' "$rootfiles/linux/kse-workbench"; then fail "the Linux start script has CR line ends"; fi

run -u JAVA_HOME PATH="$tmp/tools"
refused "no java" "needs Java 21 or newer and found none" "JAVA_HOME is not set" "no java on the PATH"
run JAVA_HOME="$tmp/jdk-empty" PATH="$tmp/tools"
refused "JAVA_HOME without java" "found none" "JAVA_HOME is $tmp/jdk-empty" "no bin/java"
run JAVA_HOME="$tmp/jdk-1.8"
refused "Java 1.8 as JAVA_HOME" "found Java 1.8 at $tmp/jdk-1.8/bin/java" "JAVA_HOME is $tmp/jdk-1.8"
run -u JAVA_HOME PATH="$tmp/jdk-17/bin:$PATH"
refused "Java 17 first on the PATH" "found Java 17 at $tmp/jdk-17/bin/java" "JAVA_HOME is not set"
run JAVA_HOME="$tmp/jdk-broken"
refused "a java without a version" "could not read the version of $tmp/jdk-broken/bin/java" "JAVA_HOME is $tmp/jdk-broken"

run -u JAVA_HOME PATH="$tmp/tools" && run -u JAVA_HOME PATH="$tmp/tools"
[ "$(wc -l < "$log")" = 2 ] || fail "two refusals did not append two lines to the log: $(cat "$log")"
echo "   ok refusals append to the log"
rm -f "$log"
mkdir "$log"
run -u JAVA_HOME PATH="$tmp/tools"
[ "$code" = 2 ] || fail "no writable log: exit code $code, expected 2"
if grep -qF "also in" <<< "$output"; then fail "no writable log, yet the message names it: $output"; fi
echo "   ok no writable log: $output"
rmdir "$log"

cache="$tmp/cache home/kse"
archive="$cache/workbench-$(printf '%s' "$product" | cksum | cut -d ' ' -f 1)"
run JAVA_HOME="$tmp/jdk-25" PATH="$tmp/jdk-17/bin:$PATH" KSE_JAVA_OPTS="-Dkse.test=yes -Xmx1g" XDG_CACHE_HOME="$tmp/cache home"
started "Java 25 as JAVA_HOME, KSE_JAVA_OPTS" "$tmp/jdk-25" -Xss16m --sun-misc-unsafe-memory-access=allow \
  -XX:+AutoCreateSharedArchive "-XX:SharedArchiveFile=$archive-java25.jsa" "-splash:$product/kse-splash.png" -Dkse.test=yes -Xmx1g
[ -d "$cache" ] || fail "the class data sharing folder $cache was not made"
run -u JAVA_HOME -u KSE_JAVA_OPTS PATH="$tmp/jdk-21/bin:$PATH" XDG_CACHE_HOME="$tmp/cache home"
started "Java 21 first on the PATH" "$tmp/jdk-21" -Xss16m -XX:+AutoCreateSharedArchive "-XX:SharedArchiveFile=$archive-java21.jsa" "-splash:$product/kse-splash.png"
chmod 555 "$tmp/cache home" && rm -rf "$cache"
if [ -w "$tmp/cache home" ]; then echo "   (root can write anywhere: the start without a writable cache is not checked)"; else
  run -u JAVA_HOME -u KSE_JAVA_OPTS PATH="$tmp/jdk-21/bin:$PATH" XDG_CACHE_HOME="$tmp/cache home"
  started "no writable cache folder" "$tmp/jdk-21" -Xss16m "-splash:$product/kse-splash.png"
fi
chmod 755 "$tmp/cache home"

rm "$launcher"
run JAVA_HOME="$tmp/jdk-25"
refused "no launcher" "no Equinox launcher under $product/plugins"
: > "$launcher"

real17=/usr/lib/jvm/java-17-openjdk-amd64
if [ -x "$real17/bin/java" ]; then
  run JAVA_HOME="$real17"
  refused "the real Java 17" "found Java 17 at $real17/bin/java" "JAVA_HOME is $real17"
else
  echo "   (no $real17: the check with a real Java 17 is skipped)"
fi

echo "-- the Windows start script (its text only: there is no cmd.exe here)"
cmd="$rootfiles/win32/kse-workbench.cmd"
lines=$(tr -cd '\n' < "$cmd" | wc -c)
if [ "$lines" = 0 ] || [ "$(grep -c $'\r$' "$cmd")" != "$lines" ] || [ "$(tr -cd '\r' < "$cmd" | wc -c)" != "$lines" ]; then
  fail "$cmd does not end each of its lines with CRLF (cmd.exe misreads labels and for loops with LF only)"
fi
[ "$(tail -c 2 "$cmd" | od -An -tx1 | tr -d ' \n')" = 0d0a ] || fail "the last line of $cmd has no CRLF"
echo "   ok CRLF line ends ($lines lines)"
text=$(tr -d '\r' < "$cmd")
while read -r target; do
  grep -qiE "^:$target\$" <<< "$text" || fail "$cmd goes to :$target, which it does not have"
done < <(grep -oiE 'goto :?[a-z]+' <<< "$text" | sed -E 's/goto :?//I' | sort -u | grep -vix eof)
echo "   ok every goto has its label"
if grep -nE '\($' <<< "$text"; then fail "$cmd opens a block over several lines: a path with ( ) in it would end the block"; fi
echo "   ok no block over several lines"

echo "-- the Windows archive"
windows="${1:-}"
if [ -z "$windows" ]; then
  for zip in "$here"/releng/org.kse.product/target/products/kse-workbench-*-win32.win32.x86_64.zip; do
    if [ -f "$zip" ]; then windows=$zip; fi
  done
fi
if [ -z "$windows" ]; then
  echo "   (no Windows archive built: its checks are skipped)"
  echo "start scripts: ok"
  exit 0
fi
[ -f "$windows" ] || fail "no such archive: $windows"
entries=$(unzip -Z1 "$windows")
problems=()
for entry in '^kse-workbench\.cmd$' '^kse-splash\.png$' '^plugins/org\.eclipse\.equinox\.launcher_[^/]*\.jar$' \
             '^plugins/org\.eclipse\.equinox\.launcher\.win32\.win32\.x86_64_[^/]*/eclipse_[^/]*\.dll$' \
             '^plugins/org\.eclipse\.swt\.win32\.win32\.x86_64_[^/]*\.jar$'; do
  count=$(grep -cE "$entry" <<< "$entries" || true)
  if [ "$count" = 1 ]; then echo "   has ${entry}"; else problems+=("it has $count entries ${entry}, expected one"); fi
done
if grep -qxF kse-workbench <<< "$entries"; then problems+=("it carries the Linux start script kse-workbench"); fi
if grep -qxF kse-workbench.cmd <<< "$entries"; then
  if unzip -p "$windows" kse-workbench.cmd | cmp -s - "$cmd"; then echo "   kse-workbench.cmd is the one in the source tree"
  else problems+=("its kse-workbench.cmd differs from $cmd"); fi
fi
if grep -qxF kse-splash.png <<< "$entries"; then
  if unzip -p "$windows" kse-splash.png | cmp -s - "$rootfiles/common/kse-splash.png"; then echo "   kse-splash.png is the one in the source tree"
  else problems+=("its kse-splash.png differs from $rootfiles/common/kse-splash.png"); fi
fi
if [ ${#problems[@]} -gt 0 ]; then
  echo "start-scripts: $(basename "$windows") is not right:" >&2
  printf '   %s\n' "${problems[@]}" >&2
  exit 1
fi
echo "start scripts: ok"
