// convexloc (internal) — a polygon's dual: its polar locator, and the direction cells that
// propose a line's extreme vertices in O(1). The argument heads dual_polar.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "convexloc/geometry.hpp"
#include "convexloc/locate2d.hpp"
#include "convexloc/table.hpp"

namespace convexloc::detail {

// Four consecutive vertices of the ring, from the one before a cell's proposal to two after
// it, on one cache line: all that confirming the proposal or its successor reads.
struct alignas(64) RingWindow {
  Vec2 v[4];
};

class DualPolar2D {
 public:
  // builds the dual of the counter-clockwise ring of a strictly convex polygon: O(N log N)
  explicit DualPolar2D(std::span<const Vec2> ring);
  // The direction cells of the line p1 -> p2's normal w (f = (p2 - p1) x (x - p1) is largest
  // along w) and of -w, side by side in one 128-byte block; false when the direction has no
  // cell (the caller then searches).
  bool cells(Vec2 p1, Vec2 p2, std::int64_t& up, std::int64_t& down) const noexcept;
  // the polar cells of the dual holding c* + w / |w|max and c* - w / |w|max (for the trace)
  bool polarCells(Vec2 p1, Vec2 p2, std::int64_t& up, std::int64_t& down) const noexcept;
  // direction cell c's proposal for the vertex largest along its directions: the ring index
  // of window(c).v[1]
  std::uint32_t proposal(std::int64_t c) const noexcept {
    return starts_[static_cast<std::size_t>(c)];
  }
  // the ring around direction cell c's proposal
  const RingWindow& window(std::int64_t c) const noexcept {
    return windows_[static_cast<std::size_t>(c)];
  }
  // starts loading direction cell c's window
  void prefetch(std::int64_t c) const noexcept { __builtin_prefetch(windows_.data() + c); }
  // the polar locator of the dual polygon; null when the dual has no centre (never for the
  // centrally symmetric dual built here, but then every query searches)
  const PolarLocator* locator() const noexcept { return polar_ ? &*polar_ : nullptr; }
  std::size_t dualVertices() const noexcept { return dualVertices_; }
  // the dual polygon's vertices, counter-clockwise
  std::span<const Vec2> vertices() const noexcept { return vertices_; }
  std::size_t maxPerCell() const noexcept { return maxPerCell_; }
  // direction cells per octant
  std::uint32_t slabs() const noexcept { return slabs_; }
  std::size_t bytes() const noexcept;

 private:
  std::optional<PolarLocator> polar_;
  std::vector<Vec2> vertices_;
  // fills windows_ and starts_ for the ring's n vertices
  void buildDirectionCells(std::span<const Vec2> ring);
  Table<RingWindow> windows_;    // per direction cell: the pair of w and -w side by side
  Table<std::uint32_t> starts_;  // per direction cell: its proposal
  std::uint32_t slabs_ = 0;      // direction cells per octant
  Vec2 centre_{};
  std::size_t dualVertices_ = 0;
  std::size_t maxPerCell_ = 0;
};

}  // namespace convexloc::detail
