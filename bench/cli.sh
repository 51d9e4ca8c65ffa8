#!/usr/bin/env bash
# Command line benchmark: what a user or a build waits for, a whole `kse` process from start to
# exit, on the Goalie. The kse launcher (a plain class path with the JVM's ahead-of-time cache,
# ADR 0023) against the same commands started as the Equinox application of the headless
# product, its baseline, run in turn (A B A B ...) in the same run; and three models validated
# in one call against three calls. Prints the median wall and CPU seconds and the ratios.
#   usage: bench/cli.sh [runs]   (default 7)
set -euo pipefail
here="$(cd "$(dirname "$0")/.." && pwd)"
runs="${1:-7}"
java_home="${JAVA_HOME:-/usr/lib/jvm/temurin-25-jdk-amd64}"
launcher="$here/releng/org.kse.cli.dist/target/kse/bin/kse"
product="$here/releng/org.kse.product/target/products/org.kse.cli.product/linux/gtk/x86_64"
if [ ! -x "$launcher" ] || [ ! -d "$product/plugins" ]; then
  (cd "$here" && JAVA_HOME="$java_home" ./mvnw -B -q install -DskipTests >&2)
fi
equinox=$(ls "$product"/plugins/org.eclipse.equinox.launcher_*.jar | head -n 1)
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT
cp "$here"/examples/{Goalie/Goalie,Attacker/Attacker,Defender/Defender}.stct "$scratch/"
"$launcher" generate -q "$scratch/Goalie.stct" -o "$scratch/src" > /dev/null

old() {
  "$java_home/bin/java" -Xss16m --sun-misc-unsafe-memory-access=allow \
    -Dlog4j.configuration="file:$here/releng/log4j.properties" -Dlog4j2.configurationFile="file:$here/releng/log4j2.properties" \
    -jar "$equinox" -nosplash "$@"
}
new() { "$launcher" "$@"; }
three_calls() { for model in Goalie Attacker Defender; do "$launcher" validate "$scratch/$model.stct"; done; }
one_call() { "$launcher" validate "$scratch"/{Goalie,Attacker,Defender}.stct; }

# one timed run: appends "wall user+sys" to a file
timed() { # file, command...
  local file="$1"; shift
  local TIMEFORMAT='%R %U %S'
  { time "$@" > /dev/null 2>&1; } 2>> "$file"
}
median() { # file, column expression
  awk "{print $2}" "$1" | sort -n | awk '{v[NR]=$1} END {print (NR % 2) ? v[(NR+1)/2] : (v[NR/2]+v[NR/2+1])/2}'
}
report() { # name, A file, B file, A name, B name
  local aw ac bw bc
  aw=$(median "$2" '$1'); ac=$(median "$2" '$2+$3'); bw=$(median "$3" '$1'); bc=$(median "$3" '$2+$3')
  printf '  %-34s %-10s %6.3f s wall %6.3f s CPU | %-10s %6.3f s wall %6.3f s CPU | ratio %.2f wall %.2f CPU\n' \
    "$1" "$4" "$aw" "$ac" "$5" "$bw" "$bc" "$(echo "$aw / $bw" | bc -l)" "$(echo "$ac / $bc" | bc -l)"
}

echo "kse command line benchmark: whole processes on the Goalie, median of $runs runs in turn ($(nproc) cores)"
for spec in "version|version" "validate Goalie|validate $scratch/Goalie.stct" \
    "generate Goalie (nothing changes)|generate -q $scratch/Goalie.stct -o $scratch/src" \
    "diagram Goalie|diagram $scratch/Goalie.stct -o $scratch/Goalie.svg"; do
  name="${spec%%|*}"; read -r -a args <<< "${spec#*|}"
  : > "$scratch/a"; : > "$scratch/b"
  new "${args[@]}" > /dev/null 2>&1; old "${args[@]}" > /dev/null 2>&1   # warm the file cache
  for _ in $(seq "$runs"); do timed "$scratch/a" new "${args[@]}"; timed "$scratch/b" old "${args[@]}"; done
  report "$name" "$scratch/a" "$scratch/b" launcher Equinox
done
: > "$scratch/a"; : > "$scratch/b"
for _ in $(seq "$runs"); do timed "$scratch/a" one_call; timed "$scratch/b" three_calls; done
report "validate 3 models" "$scratch/a" "$scratch/b" "one call" "3 calls"
