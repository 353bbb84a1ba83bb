#!/usr/bin/env python3
"""Checks the slide rules from an export's layout.json and against its PNGs.

usage: slide_rules.py DIR PIXELS_TOOL [BACKGROUND]

For every slide in DIR/layout.json (written by convexloc-viewer --export):
  - no box overlaps another (the shape lies inside the figure, the inset beside the shape);
  - the smallest text is at least 2.2% of the page height;
  - a figure slide's figure room is at least 55% of the page, and its shape's drawn box is
    inside the room and at least 80% of the room's width or height;
  - a 3D query's x_T and x are at least 5% of the page width apart, the hit face's middle
    inside the figure room;
  - against DIR/slide-NN.png (viewer_layout_pixels): the page outside every box is the
    background, and each side of the shape's box touches the drawing.
Prints every broken rule and exits 1 when there is one.
"""
import json
import struct
import subprocess
import sys


def overlap(a, b):
    """the area two [x, y, w, h] boxes share"""
    w = min(a[0] + a[2], b[0] + b[2]) - max(a[0], b[0])
    h = min(a[1] + a[3], b[1] + b[3]) - max(a[1], b[1])
    return max(w, 0) * max(h, 0)


def inside(inner, outer, slack=1.0):
    return (inner[0] >= outer[0] - slack and inner[1] >= outer[1] - slack
            and inner[0] + inner[2] <= outer[0] + outer[2] + slack
            and inner[1] + inner[3] <= outer[1] + outer[3] + slack)


def point_in(p, box):
    return box[0] <= p[0] <= box[0] + box[2] and box[1] <= p[1] <= box[1] + box[3]


def layout_rules(s):
    """the broken rules of one slide's record"""
    bad = []
    W, H = s["page"]
    boxes = s["boxes"]
    names = [n for n in boxes if n != "shape"]
    for i, a in enumerate(names):
        for b in names[i + 1:]:
            # the inset is drawn inside the figure room, beside the shape
            if {a, b} == {"inset", "figure"}:
                continue
            if overlap(boxes[a], boxes[b]) > 1.0:
                bad.append(f"{a} {boxes[a]} overlaps {b} {boxes[b]}")
    if "inset" in boxes and "shape" in boxes and overlap(boxes["inset"], boxes["shape"]) > 1.0:
        bad.append(f"inset {boxes['inset']} overlaps the shape {boxes['shape']}")
    if s["min_text_px"] < 0.022 * H - 1e-9:
        bad.append(f"text {s['min_text_px']} px < 2.2% of {H}")
    if s["kind"] == "plots":
        # Why O(1)'s plots: the figure room, no scene in it
        fig = boxes.get("figure")
        if not fig:
            return bad + ["a plots slide without a figure box"]
        if fig[2] * fig[3] < 0.55 * W * H:
            bad.append(f"figure room {fig} is {fig[2] * fig[3] / (W * H):.0%} of the page")
        if "shape" in boxes:
            bad.append("a plots slide with a shape box (a scene drawn under its plots)")
    if s["kind"] in ("figure2d", "figure3d"):
        fig = boxes.get("figure")
        shape = boxes.get("shape")
        if not fig or not shape:
            return bad + ["a figure slide without a figure or a shape box"]
        if fig[2] * fig[3] < 0.55 * W * H:
            bad.append(f"figure room {fig} is {fig[2] * fig[3] / (W * H):.0%} of the page")
        if not inside(shape, fig, 2.0):
            bad.append(f"shape {shape} outside the figure room {fig}")
        if shape[2] < 0.8 * fig[2] and shape[3] < 0.8 * fig[3]:
            bad.append(f"shape {shape} fills {shape[2] / fig[2]:.0%} x {shape[3] / fig[3]:.0%}"
                       f" of the figure room {fig}")
    q = s.get("query3d")
    if q:
        gap = ((q["x_T"][0] - q["x"][0]) ** 2 + (q["x_T"][1] - q["x"][1]) ** 2) ** 0.5
        if gap < 0.05 * W:
            bad.append(f"x_T and x {gap:.1f} px apart (< 5% of {W})")
        if not point_in(q["hit_face"], boxes.get("figure", [0, 0, 0, 0])):
            bad.append(f"hit face {q['hit_face']} outside the figure room")
    return bad


def pixel_rules(s, png, tool, background, offset):
    """the broken rules of one slide's picture (boxes moved by the page's `offset`)"""
    args = [tool, png, "--background", background]
    for name, b in s["boxes"].items():
        if name == "shape":
            continue
        # a pixel to spare: a line along a box's edge is anti-aliased across it
        args += ["--allow", ",".join(str(v) for v in (b[0] + offset[0] - 1, b[1] + offset[1] - 1,
                                                       b[2] + 2, b[3] + 2))]
    if "shape" in s["boxes"]:
        b = s["boxes"]["shape"]
        args += ["--shape", ",".join(str(v) for v in (b[0] + offset[0], b[1] + offset[1],
                                                       b[2], b[3]))]
    out = subprocess.run(args, capture_output=True, text=True, check=True).stdout.split("\n")
    bad = []
    stray = out[0].split()
    if int(stray[1]) > 0:
        bad.append(f"{stray[1]} pixels drawn outside every box (the first at {stray[2]}, "
                   f"{stray[3]})")
    if len(out) > 1 and out[1].startswith("shape"):
        sides = [int(v) for v in out[1].split()[1:]]
        for side, n in zip(("left", "top", "right", "bottom"), sides):
            if n == 0:
                bad.append(f"nothing drawn along the shape box's {side} side")
    return bad


def main():
    folder, tool = sys.argv[1], sys.argv[2]
    background = sys.argv[3] if len(sys.argv) > 3 else "fbfbfa"
    with open(f"{folder}/layout.json", encoding="utf-8") as f:
        slides = json.load(f)["slides"]
    failures = 0
    for s in slides:
        png = f"{folder}/slide-{s['slide']:02d}.png"
        # the page centred in the picture (letterboxed where their aspects differ)
        with open(png, "rb") as f:
            w, h = struct.unpack(">II", f.read(24)[16:24])
        s["offset"] = [(w - s["page"][0]) / 2, (h - s["page"][1]) / 2]
        bad = layout_rules(s) + pixel_rules(s, png, tool, background, s.get("offset", [0, 0]))
        for b in bad:
            print(f"{folder} slide {s['slide']} ({s['kind']}, {s['page'][0]}x{s['page'][1]}): {b}")
        failures += len(bad)
    print(f"{folder}: {len(slides)} slides checked, {failures} rules broken")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
