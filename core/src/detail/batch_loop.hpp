// convexloc (internal) — the batch of a locator without a batch path of its own.
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>

#include "convexloc/geometry.hpp"

namespace convexloc::detail {

// out[i] = loc.locate(points[i]) over the shorter of the two spans
template <class Locator, class Point>
void locateEach(const Locator& loc, std::span<const Point> points, std::span<Location> out) {
  const std::size_t n = std::min(points.size(), out.size());
  for (std::size_t i = 0; i < n; ++i) out[i] = loc.locate(points[i]);
}

}  // namespace convexloc::detail
