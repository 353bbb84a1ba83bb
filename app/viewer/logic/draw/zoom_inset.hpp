// convexloc-viewer — a zoom inset: edges far too short to see at the polygon's scale (the
// tiny-edges gallery shape) drawn again, magnified, in a framed square beside the polygon,
// with the magnification written over it. A drawing matter only: the inset copies the
// polygon's edges through a scale, nothing in it is decided. GL-free.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "convexloc/polygon.hpp"
#include "logic/base/colour.hpp"
#include "logic/base/draw_list.hpp"
#include "logic/view/label_layout.hpp"

namespace convexloc::viewer {

// where the inset looks and where it is drawn, in world units
struct ZoomInset {
  Box2 source;               // the square around the short edges
  Box2 frame;                // the square it is drawn in, left of the polygon's box
  double magnification = 1;  // frame size over source size: mantissa * 10^exponent
  int mantissa = 1;          // 1, 2 or 5
  int exponent = 0;
};

// The inset for a polygon with edges shorter than 10^-4 of its box's diagonal: the square
// around every such edge, magnified to about half the box's height (rounded down to 1, 2
// or 5 times a power of ten), its frame beside the box at the corner next to them; none
// when every edge is long enough to see.
std::optional<ZoomInset> tinyEdgesInset(const ConvexPolygon& polygon);

// where the leader from the source ends: the middle of the frame's side facing it
glm::dvec3 zoomLeaderEnd(const ZoomInset& inset);

// "×10^9", "×5·10^8": the magnification as the label writes it
std::string magnificationText(const ZoomInset& inset);

// where a world point of the source is drawn in the frame
Vec2 insetPoint(const ZoomInset& inset, Vec2 p);

// The frame (background, border), the polygon's edges and vertices inside the source drawn
// magnified in it, the source marked where it lies with a leader to the frame, and the
// label "zoom ×10^K" over the frame.
void drawZoomInset(const ConvexPolygon& polygon, const ZoomInset& inset, const Palette& palette,
                   DrawList& out);

// For a polygon farther from the origin than 10^6 times its size (the large-offset gallery
// shape), what its digits are: "at 10^9 from the origin: vertex 0 is (1000000000.25, ...)",
// the vertex's exact doubles in their shortest digits, the offset's power of ten rounded;
// none for a polygon near the origin.
std::optional<std::string> offsetNote(const ConvexPolygon& polygon);

// the note over the middle of the polygon's box (none where it is empty), and a ring at
// vertex 0
void drawOffsetNote(const ConvexPolygon& polygon, const std::string& note, const Palette& palette,
                    DrawList& out);

// The inset in window pixels (points (x, y, 0), y downward) in `frame`, its source drawn
// where `project` puts the world there: the frame's background and border, the polygon's
// edges and vertices in the source magnified, "zoom ×10^K" centred `textRoom` / 2 over the
// frame, and a dashed leader from the middle of the frame's side facing the source to a ring
// around it.
void drawZoomInsetOnScreen(const ConvexPolygon& polygon, const ZoomInset& inset,
                           const Palette& palette, PixelBox frame, double textRoom,
                           const std::function<std::optional<glm::dvec2>(Vec2)>& project,
                           DrawList& out);

// the zoom inset where the polygon has tiny edges and the offset note where it lies far out
// (`zoom`: both in world units, else vertex 0's ring alone: a slide draws them in its layout)
void drawDegenerateInsets(const ConvexPolygon& polygon, const Palette& palette, DrawList& out,
                          bool zoom = true);

}  // namespace convexloc::viewer
