// convexloc (internal) — the cube map of a polyhedron's dual, proposing a plane's extreme
// vertices in O(1). The argument heads plane_dual.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "convexloc/geometry.hpp"
#include "convexloc/locate3d.hpp"
#include "convexloc/polyhedron.hpp"
#include "convexloc/table.hpp"
#include "intersect/graph3d.hpp"

namespace convexloc::detail {

// A cell of the direction grid: the vertex it proposes, where that vertex's star begins in
// stars(), and its degree.
struct GridCell {
  std::uint32_t vertex = 0;
  std::uint32_t star = 0;
  std::uint32_t degree = 0;
};

class DualCubemap3D {
 public:
  // builds the dual of the polyhedron (Qhull on its unit face normals, then the cube map)
  // and the direction grid with its proposals
  DualCubemap3D(const ConvexPolyhedron& polyhedron, const VertexGraph& graph);
  // The grid cells of the plane's w (G largest along it) and of -w; false when w has none
  // (the three points are collinear in doubles).
  bool cells(Vec3 q1, Vec3 q2, Vec3 q3, std::int64_t& up, std::int64_t& down) const noexcept;
  const GridCell& cell(std::int64_t c) const noexcept { return grid_[static_cast<std::size_t>(c)]; }
  // vertex v's star: v, then its neighbours in the graph's order (degree + 1 points)
  GridCell starOf(std::uint32_t v, const VertexGraph& graph) const noexcept {
    return {v, graph.offsets[v] + v, graph.offsets[v + 1] - graph.offsets[v]};
  }
  const Vec3* star(const GridCell& c) const noexcept { return stars_.data() + c.star; }
  // start loading cell c, or the star a cell proposes
  void prefetch(std::int64_t c) const noexcept { __builtin_prefetch(grid_.data() + c); }
  void prefetchStar(const GridCell& c) const noexcept {
    const std::uintptr_t first = reinterpret_cast<std::uintptr_t>(stars_.data() + c.star);
    const std::uintptr_t end = first + (c.degree + 1) * sizeof(Vec3);
    for (std::uintptr_t line = first & ~std::uintptr_t{63}; line < end; line += 64)
      __builtin_prefetch(reinterpret_cast<const void*>(line));
  }
  // the unit direction w along which the plane's G grows (zero for collinear points)
  static Vec3 aim(Vec3 q1, Vec3 q2, Vec3 q3) noexcept;
  // how many faces the cube-map cells of the plane's w and -w list (for the trace)
  bool listed(Vec3 q1, Vec3 q2, Vec3 q3, std::uint32_t& largest,
              std::uint32_t& smallest) const noexcept;
  // the cube map of the dual polyhedron; none when the dual could not be built
  const CubemapLocator* locator() const noexcept { return cube_ ? &*cube_ : nullptr; }
  std::size_t dualVertices() const noexcept { return dualVertices_; }
  std::size_t dualFaces() const noexcept { return dualFaces_; }
  // the direction grid's cells per side on each cube face
  std::uint32_t gridSide() const noexcept { return side_; }
  // per face of the dual, the vertex of P farthest along its middle direction (the face of
  // P* that vertex is): what the viewer's dual view names; empty without a dual
  const std::vector<std::uint32_t>& labels() const noexcept { return labels_; }
  std::size_t bytes() const noexcept;

 private:
  std::optional<CubemapLocator> cube_;
  Table<GridCell> grid_;  // 6 side^2 cells, cube face by cube face, row by row
  Table<Vec3> stars_;     // every vertex's star, in vertex order
  std::uint32_t side_ = 1;
  std::size_t dualVertices_ = 0;
  std::size_t dualFaces_ = 0;
  std::vector<std::uint32_t> labels_;  // per dual face: the vertex farthest along its middle
};

}  // namespace convexloc::detail
