# Sourced by the scripts that start a workbench: start_virtual_display LOG starts Xvfb on a free
# display, sets $display and $xvfb (its pid; the caller kills it on exit) and returns once the
# display answers, or fails after 10 s.
start_virtual_display() {
  local log="$1" number
  for _ in 1 2 3 4 5; do
    number=$(( 100 + RANDOM % 800 ))
    [ -e "/tmp/.X11-unix/X$number" ] || [ -e "/tmp/.X$number-lock" ] || break
  done
  display=":$number"
  Xvfb "$display" -screen 0 1280x800x24 -nolisten tcp > "$log" 2>&1 &
  xvfb=$!
  for _ in $(seq 1 100); do
    DISPLAY="$display" xwininfo -root > /dev/null 2>&1 && return 0
    kill -0 $xvfb 2>/dev/null || break
    sleep 0.1
  done
  cat "$log" >&2
  echo "no virtual display $display (Xvfb did not start)" >&2
  return 1
}
