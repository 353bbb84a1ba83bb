// convexloc — the halfplane locator, O(N): a point is inside iff it is on the inner side of
// every edge (eq. 1), on the boundary iff it is on no outer side and on some edge's line.
#include <cstddef>
#include <cstdint>

#include "convexloc/locate2d.hpp"
#include "convexloc/predicates.hpp"
#include "detail/sink_queries.hpp"
#include "detail/sinks2d.hpp"
#include "detail/stats2d.hpp"

namespace convexloc {

HalfplaneLocator::HalfplaneLocator(const ConvexPolygon& polygon) {
  vertices_ = detail::copyVertices(polygon, buildSeconds_);
}

// every edge in order, stopping at the first outer side
template <class Sink>
Location HalfplaneLocator::run(Vec2 p, Sink& sink) const noexcept {
  if (detail::nonFinite(p)) return Location::Outside;  // before any predicate
  bool zero = false;
  const std::size_t n = vertices_.size();
  for (std::size_t i = 0; i < n; ++i) {
    int s = orient2d(vertices_[i], vertices_[i + 1 == n ? 0 : i + 1], p);
    sink.edge(static_cast<std::uint32_t>(i), s);
    if (s < 0) return Location::Outside;
    zero |= s == 0;
  }
  return zero ? Location::Boundary : Location::Inside;
}

template class detail::SinkQueries<HalfplaneLocator, Vec2, Trace2D>;

Stats2D HalfplaneLocator::stats() const {
  return detail::plainStats(vertices_.size(), sizeof(*this) + detail::bytesOf(vertices_),
                            buildSeconds_);
}

}  // namespace convexloc
