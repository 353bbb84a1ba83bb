#!/usr/bin/env bash
# A lecture reads the same at any size, and each slide's SVG shows what its PNG shows:
#  - the lecture exported at 1920x1080 and at 1280x720 (every slide), and a few slides at
#    3840x2160 (the first, whose look is the lecture's, and those listed in SLIDES_4K: the
#    4K export takes a minute for the whole lecture on two cores); each slide compared with
#    its 1920x1080 export after both are resampled to 480x270;
#  - every 1920x1080 SVG rendered by rsvg-convert and compared with its PNG at full size:
#    RMSE at most 0.05 (Why O(1)'s plots too: a slide draws them without a window);
#  - every SVG holds the slide's title and its whole caption (the lecture's `caption` key),
#    and a large-offset slide its digits ("at 10^9 from the origin: vertex 0 is ...").
# usage: lecture_sizes.sh XVFB_RUN VIEWER COMPARER LECTURE OUTDIR
set -euo pipefail
xvfb=$1 viewer=$2 compare=$3 lecture=$4 out=$5
SLIDES_4K=${SLIDES_4K:-"4 16 18 23"}
rm -rf "$out"
mkdir -p "$out"
export_at() {  # LECTURE SIZE DIR
  "$xvfb" -a -s "-screen 0 3860x2180x24" "$viewer" --lecture "$1" --export "$3" --size "$2" \
    >"$3.log"
}
export_at "$lecture" 1920x1080 "$out/1080"
# under the sanitizers (scripts/test.sh sets CONVEXLOC_HOSTILE_SCALE below 1) the 1080p
# export's own checks only: the same code draws the other sizes
sanitized=
if awk -v s="${CONVEXLOC_HOSTILE_SCALE:-1}" 'BEGIN { exit !(s < 1) }'; then sanitized=1; fi
[[ -n $sanitized ]] || export_at "$lecture" 1280x720 "$out/720"

# the 4K subset: slide 1 and the chosen slides, as a lecture of their own (shape and timing
# file paths made absolute, since the subset lies elsewhere)
dir=$(cd "$(dirname "$lecture")" && pwd)
awk -v keep=" 1 $SLIDES_4K " -v dir="$dir" '
  /^slide / { n++; on = index(keep, " " n " ") > 0; if (on) print "# slide " n }
  on && /^(shape|why-from) / && $2 !~ /^\// { print $1 " " dir "/" $2; next }
  on { print }' "$lecture" >"$out/subset.lecture"
[[ -n $sanitized ]] || export_at "$out/subset.lecture" 3840x2160 "$out/4k"

status=0
k=0
for n in 1 $SLIDES_4K; do
  [[ -z $sanitized ]] || break
  k=$((k + 1))
  "$compare" "$(printf '%s/4k/slide-%02d.png' "$out" "$k")" \
    "$(printf '%s/1080/slide-%02d.png' "$out" "$n")" --max-mean 6 || status=1
done
for png in "$out"/1080/slide-*.png; do
  name=$(basename "$png" .png)
  [[ -n $sanitized ]] || "$compare" "$out/720/$name.png" "$png" --max-mean 7 || status=1
  rsvg-convert "$out/1080/$name.svg" -o "$out/1080/$name.svg.png"
  "$compare" "$out/1080/$name.svg.png" "$png" --max-rmse 0.05 || status=1
done

# every SVG: its title card holds the slide's title, its caption box the whole caption
python3 - "$lecture" "$out/1080" <<'PY' || status=1
import sys, xml.etree.ElementTree as ET
lecture, folder = sys.argv[1], sys.argv[2]
slides = []
for line in open(lecture, encoding="utf-8"):
    line = line.rstrip("\n")
    if line.startswith("slide "):
        slides.append({"title": line[6:].strip(), "caption": "", "far": False})
    elif line.startswith("caption ") and slides:
        slides[-1]["caption"] = line[8:].strip()
    elif line.strip() == "preset large-offset" and slides:
        slides[-1]["far"] = True
ns = "{http://www.w3.org/2000/svg}"
bad = 0
for n, s in enumerate(slides, 1):
    root = ET.parse(f"{folder}/slide-{n:02d}.svg").getroot()
    def text(cls):  # a line's words are tspans
        return " ".join(" ".join("".join(e.itertext()).split()) for e in root.iter(ns + "text")
                        if e.get("class") == cls)
    title, caption = text("title"), text("caption")
    if f"{n} / {len(slides)}: {s['title']}" not in title:
        print(f"slide {n}: the SVG's title card reads {title!r}, not the title {s['title']!r}")
        bad += 1
    if " ".join(s["caption"].split()) not in caption:
        print(f"slide {n}: the SVG's caption reads {caption!r}, not {s['caption']!r}")
        bad += 1
    # (a label over the polygon, or on a slide a box in its figure room's corner)
    if s["far"] and "from the origin: vertex 0 is (" not in text("label") + " " + text("note"):
        print(f"slide {n}: a large offset without its digits")
        bad += 1
print(f"{len(slides)} SVGs: titles and captions checked, {bad} problems")
sys.exit(1 if bad else 0)
PY
exit $status
