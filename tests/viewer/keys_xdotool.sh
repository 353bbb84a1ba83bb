#!/usr/bin/env bash
# The key queue against the real window: a five-slide lecture under Xvfb, xdotool types three
# quick PageDowns (10 ms apart, faster than a frame), then End, PageUp, B and PageDown (which
# only brings the blanked slide back). The viewer prints each slide's notes on stdout as it
# is shown: the slides seen must be 1, 2, 3, 4, then 5, 4, and nothing after the blank. N
# opens the notes' own window and closes it again.
# usage: keys_xdotool.sh VIEWER OUTDIR   (run under xvfb-run)
set -euo pipefail
viewer=$1 out=$2
rm -rf "$out"
mkdir -p "$out"
lecture=$out/keys.lecture
for k in 1 2 3 4 5; do printf 'slide S%s\nnotes n%s\nspray 0\n' "$k" "$k"; done >"$lecture"
"$viewer" --lecture "$lecture" --size 640x360 >"$out/stdout.txt" 2>"$out/stderr.txt" &
pid=$!
trap 'kill "$pid" 2>/dev/null || true' EXIT
window=$(xdotool search --sync --onlyvisible --name convexloc | head -n 1)
xdotool windowfocus --sync "$window" 2>/dev/null || true
sleep 2  # the first frames
xdotool key --delay 10 Next Next Next
sleep 2
xdotool key --delay 10 End Prior
sleep 2
xdotool key --delay 10 b Next
sleep 2
# N opens the speaker notes in a window of their own; N again closes it
xdotool key n
sleep 2
xdotool search --name "speaker notes" >/dev/null || { echo "N opened no notes window" >&2; exit 1; }
xdotool key n
sleep 2
if xdotool search --name "speaker notes" >/dev/null; then
  echo "the notes window stayed open after a second N" >&2
  exit 1
fi
kill -0 "$pid"  # still running
seen=$(grep -o '^--- [0-9]*' "$out/stdout.txt" | cut -d' ' -f2 | tr '\n' ' ')
if [[ $seen != "1 2 3 4 5 4 " ]]; then
  echo "slides shown: '$seen', expected '1 2 3 4 5 4 '" >&2
  cat "$out/stderr.txt" >&2
  exit 1
fi
echo "keys: slides $seen"
