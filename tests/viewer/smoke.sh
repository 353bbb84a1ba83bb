#!/usr/bin/env bash
# Runs the viewer under xvfb-run to write a PNG, then checks the PNG.
# usage: smoke.sh XVFB_RUN VIEWER CHECKER PNG [viewer args...] -- [checker args...]
set -euo pipefail
xvfb=$1 viewer=$2 checker=$3 png=$4
shift 4
viewer_args=()
while [[ $# -gt 0 && $1 != "--" ]]; do
  viewer_args+=("$1")
  shift
done
[[ $# -gt 0 ]] && shift
rm -f "$png"
"$xvfb" -a -s "-screen 0 1280x800x24" "$viewer" "${viewer_args[@]}"
exec "$checker" "$png" "$@"
