// convexloc — the slab locator, O(log N): horizontal slabs at the vertices' distinct y. In a
// convex polygon every slab meets exactly two edges, one rising and one falling (a polygon
// with area spans some height, so there is at least one slab); binary search over the y
// finds p's slab, and those two edges decide.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <utility>

#include "convexloc/locate2d.hpp"
#include "convexloc/timing.hpp"
#include "detail/sink_queries.hpp"
#include "detail/sinks2d.hpp"
#include "detail/stats2d.hpp"

namespace convexloc {

SlabLocator::SlabLocator(const ConvexPolygon& polygon) {
  const auto t0 = Clock::now();
  vertices_ = detail::copyVertices(polygon);
  box_ = polygon.bounds();
  const std::uint32_t n = static_cast<std::uint32_t>(vertices_.size());
  vertexYs_.reserve(n);
  for (Vec2 p : vertices_) vertexYs_.push_back(p.y);
  std::sort(vertexYs_.begin(), vertexYs_.end());
  vertexYs_.erase(std::unique(vertexYs_.begin(), vertexYs_.end()), vertexYs_.end());
  const std::size_t slabs = vertexYs_.size() - 1;
  activeEdges_.assign(2 * slabs, 0);
  auto rank = [&](double y) {
    return static_cast<std::size_t>(std::lower_bound(vertexYs_.begin(), vertexYs_.end(), y) -
                                    vertexYs_.begin());
  };
  for (std::uint32_t e = 0; e < n; ++e) {
    Vec2 a = vertices_[e], b = vertices_[e + 1 == n ? 0 : e + 1];
    if (a.y == b.y) continue;
    bool rising = a.y < b.y;
    std::size_t r0 = rank(std::min(a.y, b.y)), r1 = rank(std::max(a.y, b.y));
    for (std::size_t s = r0; s < r1; ++s) activeEdges_[2 * s + (rising ? 0 : 1)] = e;
  }
  buildSeconds_ = secondsSince(t0);
}

template <class Sink>
Location SlabLocator::run(Vec2 p, Sink& sink) const noexcept {
  if (detail::outsideBox(box_, p)) {
    sink.outsideBox();
    return Location::Outside;
  }
  const std::size_t slabs = vertexYs_.size() - 1;
  std::size_t s = sink.upperBound(vertexYs_, p.y);  // std::upper_bound, probes traced
  s = std::min(s == 0 ? 0 : s - 1, slabs - 1);
  sink.cell(static_cast<std::int64_t>(s), -1);
  const std::uint32_t* pair = activeEdges_.data() + 2 * s;
  Location r = detail::testEdges(vertices_, pair, pair + 2, p, sink);
  // on the bottom or top line, the only points between the chains are boundary points
  if (r == Location::Inside && (p.y == box_.lo.y || p.y == box_.hi.y)) return Location::Boundary;
  return r;
}

template class detail::SinkQueries<SlabLocator, Vec2, Trace2D>;

Stats2D SlabLocator::stats() const {
  Stats2D s = detail::plainStats(vertices_.size(),
                                 sizeof(*this) + detail::bytesOf(vertices_) +
                                     detail::bytesOf(vertexYs_) + detail::bytesOf(activeEdges_),
                                 buildSeconds_);
  s.cells = vertexYs_.size() - 1;
  s.entries = activeEdges_.size();
  s.maxPerCell = 2;
  s.meanPerCell = 2.0;
  s.histogram.assign(kCrowdedCell + 2, 0);
  s.histogram[2] = s.cells;
  return s;
}

std::vector<Cell2D> SlabLocator::cells() const {
  std::vector<Cell2D> out;
  for (std::size_t s = 0; s + 1 < vertexYs_.size(); ++s) {
    Cell2D c;
    c.index = static_cast<std::uint32_t>(s);
    c.y0 = vertexYs_[s];
    c.y1 = vertexYs_[s + 1];
    c.outline = {{box_.lo.x, c.y0}, {box_.hi.x, c.y0}, {box_.hi.x, c.y1}, {box_.lo.x, c.y1}};
    c.edges = {activeEdges_[2 * s], activeEdges_[2 * s + 1]};
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace convexloc
