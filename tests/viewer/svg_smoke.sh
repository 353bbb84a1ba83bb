#!/usr/bin/env bash
# Runs the viewer under xvfb-run to write an SVG (--svg), then checks it with Python's XML
# parser: well-formed, an <svg> root with the window's viewBox, one edge line per polygon
# edge, at least one cell polygon, labels, and the escaped caption.
# usage: svg_smoke.sh XVFB_RUN VIEWER SVG EDGES [viewer args...]
set -euo pipefail
xvfb=$1 viewer=$2 svg=$3 edges=$4
shift 4
rm -f "$svg"
"$xvfb" -a -s "-screen 0 1280x800x24" "$viewer" "$@" --svg "$svg" --size 1024x768 \
  --caption 'edges & cells <as core reports them>'
python3 - "$svg" "$edges" <<'PY'
import sys
import xml.etree.ElementTree as ET
path, edges = sys.argv[1], int(sys.argv[2])
root = ET.parse(path).getroot()  # raises on malformed XML
ns = "{http://www.w3.org/2000/svg}"
assert root.tag == ns + "svg", root.tag
assert root.get("viewBox") == "0 0 1024.00 768.00", root.get("viewBox")
def count(tag, cls):
    return sum(1 for e in root.iter(ns + tag) if e.get("class") == cls)
assert count("line", "edge") == edges, ("edge lines", count("line", "edge"), edges)
assert count("polygon", "cell") > 0, "no cell polygons"
assert count("text", "label") > 0, "no labels"
captions = ["".join(e.itertext()) for e in root.iter(ns + "text") if e.get("class") == "caption"]
assert captions == ["edges & cells <as core reports them>"], captions
print(f"{path}: well-formed, {edges} edges, {count('polygon', 'cell')} cells, "
      f"{count('text', 'label')} labels")
PY
