// convexloc — the polar locator's one-point queries: locate(p), with its fast path (the
// cell's radii, then the two edges of a cell listing one or two, by the filtered
// predicate alone), trace(p) and the public index function.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "convexloc/locate2d.hpp"
#include "detail/radii.hpp"
#include "detail/sinks2d.hpp"
#include "polar/index.hpp"
#include "polar/query.hpp"

namespace convexloc {

std::int64_t PolarLocator::cellIndex(Vec2 p) const noexcept {
  return polar::cellIndex(index_, p);
}

Location PolarLocator::locate(Vec2 p) const noexcept {
  const std::int64_t c = polar::cellIndex(index_, p);
  if (c >= 0) {
    const Radii r = radii_[static_cast<std::size_t>(c)];
    const double d2 = polar::distance2(p, index_.centre);
    // one branch, taken by most points, then the answer without one
    if (detail::radiiDecide(d2, r.in2, r.out2))
      return detail::insideOrOutside(d2 > static_cast<double>(r.out2));
    const std::uint32_t b = offsets_[static_cast<std::size_t>(c)];
    const std::uint32_t k = offsets_[static_cast<std::size_t>(c) + 1] - b;
    Location out;
    if (k - 1 < 2 && polar::twoEdges(vertices_.data() + entries_[b], p, out)) return out;
  }
  detail::NoSink2D sink;
  return run(p, sink);
}

namespace {

// the index function's numbers for a point that has a cell, with cellIndex()'s operations
PolarIndexTrace indexNumbers(const detail::PolarIndex& index, Vec2 p) {
  PolarIndexTrace n;
  n.direction = {p.x - index.centre.x, p.y - index.centre.y};
  const double ax = std::fabs(n.direction.x), ay = std::fabs(n.direction.y);
  n.steep = ay > ax;
  n.ratio = std::min(ax, ay) / std::max(ax, ay);
  n.slabs = index.slabsPerOctant;
  polar::OctantSlab o;
  polar::octantSlab(n.direction.x, n.direction.y, index.slabScale, n.slabs, o);
  n.slab = o.slab;
  n.base = index.cellBase[o.octant];
  n.step = index.cellStep[o.octant];
  return n;
}

}  // namespace

Trace2D PolarLocator::trace(Vec2 p, TraceOptions options) const {
  Trace2D t;
  t.method = Method2D::Polar;
  t.apex = entries_.empty() ? vertices_[0] : index_.centre;
  t.radiusFilter = options.radii;
  detail::TraceSink2D sink{t};
  t.result = run(p, sink);
  if (t.cell >= 0) t.polar = indexNumbers(index_, p);
  return t;
}

}  // namespace convexloc
