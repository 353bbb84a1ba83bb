// convexloc (detail) — the three queries of a locator whose query is written once.
//
// A locator that writes its query once, as a private
//   template <class Sink> Location run(Point p, Sink& sink) const noexcept
// reporting each step to the sink, derives from SinkQueries<Derived, Point, Trace> and gets
// locate(p) (run with a sink that records nothing and compiles away), the batch (locate,
// point after point) and trace(p) (run with a sink that records every step, into a Trace
// whose method is Derived::kMethod). Derived befriends the base; where a trace needs more
// than the steps it defines `void completeTrace(Trace&) const`. The members are defined in
// core (src/detail/sink_queries.hpp) and instantiated in each locator's source file.
#pragma once

#include <span>

#include "convexloc/geometry.hpp"

namespace convexloc::detail {

template <class Derived, class Point, class Trace>
class SinkQueries {
 public:
  // the class of p (exact); one copy, out of line, which the batch calls point after point
  [[gnu::noinline]] Location locate(Point p) const noexcept;
  // out[i] = locate(points[i]) over the shorter of the two spans; allocates nothing
  void locate(std::span<const Point> points, std::span<Location> out) const noexcept;
  // the steps locate(p) takes, and its answer
  Trace trace(Point p) const;

 private:
  const Derived& self() const noexcept { return static_cast<const Derived&>(*this); }
};

}  // namespace convexloc::detail
