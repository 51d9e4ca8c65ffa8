#!/usr/bin/env bash
# End-to-end tests of the diagram editor page: starts the diagram server on a temporary folder
# (a copy of examples/Goalie), runs tests/*.test.mjs with `node --test` in headless Chromium
# (Debian's /usr/bin/chromium, or $CHROMIUM), and stops the server. Screenshots of every step go
# to target/screenshots/ (emptied when tests run, not for a --script), the server's output to
# target/server.log.
#
# The server is started like /tmp/kse-serve-ready does it:
#   <repository>/kse serve <folder> --pages <repository>/bundles/org.kse.diagram.client/dist
# Another start command can be given as KSE_SERVE_COMMAND: a script that takes the folder as $1
# and prints the page URL (with the token), e.g. KSE_SERVE_COMMAND=/tmp/kse-serve-ready.
# Arguments are passed to node --test (e.g. --test-name-pattern=undo); test files given run alone.
set -euo pipefail

here="$(cd "$(dirname "$(readlink -f "${BASH_SOURCE[0]}")")" && pwd)"
repository="$(cd "$here/../.." && pwd)"
client="$repository/bundles/org.kse.diagram.client"
cd "$here"

if [ ! -x "${CHROMIUM:-/usr/bin/chromium}" ]; then
  echo "run.sh: needs Chromium at ${CHROMIUM:-/usr/bin/chromium} (Debian: apt-get install -y chromium)" >&2
  exit 2
fi
if [ ! -f "$client/dist/index.html" ]; then
  echo "run.sh: building the diagram client first" >&2
  (cd "$client" && npm ci --no-audit --no-fund && npm run build)
fi

# installed once per lock file: `npm ci` empties node_modules first, under any run going on beside
if [ ! -f node_modules/.package-lock.json ] || [ package-lock.json -nt node_modules/.package-lock.json ]; then
  npm ci --no-audit --no-fund
fi

mkdir -p target
# a test run starts with no screenshots but its own; a --script run (a benchmark, which takes none)
# keeps those of the run before it (test.sh runs the benchmarks right after the suite)
if [ "${1:-}" != --script ]; then
  rm -rf target/screenshots target/downloads
fi
folder="$(mktemp -d "${TMPDIR:-/tmp}/kse-e2e-models.XXXXXX")"
cp "$repository/examples/Goalie/Goalie.stct" "$folder/"

# KSE_E2E_SERVER_LOG: elsewhere, so that runs in one checkout do not read each other's URL
log="${KSE_E2E_SERVER_LOG:-$here/target/server.log}"
export KSE_E2E_SERVER_LOG="$log"
if [ -n "${KSE_SERVE_COMMAND:-}" ]; then
  setsid bash "$KSE_SERVE_COMMAND" "$folder" >"$log" 2>&1 &
else
  setsid "$repository/kse" serve "$folder" --pages "$client/dist" >"$log" 2>&1 &
fi
server=$!

stop() {
  kill -TERM -- "-$server" 2>/dev/null || true
  for _ in $(seq 1 50); do
    kill -0 "$server" 2>/dev/null || break
    sleep 0.2
  done
  kill -KILL -- "-$server" 2>/dev/null || true
  rm -rf "$folder"
}
trap stop EXIT

url=""
for _ in $(seq 1 600); do
  url="$(grep -o 'http://127\.0\.0\.1:[0-9]*/?token=[^ ]*' "$log" | head -n 1 || true)"
  [ -n "$url" ] && break
  if ! kill -0 "$server" 2>/dev/null; then
    echo "run.sh: the diagram server stopped:" >&2
    cat "$log" >&2
    exit 1
  fi
  sleep 0.5
done
if [ -z "$url" ]; then
  echo "run.sh: the diagram server printed no page URL within 5 minutes:" >&2
  cat "$log" >&2
  exit 1
fi
echo "run.sh: diagram server at ${url%%\?*}, serving $folder"

export KSE_E2E_URL="$url"
export KSE_E2E_FOLDER="$folder"
# Test files given (tests/NN-name.test.mjs) run alone; `--script FILE` runs a plain node script
# (a benchmark) against the server instead; other arguments go to node --test.
if [ "${1:-}" = --script ]; then
  node "${@:2}"
  exit
fi
options=()
files=()
for argument in "$@"; do
  case "$argument" in
    *.mjs) files+=("$argument") ;;
    *) options+=("$argument") ;;
  esac
done
[ ${#files[@]} -gt 0 ] || files=(tests/*.test.mjs)
status=0
node --test --test-concurrency=1 --test-timeout=180000 "${options[@]}" "${files[@]}" || status=$?
# whatever the tests did, the server answered in messages: a stack trace in its log is a failure
if grep -n -E -e '^[[:space:]]+at [[:alnum:]_$.]+\(' -e '(Exception|Error)(: |$)' "$log" >"$here/target/server-traces.txt"; then
  echo "run.sh: the diagram server logged stack traces or exceptions (target/server-traces.txt):" >&2
  head -n 20 "$here/target/server-traces.txt" >&2
  status=1
fi
exit "$status"
