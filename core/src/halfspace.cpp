// convexloc — the halfspace locator, O(F): inside iff on the inner side of every face plane
// (eq. 2). Needs no centre; the reference every other 3D method answers like.
#include "convexloc/locate3d.hpp"
#include "convexloc/timing.hpp"
#include "detail/batch_loop.hpp"
#include "detail/plane_tests3d.hpp"
#include "detail/sinks3d.hpp"

namespace convexloc {

HalfspaceLocator::HalfspaceLocator(const ConvexPolyhedron& polyhedron) {
  auto t0 = Clock::now();
  surface_ = detail::SurfaceCopy(polyhedron);
  buildSeconds_ = secondsSince(t0);
}

Location HalfspaceLocator::locate(Vec3 p) const noexcept {
  detail::NoSink3D sink;
  if (!detail::isFinite(p)) return Location::Outside;
  return detail::testAll(surface_, p, sink);
}

void HalfspaceLocator::locate(std::span<const Vec3> points,
                              std::span<Location> out) const noexcept {
  detail::locateEach(*this, points, out);
}

Trace3D HalfspaceLocator::trace(Vec3 p) const {
  return detail::traced(Method3D::Halfspace, std::nullopt, [&](auto& sink) {
    if (!detail::isFinite(p)) {
      sink.nonFinite();
      return Location::Outside;
    }
    return detail::testAll(surface_, p, sink);
  });
}

Stats3D HalfspaceLocator::stats() const {
  return detail::baseStats(surface_, sizeof(*this), buildSeconds_);
}

}  // namespace convexloc
