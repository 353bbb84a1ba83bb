// convexloc (internal) — what the 2D locators' builds and stats() share: the vertex copy and
// the statistics of a table of cells.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "convexloc/locate2d.hpp"
#include "convexloc/timing.hpp"

namespace convexloc::detail {

// the locator's own copy of the polygon's vertices
inline std::vector<Vec2> copyVertices(const ConvexPolygon& polygon) {
  return {polygon.vertices().begin(), polygon.vertices().end()};
}

// the copy of a locator that builds nothing else, and the seconds it took into `seconds`
inline std::vector<Vec2> copyVertices(const ConvexPolygon& polygon, double& seconds) {
  const auto t0 = Clock::now();
  std::vector<Vec2> v = copyVertices(polygon);
  seconds = secondsSince(t0);
  return v;
}

// statistics of a locator without cells
inline Stats2D plainStats(std::size_t edges, std::size_t bytes, double buildSeconds) {
  Stats2D s;
  s.edges = edges;
  s.bytes = bytes;
  s.bytesPerEdge = edges ? static_cast<double>(bytes) / static_cast<double>(edges) : 0.0;
  s.buildSeconds = buildSeconds;
  return s;
}

// statistics of a CSR table: cell c lists entries [offsets[c], offsets[c + 1])
inline Stats2D csrStats(std::size_t edges, std::span<const std::uint32_t> offsets,
                        std::size_t bytes, double buildSeconds) {
  Stats2D s = plainStats(edges, bytes, buildSeconds);
  s.cells = offsets.empty() ? 0 : offsets.size() - 1;
  s.histogram.assign(kCrowdedCell + 2, 0);
  for (std::size_t c = 0; c < s.cells; ++c) {
    std::size_t k = offsets[c + 1] - offsets[c];
    s.entries += k;
    s.maxPerCell = std::max(s.maxPerCell, k);
    if (k > kCrowdedCell) ++s.crowdedCells;
    ++s.histogram[std::min(k, s.histogram.size() - 1)];
  }
  s.meanPerCell = s.cells ? static_cast<double>(s.entries) / static_cast<double>(s.cells) : 0.0;
  return s;
}

}  // namespace convexloc::detail
