#!/usr/bin/env bash
# No transient frames: a slide's layout and camera are final on the first frame drawn after
# it is shown. An export made with --export-first (which shows each slide where PageDown
# would: before the frame's text size, fit and layout) holds each slide's first frame,
# slide-NN-first.png, beside its settled one; the two must be alike pixel for pixel (RMSE at
# most 0.001) on every slide but Why O(1)'s, whose plots fill in as their records load.
# usage: first_frame.sh COMPARER DIR
set -euo pipefail
compare=$1 dir=$2
# the slides drawn as figures (layout.json's kind), not Why O(1)'s plots
slides=$(python3 -c '
import json, sys
print(" ".join(str(s["slide"]) for s in json.load(open(sys.argv[1]))["slides"]
               if s["kind"] != "plots"))' "$dir/layout.json")
status=0 checked=0
for k in $slides; do
  name=$(printf 'slide-%02d' "$k")
  if [[ ! -f $dir/$name-first.png ]]; then
    echo "$dir: no first frame for slide $k" >&2
    status=1
    continue
  fi
  if ! "$compare" "$dir/$name-first.png" "$dir/$name.png" --max-rmse 0.001 >"$dir/first.txt"; then
    echo "$dir: slide $k's first frame is not its settled frame: $(cat "$dir/first.txt")" >&2
    status=1
  fi
  checked=$((checked + 1))
done
echo "$dir: $checked slides' first frames are their settled frames"
exit $status
