#!/usr/bin/env bash
# --why-svg without a display: measures small N-gons, writes the SVG, and the SVG closes
# and holds one series polyline per curve (5 methods twice, the paper's polar, 3 memory);
# the 3D page beside it (x-3d.svg) 3 methods three times (tests, time, memory).
# usage: why_svg.sh VIEWER SVG
set -euo pipefail
viewer=$1 svg=$2
solid=${svg%.svg}-3d.svg
rm -f "$svg" "$solid"
env -u DISPLAY "$viewer" --why-svg "$svg" --why-max 512 --theme light
tail -n 1 "$svg" | grep -qx '</svg>'
count=$(grep -c '<polyline class="series"' "$svg")
[[ $count -eq 14 ]] || { echo "expected 14 series polylines, found $count"; exit 1; }
tail -n 1 "$solid" | grep -qx '</svg>'
count3=$(grep -c '<polyline class="series"' "$solid")
[[ $count3 -eq 9 ]] || { echo "expected 9 series polylines in 3D, found $count3"; exit 1; }
echo "why-svg: $count series, $count3 in 3D"
