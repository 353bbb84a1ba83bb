// convexloc — the walk locator, O(sqrt F) expected: from the start face whose direction from
// the centre is nearest the point's, across face adjacency to the face the ray from the
// centre through the point leaves by (ref. [11]), then one plane test. Why the walk ends
// there and why one test is exact: detail/walk_step.hpp.
#include <algorithm>
#include <cmath>
#include <limits>

#include "convexloc/locate3d.hpp"
#include "convexloc/timing.hpp"
#include "detail/plane_tests3d.hpp"
#include "detail/sink_queries.hpp"
#include "detail/sinks3d.hpp"
#include "detail/walk_step.hpp"

namespace convexloc {

WalkLocator::WalkLocator(const ConvexPolyhedron& polyhedron) {
  auto t0 = Clock::now();
  surface_ = detail::SurfaceCopy(polyhedron);
  mesh_ = detail::WalkMesh(polyhedron);
  centre_ = polyhedron.centre();
  const std::vector<ConvexPolyhedron::Triangle>& triangles = mesh_.trianglesOf(surface_);
  const std::size_t n = triangles.size();
  maxVisits_ =
      static_cast<std::uint32_t>(std::min<double>(64 + 8 * std::sqrt(static_cast<double>(n)), 1e9));
  if (centre_) {
    // jump and walk: about F^(1/3) start faces spread over the list; a query starts from the
    // one whose direction from the centre is closest to its own
    const std::size_t k = std::clamp<std::size_t>(
        static_cast<std::size_t>(std::cbrt(static_cast<double>(n))), 1, 1024);
    const Vec3 c = *centre_;
    const std::vector<Vec3>& v = surface_.vertices;
    for (std::size_t i = 0; i < k; ++i) {
      const auto f = static_cast<std::uint32_t>(i * n / k);
      double d[3] = {0, 0, 0};
      for (std::uint32_t w : triangles[f]) {
        d[0] += (v[w].x - c.x) / 3;
        d[1] += (v[w].y - c.y) / 3;
        d[2] += (v[w].z - c.z) / 3;
      }
      const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
      if (!(len > 0) || !std::isfinite(len)) continue;
      startFaces_.push_back(f);
      startDirections_.push_back({static_cast<float>(d[0] / len), static_cast<float>(d[1] / len),
                                  static_cast<float>(d[2] / len)});
    }
    if (startFaces_.empty()) startFaces_.push_back(0), startDirections_.push_back({1, 0, 0});
  }
  buildSeconds_ = secondsSince(t0);
}

template <class Sink>
Location WalkLocator::run(Vec3 p, Sink& sink) const noexcept {
  if (detail::refusedAsNonFinite(p, sink)) return Location::Outside;
  auto testAll = [&] {
    sink.fallback();
    return detail::testAll(surface_, p, sink);
  };
  if (!centre_) return testAll();
  const Vec3 c = *centre_;
  const double dx = p.x - c.x, dy = p.y - c.y, dz = p.z - c.z;
  std::uint32_t start = startFaces_[0];
  if (std::isfinite(dx) && std::isfinite(dy) && std::isfinite(dz)) {
    // the start choice is a heuristic only; exactness comes from the walk's predicates
    double best = -std::numeric_limits<double>::infinity();
    for (std::size_t k = 0; k < startFaces_.size(); ++k) {
      const std::array<float, 3>& u = startDirections_[k];
      const double dot = dx * u[0] + dy * u[1] + dz * u[2];
      if (dot > best) {
        best = dot;
        start = startFaces_[k];
      }
    }
  }
  return detail::walkAndTest(surface_, mesh_, c, p, start, maxVisits_, sink, testAll);
}

template class detail::SinkQueries<WalkLocator, Vec3, Trace3D>;

Stats3D WalkLocator::stats() const {
  Stats3D s = detail::baseStats(surface_,
                                sizeof(*this) + mesh_.bytes() + detail::bytesOf(startFaces_) +
                                    detail::bytesOf(startDirections_),
                                buildSeconds_);
  s.centred = centre_.has_value();
  return s;
}

}  // namespace convexloc
