// convexloc-viewer — what a screen position hits: a cell (by the outlines core reports),
// a polygon vertex, a sprayed point. Picking is a drawing matter: it uses plain double
// arithmetic and never decides whether a point is inside the shape (core does that).
#pragma once

#include <cstddef>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "convexloc/locate2d.hpp"
#include "logic/view/camera2d.hpp"

namespace convexloc::viewer {

// true when `p` lies in the closed convex counter-clockwise `outline`
bool outlineContains(std::span<const Vec2> outline, Vec2 p);

// the index (into `cells`) of the first cell whose outline holds `p`, or -1
std::ptrdiff_t pickCell(std::span<const Cell2D> cells, Vec2 p);

// the vertex nearest to the window pixel `screen` within `radiusPx`, or -1
std::ptrdiff_t pickVertex(std::span<const Vec2> vertices, const Camera2D& camera, glm::dvec2 screen,
                          double radiusPx);

// The point nearest to the window pixel `screen` within `radiusPx` among those whose class
// bit is set in `visibleMask` (bit 0 inside, 1 boundary, 2 outside), or -1.
std::ptrdiff_t pickPoint(std::span<const Vec2> points, std::span<const Location> classes,
                         unsigned visibleMask, const Camera2D& camera, glm::dvec2 screen,
                         double radiusPx);

// the bit of a class in a visibility mask
constexpr unsigned classBit(Location l) {
  return 1u << static_cast<unsigned>(l);
}
inline constexpr unsigned kAllClasses = 7u;

}  // namespace convexloc::viewer
