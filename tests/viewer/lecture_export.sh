#!/usr/bin/env bash
# Exports a lecture under xvfb-run and checks that every slide became a PNG and a
# well-formed SVG; a lecture whose only slide is bad must exit 1 and write nothing, one with
# some bad slides writes the others and exits 1.
# With PIXELS (viewer_layout_pixels), every slide's layout.json record is checked against
# the slide rules and its PNG (slide_rules.py); with COMPARER (viewer_image_compare), every
# slide's first frame against its settled one (first_frame.sh).
# usage: lecture_export.sh XVFB_RUN VIEWER CHECKER LECTURE OUTDIR [PIXELS [COMPARER]]
set -euo pipefail
xvfb=$1 viewer=$2 checker=$3 lecture=$4 out=$5 pixels=${6:-} compare=${7:-}
rm -rf "$out"
"$xvfb" -a -s "-screen 0 1280x800x24" "$viewer" --lecture "$lecture" --export "$out/good" \
  --size 960x540 ${compare:+--export-first}
slides=$(grep -c '^slide ' "$lecture")
pngs=$(find "$out/good" -name 'slide-??.png' | wc -l)
if [[ $slides -ne $pngs ]]; then
  echo "expected $slides slides, found $pngs PNGs" >&2
  exit 1
fi
svgs=$(find "$out/good" -name 'slide-*.svg' | wc -l)
if [[ $slides -ne $svgs ]]; then
  echo "expected $slides slides, found $svgs SVGs" >&2
  exit 1
fi
for svg in "$out"/good/slide-*.svg; do
  python3 -c 'import sys, xml.dom.minidom; xml.dom.minidom.parse(sys.argv[1])' "$svg"
done
for png in "$out"/good/slide-??.png; do
  "$checker" "$png" --size 960x540 --not-uniform 0.0,0.0,1.0,1.0
done
if [[ -n $pixels ]]; then
  python3 "$(dirname "$0")/slide_rules.py" "$out/good" "$pixels"
fi
if [[ -n $compare ]]; then
  "$(dirname "$0")/first_frame.sh" "$compare" "$out/good"
fi
# a bad lecture: FILE:LINE on stderr, exit 1, no PNG
mkdir -p "$out"
printf 'slide One\nmethod polar\nwobble 3\n' >"$out/bad.lecture"
if "$xvfb" -a -s "-screen 0 1280x800x24" "$viewer" --lecture "$out/bad.lecture" \
  --export "$out/bad" 2>"$out/bad.err"; then
  echo "a bad lecture was exported" >&2
  exit 1
fi
grep -q "bad.lecture:3: unknown key 'wobble'" "$out/bad.err"
[[ ! -e $out/bad ]]
# a lecture with mistakes on two of its four slides: both reported, the good slides written
# under their own numbers, exit 1
printf 'slide A\nspray 0\nslide B\nmethd polar\nslide C\nprobe 1,2x\nslide D\nspray 0\n' \
  >"$out/mixed.lecture"
if "$xvfb" -a -s "-screen 0 1280x800x24" "$viewer" --lecture "$out/mixed.lecture" \
  --export "$out/mixed" --size 640x360 2>"$out/mixed.err"; then
  echo "a lecture with problems exited 0" >&2
  exit 1
fi
grep -q "mixed.lecture:4: unknown key 'methd'" "$out/mixed.err"
grep -q "mixed.lecture:6: probe needs" "$out/mixed.err"
[[ -e $out/mixed/slide-01.png && -e $out/mixed/slide-04.svg ]]
[[ ! -e $out/mixed/slide-02.png && ! -e $out/mixed/slide-03.png ]]
echo "$pngs slides exported (PNG and SVG); a lecture with problems: its good slides"
