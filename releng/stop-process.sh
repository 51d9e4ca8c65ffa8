# Sourced by the scripts that start a workbench or an Eclipse and end it themselves.
# stop_process PID: SIGTERM, 10 s to exit, then SIGKILL, and reaps it. An Eclipse can hang in
# its shutdown (seen under load: the JVM no longer answered even a thread dump), and a plain
# `kill; wait` then waits for ever.
stop_process() {
  local pid="$1"
  [ -n "$pid" ] || return 0
  kill "$pid" 2>/dev/null || true
  for _ in $(seq 1 100); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
  kill -9 "$pid" 2>/dev/null || true
  wait "$pid" 2>/dev/null || true
}
