#!/usr/bin/env bash
# Runs a command on an Xvfb server of its own. The server picks a free display itself
# (-displayfd), so any number of these run at once: xvfb-run -a can hand the same display to
# two tests started together, which is why the smoke tests once ran one at a time.
# usage: xvfb_display.sh [-a] [-s "SERVER ARGS"] COMMAND [ARGS...]   (xvfb-run's options)
set -euo pipefail
server_args="-screen 0 1280x800x24"
while [[ $# -gt 0 ]]; do
  case $1 in
    -a) shift ;;
    -s) server_args=$2; shift 2 ;;
    *) break ;;
  esac
done
if [[ $# -eq 0 ]]; then
  echo "usage: xvfb_display.sh [-a] [-s \"SERVER ARGS\"] COMMAND [ARGS...]" >&2
  exit 2
fi

number=$(mktemp)
log=$(mktemp)
# shellcheck disable=SC2086 # the server's arguments are words, as xvfb-run takes them
Xvfb -displayfd 3 -nolisten tcp $server_args 3>"$number" 2>"$log" &
server=$!
stop() {
  kill "$server" 2>/dev/null || true
  wait "$server" 2>/dev/null || true
  rm -f "$number" "$log"
}
trap stop EXIT

# the server writes its display number once it accepts clients
for _ in $(seq 200); do
  if grep -q '^[0-9][0-9]*$' "$number"; then break; fi
  if ! kill -0 "$server" 2>/dev/null; then
    echo "xvfb_display.sh: Xvfb did not start:" >&2
    cat "$log" >&2
    exit 1
  fi
  sleep 0.05
done
if ! grep -q '^[0-9][0-9]*$' "$number"; then
  echo "xvfb_display.sh: Xvfb gave no display number within 10 s" >&2
  exit 1
fi

status=0
DISPLAY=":$(head -n 1 "$number")" "$@" || status=$?
exit "$status"
