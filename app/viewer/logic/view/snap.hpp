// convexloc-viewer — snapping a pointer position to what a lecturer aims at: a vertex, an
// edge, the centre, a grid point. A snap to a vertex gives the vertex's very doubles; a snap
// to an edge gives doubles that core's exact orient2d puts on the edge's line (inside the
// segment), or, where none is found near, the edge's nearer end. So a point snapped onto the
// boundary is classified "boundary" by the exact locators, not "inside by a hair". GL-free.
#pragma once

#include <cstddef>
#include <optional>
#include <span>

#include "convexloc/geometry.hpp"

namespace convexloc::viewer {

// what a position snapped to
enum class SnapKind { None, Vertex, Edge, Centre, Grid };

// the snapped position and what it lies on
struct Snap {
  Vec2 point{};  // the position to use (the cursor's, when kind is None)
  SnapKind kind = SnapKind::None;
  std::size_t index = 0;  // the vertex (Vertex), or the edge from vertex index (Edge)
  // a Vertex snap taken because the edge aimed at (from this vertex index) holds no double
  // near the pointer
  std::optional<std::size_t> fromEdge;
};

// what a position may snap to, in world units
struct SnapTargets {
  std::span<const Vec2> ring;       // the polygon's vertices, in order (edges between)
  std::optional<Vec2> centre;       // the polar centre, where there is one
  double gridStep = 0.0;            // the grid's spacing; 0: no grid
  std::optional<std::size_t> skip;  // a vertex that is not a target (the one dragged)
};

// "vertex", "edge", "centre", "grid" or "" (for the indicator's label)
const char* toString(SnapKind k);

// A point exactly on the segment a-b within `reach` of `p` (orient2d(a, b, q) == 0, q in the
// segment's box), nearest to p's projection among those tried: the doubles a few ulps about
// the projection and the points a + t (b - a) at dyadic t; nothing when none of them is.
// Between two generic doubles an edge often holds no double but its ends.
std::optional<Vec2> pointOnSegment(Vec2 a, Vec2 b, Vec2 p, double reach);

// The snap of the cursor `p` within `radius` (world units): the nearest vertex first, then
// the centre, then the nearest edge, then the nearest grid point; else `p` itself.
Snap snapPoint(Vec2 p, const SnapTargets& targets, double radius);

// a grid spacing of 1, 2 or 5 times a power of ten, at least `minWorld` world units
double niceGridStep(double minWorld);

}  // namespace convexloc::viewer
