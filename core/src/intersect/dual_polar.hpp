// convexloc (internal) — the polar locator of a polygon's dual, proposing a line's extreme
// vertices in O(1). The argument heads dual_polar.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "convexloc/geometry.hpp"
#include "convexloc/locate2d.hpp"

namespace convexloc::detail {

// a proposal: the vertex largest along a direction and the one largest along its opposite
struct ExtremePair {
  std::uint32_t largest = 0;
  std::uint32_t smallest = 0;
};

class DualPolar2D {
 public:
  // builds the dual of the counter-clockwise ring of a strictly convex polygon: O(N log N)
  explicit DualPolar2D(std::span<const Vec2> ring);
  // The proposal for the line p1 -> p2 (f = (p2 - p1) x (x - p1)) and the polar cell it came
  // from; false when the direction has no cell (the caller then searches without one).
  bool propose(Vec2 p1, Vec2 p2, ExtremePair& out, std::int64_t& cell) const noexcept;
  // the polar locator of the dual polygon; null when the dual has no centre (never for the
  // centrally symmetric dual built here, but then every query searches)
  const PolarLocator* locator() const noexcept { return polar_ ? &*polar_ : nullptr; }
  std::size_t dualVertices() const noexcept { return dualVertices_; }
  // the dual polygon's vertices, counter-clockwise
  std::span<const Vec2> vertices() const noexcept { return vertices_; }
  std::size_t maxPerCell() const noexcept { return maxPerCell_; }
  std::size_t bytes() const noexcept;

 private:
  std::optional<PolarLocator> polar_;
  std::vector<Vec2> vertices_;
  std::vector<ExtremePair> byCell_;  // per polar cell: the labels of the middle edge it lists
  Vec2 centre_{};
  std::size_t dualVertices_ = 0;
  std::size_t maxPerCell_ = 0;
};

}  // namespace convexloc::detail
