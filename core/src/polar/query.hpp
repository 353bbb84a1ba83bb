// convexloc (internal) — the polar locator's query, written once for locate(), the batch
// and trace(): the cell from the index function, the cell's radii, then its edges (one
// test each, or a bisection of a crowded cell's run), and the fan where there is no cell.
#pragma once

#include <cmath>
#include <cstdint>

#include "convexloc/locate2d.hpp"
#include "convexloc/predicates.hpp"
#include "detail/fan.hpp"
#include "detail/radii.hpp"
#include "detail/sinks2d.hpp"
#include "polar/index.hpp"

namespace convexloc {

template <class Sink>
Location PolarLocator::searchRange(Vec2 p, std::uint32_t first, std::uint32_t count,
                                   Sink& sink) const noexcept {
  // The run's inner vertices and p's direction lie within the cell's widened angular range
  // (under 90 degrees), so the side of each ray from the centre is monotone along the run.
  const std::uint32_t* e = entries_.data() + first;
  std::uint32_t lo = 0, hi = count;
  while (hi - lo > 1) {
    std::uint32_t mid = lo + (hi - lo) / 2;
    int s = orient2d(index_.centre, vertices_[e[mid]], p);
    sink.ray(e[mid], s);
    if (s >= 0)
      lo = mid;
    else
      hi = mid;
  }
  // the ray from the centre through p leaves through edge e[lo]: one test decides
  int s = detail::edgeSign(ring(), e[lo], p);
  sink.edge(e[lo], s);
  return s > 0 ? Location::Inside : (s == 0 ? Location::Boundary : Location::Outside);
}

// The whole query. locate() and the batch first try their inline fast path (the radii, two
// edges) and call this for the rest, so it stays out of line: one copy, outside their loops.
template <class Sink>
[[gnu::noinline]] Location PolarLocator::run(Vec2 p, Sink& sink) const noexcept {
  if (entries_.empty()) return detail::fanLocate(ring(), p, sink);  // no centre strictly inside
  std::int64_t c = cellIndex(p);
  if (c < 0) {
    if (p == index_.centre) {
      sink.atCentre();
      return Location::Inside;
    }
    return detail::fanLocate(ring(), p, sink);  // offsets too large for the index arithmetic
  }
  const std::uint32_t cell = static_cast<std::uint32_t>(c);
  sink.cell(c, static_cast<int>(cell / index_.slabsPerOctant));
  if (sink.radii()) {  // always, but in a trace asked without the radius filter
    const Radii r = radii_[cell];
    const double d2 = polar::distance2(p, index_.centre);
    const bool decided = detail::radiiDecide(d2, r.in2, r.out2);
    sink.radius(d2, r.in2, r.out2, decided);
    if (decided) return detail::insideOrOutside(d2 > static_cast<double>(r.out2));
  }
  const std::uint32_t b = offsets_[cell], k = offsets_[cell + 1] - b;
  if (k <= kCrowdedCell)
    return detail::testEdges(ring(), entries_.data() + b, entries_.data() + b + k, p, sink);
  sink.crowded();
  return searchRange(p, b, k, sink);
}

namespace polar {

// Inside / Outside from the filtered signs of p against edges (r0, r1) and (r1, r2), without a
// branch on the answer; false when the filter cannot decide one of them (then the caller
// takes the exact path). Testing a second edge that the cell does not list is harmless:
// p is inside the polygon only if it is on the inner side of every edge.
inline bool twoEdges(const Vec2* r, Vec2 p, Location& out) noexcept {
  using detail::kCcwBound;
  using detail::kTinyPermanent;
  using detail::kUnderflowSlack;
  const double l0 = (r[0].x - p.x) * (r[1].y - p.y), m0 = (r[0].y - p.y) * (r[1].x - p.x);
  const double l1 = (r[1].x - p.x) * (r[2].y - p.y), m1 = (r[1].y - p.y) * (r[2].x - p.x);
  const double d0 = l0 - m0, d1 = l1 - m1;
  const double s0 = std::fabs(l0) + std::fabs(m0), s1 = std::fabs(l1) + std::fabs(m1);
  const bool sure = std::fabs(d0) > kCcwBound * s0 + kUnderflowSlack && s0 >= kTinyPermanent &&
                    std::fabs(d1) > kCcwBound * s1 + kUnderflowSlack && s1 >= kTinyPermanent;
  out = ((d0 < 0) | (d1 < 0)) ? Location::Outside : Location::Inside;
  return sure;
}

}  // namespace polar
}  // namespace convexloc
