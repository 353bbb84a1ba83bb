// convexloc — the wedge locator, O(log N): bisection over the fan of diagonals from vertex 0
// (eq. 3; the bisection itself is detail/fan.hpp, which the polar locator's fallback shares).
#include <cstddef>
#include <cstdint>
#include <utility>

#include "convexloc/locate2d.hpp"
#include "detail/fan.hpp"
#include "detail/sink_queries.hpp"
#include "detail/sinks2d.hpp"
#include "detail/stats2d.hpp"

namespace convexloc {

WedgeLocator::WedgeLocator(const ConvexPolygon& polygon) {
  vertices_ = detail::copyVertices(polygon, buildSeconds_);
}

template <class Sink>
Location WedgeLocator::run(Vec2 p, Sink& sink) const noexcept {
  return detail::fanLocate(vertices_, p, sink);
}

void WedgeLocator::completeTrace(Trace2D& t) const {
  t.apex = vertices_[0];  // also for a point that no ray reached
  if (!t.edges.empty()) t.cell = t.edges.back().edge;
}

template class detail::SinkQueries<WedgeLocator, Vec2, Trace2D>;

// the fan triangles of cells(): one per inner diagonal pair, holding 1 to 3 edges
Stats2D WedgeLocator::stats() const {
  const std::size_t n = vertices_.size();
  Stats2D s = detail::plainStats(n, sizeof(*this) + detail::bytesOf(vertices_), buildSeconds_);
  s.cells = n - 2;
  s.entries = n;
  s.maxPerCell = n == 3 ? 3 : 2;
  s.meanPerCell = static_cast<double>(n) / static_cast<double>(n - 2);
  s.histogram.assign(kCrowdedCell + 2, 0);
  if (n == 3) {
    s.histogram[3] = 1;
  } else {
    s.histogram[2] = 2;
    s.histogram[1] = n - 4;
  }
  return s;
}

std::vector<Cell2D> WedgeLocator::cells() const {
  std::vector<Cell2D> out;
  const std::uint32_t n = static_cast<std::uint32_t>(vertices_.size());
  for (std::uint32_t i = 1; i + 1 < n; ++i) {
    Cell2D c;
    c.index = i;
    c.outline = {vertices_[0], vertices_[i], vertices_[i + 1]};
    c.edges = {i};
    if (i == 1) c.edges.insert(c.edges.begin(), 0);
    if (i + 2 == n) c.edges.push_back(n - 1);
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace convexloc
