// convexloc — the halfspace locator, O(F): inside iff on the inner side of every face plane
// (eq. 2). Needs no centre; the reference every other 3D method answers like.
#include "convexloc/locate3d.hpp"
#include "convexloc/timing.hpp"
#include "detail/plane_tests3d.hpp"
#include "detail/sink_queries.hpp"
#include "detail/sinks3d.hpp"

namespace convexloc {

HalfspaceLocator::HalfspaceLocator(const ConvexPolyhedron& polyhedron) {
  auto t0 = Clock::now();
  surface_ = detail::SurfaceCopy(polyhedron);
  buildSeconds_ = secondsSince(t0);
}

template <class Sink>
Location HalfspaceLocator::run(Vec3 p, Sink& sink) const noexcept {
  if (detail::refusedAsNonFinite(p, sink)) return Location::Outside;
  return detail::testAll(surface_, p, sink);
}

template class detail::SinkQueries<HalfspaceLocator, Vec3, Trace3D>;

Stats3D HalfspaceLocator::stats() const {
  return detail::baseStats(surface_, sizeof(*this), buildSeconds_);
}

}  // namespace convexloc
