// convexloc — a validated convex polygon.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "convexloc/geometry.hpp"

namespace convexloc {

// The most vertices a polygon may have (indices are 32-bit).
inline constexpr std::size_t kMaxPolygonVertices = std::size_t{1} << 31;

// A strictly convex polygon with counter-clockwise vertices: every turn is exactly a left
// turn and the boundary winds once. Immutable once built.
class ConvexPolygon {
 public:
  // Validates `points` (either orientation) and normalises them: orientation becomes
  // counter-clockwise, repeated vertices and vertices exactly on the segment joining their
  // neighbours are dropped (the region is unchanged). Throws GeometryError naming the
  // witness: a non-finite coordinate, fewer than 3 distinct vertices, all vertices collinear,
  // a boundary that doubles back or crosses itself, a reflex vertex. `lines`, when not empty,
  // gives each point's source line (same size as `points`) for the error's line().
  explicit ConvexPolygon(std::span<const Vec2> points, std::span<const std::size_t> lines = {});

  // The exact convex hull of `points` (every point inside or on it, every vertex an input
  // point, no vertex on the segment joining its neighbours), counter-clockwise, with
  // sourceIndex() giving each vertex's first index in `points` and droppedCount() the points
  // that are not vertices. Throws GeometryError for a coordinate that is not finite, fewer
  // than 3 points, or points all equal or collinear; UsageError for more than
  // kMaxPolygonVertices.
  static ConvexPolygon hullOf(std::span<const Vec2> points);

  // the vertices, counter-clockwise; edge i runs from vertex i to vertex (i + 1) % size()
  std::span<const Vec2> vertices() const noexcept { return vertices_; }
  // number of vertices, which is also the number of edges
  std::size_t size() const noexcept { return vertices_.size(); }
  // vertex i, for 0 <= i < size()
  Vec2 vertex(std::size_t i) const noexcept { return vertices_[i]; }
  // start and end of edge i
  Vec2 edgeStart(std::size_t i) const noexcept { return vertices_[i]; }
  Vec2 edgeEnd(std::size_t i) const noexcept {
    return vertices_[i + 1 == vertices_.size() ? 0 : i + 1];
  }
  // the exact bounding box of the vertices
  Box2 bounds() const noexcept { return bounds_; }
  // for each kept vertex, its index in the input
  std::span<const std::uint32_t> sourceIndex() const noexcept { return source_; }
  // how many input points normalisation dropped (repeated or collinear)
  std::size_t droppedCount() const noexcept { return dropped_; }
  // whether the input was clockwise and got reversed
  bool wasClockwise() const noexcept { return clockwise_; }
  // the signed area, in double precision (for display, never for a decision)
  double area() const noexcept;

 private:
  std::vector<Vec2> vertices_;
  std::vector<std::uint32_t> source_;
  Box2 bounds_{};
  std::size_t dropped_ = 0;
  bool clockwise_ = false;
};

}  // namespace convexloc
