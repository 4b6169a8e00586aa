#!/usr/bin/env bash
# Runs a program with DISPLAY set to a private virtual X server (Xvfb, Debian package xvfb), and
# stops the server afterwards. Xvfb picks a free display itself (-displayfd), so parallel and
# back-to-back runs never race for a display number as `xvfb-run -a` can; -noreset keeps the
# server up between the test's own short connections (an X server resets when its last client
# leaves, and refuses connections meanwhile).
#   run_under_xvfb.sh PROGRAM [ARGS...]
set -euo pipefail
xvfb="$(command -v Xvfb)"
fifo_dir="$(mktemp -d)"
trap 'rm -rf "$fifo_dir"' EXIT
display_file="$fifo_dir/display"

"$xvfb" -displayfd 3 -noreset -nolisten tcp -screen 0 1024x768x24 3>"$display_file" 2>"$fifo_dir/xvfb.log" &
server=$!
stop_server() {
  kill "$server" 2>/dev/null || true
  wait "$server" 2>/dev/null || true
  rm -rf "$fifo_dir"
}
trap stop_server EXIT

# Xvfb writes the display number once it accepts connections.
for _ in $(seq 1 100); do
  [ -s "$display_file" ] && break
  if ! kill -0 "$server" 2>/dev/null; then
    echo "Xvfb did not start:" >&2
    cat "$fifo_dir/xvfb.log" >&2
    exit 1
  fi
  sleep 0.1
done
if [ ! -s "$display_file" ]; then
  echo "Xvfb gave no display number within 10 s" >&2
  exit 1
fi
DISPLAY=":$(head -n1 "$display_file")" "$@"
