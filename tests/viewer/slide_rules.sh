#!/usr/bin/env bash
# The slide rules (docs/viewer.md, "Lectures") from --export's layout.json and the PNGs
# (slide_rules.py): no box over another, text at least 2.2% of the page's height, the figure
# room at least 56% of the page with the figure filling 80% of its width or height, a 3D
# query's x_T and x apart, the page outside every box bare. The first slide and those named
# after the lecture (one of each layout: a Steps
# window, a long legend, 3D figures with and without a query, the dual views, the split
# view, the zoom insets, Why O(1)'s plots) at 1280x720, 1280x800, 1920x1080 and 3840x2160,
# and at 1280x720 with --font-scale 0.75, 1.5 and 2. A lecture
# exported whole has each slide's SVG, rendered by rsvg-convert, within RMSE 0.05 of its PNG,
# and each slide's first frame alike to its settled one (first_frame.sh).
# usage: slide_rules.sh XVFB_RUN VIEWER PIXELS COMPARER OUTDIR LECTURE:SLIDES[:whole]...
set -euo pipefail
xvfb=$1 viewer=$2 pixels=$3 compare=$4 out=$5
shift 5
here=$(cd "$(dirname "$0")" && pwd)
# under the sanitizers (scripts/test.sh sets CONVEXLOC_HOSTILE_SCALE below 1) the same code at
# fewer sizes: the smallest and the largest page, the largest text
sizes="1280x720 1280x800 1920x1080 3840x2160" scales="0.75 1.5 2"
if awk -v s="${CONVEXLOC_HOSTILE_SCALE:-1}" 'BEGIN { exit !(s < 1) }'; then
  sizes="1280x720 3840x2160" scales="2"
fi
rm -rf "$out"
mkdir -p "$out"
status=0
export_at() {  # LECTURE SIZE DIR [OPTIONS...]
  local lecture=$1 size=$2 dir=$3
  shift 3
  "$xvfb" -a -s "-screen 0 3860x2180x24" "$viewer" --lecture "$lecture" --export "$dir" \
    --size "$size" "$@" >"$dir.log" 2>&1 || { cat "$dir.log"; status=1; }
  python3 "$here/slide_rules.py" "$dir" "$pixels" || status=1
}
for spec in "$@"; do
  # LECTURE:SLIDES[:whole]: whole exports every slide at 1280x720 too (the others are
  # checked whole where they are exported already, by lecture_export.sh at 960x540)
  lecture=${spec%%:*} keep=${spec#*:} whole=
  if [[ $keep == *:whole ]]; then keep=${keep%:whole} whole=1; fi
  name=$(basename "$lecture" .lecture)
  if [[ -n $whole ]]; then
    export_at "$lecture" 1280x720 "$out/$name-720" --export-first
    "$here/first_frame.sh" "$compare" "$out/$name-720" || status=1
    for svg in "$out/$name-720"/slide-*.svg; do
      rsvg-convert "$svg" -o "$svg.png"
      "$compare" "$svg.png" "${svg%.svg}.png" --max-rmse 0.05 || status=1
    done
  fi
  # the subset as a lecture of its own (shape paths made absolute)
  dir=$(cd "$(dirname "$lecture")" && pwd)
  awk -v keep=" 1 $keep " -v dir="$dir" '
    /^slide / { n++; on = index(keep, " " n " ") > 0 }
    on && /^(shape|why-from) / && $2 !~ /^\// { print $1 " " dir "/" $2; next }
    on { print }' "$lecture" >"$out/$name-subset.lecture"
  for size in $sizes; do
    export_at "$out/$name-subset.lecture" "$size" "$out/$name-$size"
  done
  for scale in $scales; do
    export_at "$out/$name-subset.lecture" 1280x720 "$out/$name-font$scale" --font-scale "$scale"
  done
done
exit $status
