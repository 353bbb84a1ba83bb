// convexloc (internal) — the cube map of a polyhedron's dual, proposing a plane's extreme
// vertices in O(1). The argument heads dual_cubemap.cpp.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "convexloc/geometry.hpp"
#include "convexloc/locate3d.hpp"
#include "convexloc/polyhedron.hpp"
#include "convexloc/table.hpp"
#include "detail/bit_cast.hpp"
#include "intersect/graph3d.hpp"

namespace convexloc::detail {

// A view of one vertex's star record: the vertex and its degree, its coordinates and its
// neighbours' (in the graph's order), then where each neighbour's own record begins, so a
// climb's move reads the next record and nothing else. The vertex, its degree and its first
// neighbour (all the first comparison needs) lie in the record's first cache line.
struct StarRecord {
  const std::uint64_t* word;  // the record's first word
  std::uint32_t vertex() const noexcept { return static_cast<std::uint32_t>(word[0]); }
  std::uint32_t degree() const noexcept { return static_cast<std::uint32_t>(word[0] >> 32); }
  // the star's point k: the vertex (k = 0), then its neighbours (1 <= k <= degree)
  Vec3 point(std::uint32_t k) const noexcept {
    const std::uint64_t* p = word + 1 + 3 * k;
    return {detail::bit_cast<double>(p[0]), detail::bit_cast<double>(p[1]), detail::bit_cast<double>(p[2])};
  }
  // the record of neighbour k (1 <= k <= degree), as an index for DualCubemap3D::record()
  std::uint32_t link(std::uint32_t k) const noexcept {
    const std::uint64_t w = word[1 + 3 * (degree() + 1) + (k - 1) / 2];
    return static_cast<std::uint32_t>(k % 2 ? w : w >> 32);
  }
};

class DualCubemap3D {
 public:
  // builds the dual of the polyhedron (the exact hull of its unit face normals, then the
  // cube map) and the direction grid with its proposals
  DualCubemap3D(const ConvexPolyhedron& polyhedron, const VertexGraph& graph);
  // The grid cells of the plane's w (G largest along it) and of -w; false when w has none
  // (the three points are collinear in doubles).
  bool cells(Vec3 q1, Vec3 q2, Vec3 q3, std::int64_t& up, std::int64_t& down) const noexcept;
  // the star record grid cell c proposes: the copy the cell holds, or where it lies in the
  // records when it is too large to copy
  const std::uint64_t* cell(std::int64_t c) const noexcept {
    const std::uint64_t* w = grid_.data() + static_cast<std::size_t>(c) * kCellWords;
    if (w[0] >> 32 != kElsewhere) return w;
    return records_.data() + w[1] * kRecordWords;
  }
  // the record where a climb starts when no cell proposes (vertex 0's)
  const std::uint64_t* first() const noexcept { return records_.data(); }
  // record r, as a link gives it
  const std::uint64_t* record(std::uint32_t r) const noexcept {
    return records_.data() + std::size_t{r} * kRecordWords;
  }
  // start loading cell c
  void prefetch(std::int64_t c) const noexcept {
    const std::uint64_t* p = grid_.data() + static_cast<std::size_t>(c) * kCellWords;
    for (std::size_t line = 0; line < kCellWords; line += 8) __builtin_prefetch(p + line);
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
  // per face of the dual, the vertex of P farthest along its middle direction (the face of
  // P* that vertex is): what the viewer's dual view names; empty without a dual
  const std::vector<std::uint32_t>& labels() const noexcept { return labels_; }
  std::size_t bytes() const noexcept;

 private:
  // records are laid out in units of one cache line (8 words), each from a line's start
  static constexpr std::size_t kRecordWords = 8;
  // a grid cell's words (four cache lines): a copy of its proposal's record where that fits
  // (degree 8 at most), else kElsewhere in the degree's place and the record's index
  static constexpr std::size_t kCellWords = 32;
  static constexpr std::uint64_t kElsewhere = 0xffffffff;
  void buildRecords(const ConvexPolyhedron& polyhedron, const VertexGraph& graph,
                    std::vector<std::uint32_t>& recordOf);
  std::optional<CubemapLocator> cube_;
  Table<std::uint64_t> grid_;     // 6 side^2 cells, cube face by cube face, row by row
  Table<std::uint64_t> records_;  // every vertex's star record, in vertex order
  std::uint32_t side_ = 1;
  std::size_t dualVertices_ = 0;
  std::size_t dualFaces_ = 0;
  std::vector<std::uint32_t> labels_;  // per dual face: the vertex farthest along its middle
};

}  // namespace convexloc::detail
