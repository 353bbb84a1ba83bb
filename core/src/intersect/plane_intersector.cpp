// convexloc — PlaneIntersector: the vertices baseline, the dual cube map, and what they share.
//
// Both methods reach a vertex where G is largest and one where it is smallest and read the
// crossing from their exact signs (crossingOf); the baseline's classify reads every vertex's
// sign instead, stopping once both sides are seen.
#include <array>
#include <cstdint>
#include <limits>
#include <memory>
#include <optional>
#include <span>
#include <string_view>

#include "convexloc/intersect3d.hpp"
#include "convexloc/predicates.hpp"
#include "convexloc/table.hpp"
#include "convexloc/timing.hpp"
#include "intersect/graph3d.hpp"
#include "intersect/plane_dual.hpp"
#include "intersect/scan.hpp"

namespace convexloc {

namespace {

// the crossing from every vertex's side: O(V)
Crossing crossingBySides(std::span<const Vec3> vertices, Vec3 q1, Vec3 q2, Vec3 q3) noexcept {
  bool above = false, below = false, on = false;
  for (const Vec3 v : vertices) {
    const int s = orient3d(q1, q2, q3, v);
    above |= s > 0;
    below |= s < 0;
    on |= s == 0;
    if (above && below) return Crossing::Crosses;
  }
  return on ? Crossing::Touches : Crossing::Misses;
}

}  // namespace

std::string_view toString(PlaneMethod m) noexcept {
  return m == PlaneMethod::Dual ? "dual" : "vertices";
}

std::string_view costOf(PlaneMethod m) noexcept {
  return m == PlaneMethod::Dual ? "O(1)" : "O(V)";
}

std::optional<PlaneMethod> parsePlaneMethod(std::string_view name) noexcept {
  for (const PlaneMethod m : kAllPlaneMethods)
    if (toString(m) == name) return m;
  return std::nullopt;
}

bool collinear(Vec3 a, Vec3 b, Vec3 c) noexcept {
  // on one line exactly when the three projections onto the coordinate planes are
  return orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) == 0 &&
         orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}) == 0 &&
         orient2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x}) == 0;
}

PlaneIntersector::PlaneIntersector(const ConvexPolyhedron& polyhedron, PlaneMethod method)
    : method_(method),
      vertices_(polyhedron.vertices().begin(), polyhedron.vertices().end()),
      faces_(polyhedron.faceCount()) {
  const auto t0 = Clock::now();
  if (method_ == PlaneMethod::Dual) {
    graph_ = std::make_unique<detail::VertexGraph>(polyhedron);
    dual_ = std::make_unique<detail::DualCubemap3D>(polyhedron, *graph_);
  }
  buildSeconds_ = secondsSince(t0);
}

PlaneIntersector::~PlaneIntersector() = default;
PlaneIntersector::PlaneIntersector(PlaneIntersector&&) noexcept = default;
PlaneIntersector& PlaneIntersector::operator=(PlaneIntersector&&) noexcept = default;

PlaneTrace PlaneIntersector::run(Vec3 q1, Vec3 q2, Vec3 q3, bool tracing) const noexcept {
  PlaneTrace t;
  t.method = method_;
  detail::PlaneProbe up{q1, q2, q3}, down = up.swapped();
  ExtremeVertices& e = t.extremes;
  if (method_ == PlaneMethod::Vertices) {
    e.largest = detail::scanLargest<Vec3>(vertices_, up);
    e.smallest = detail::scanLargest<Vec3>(vertices_, down);
  } else {
    t.proposed = dual_->propose(q1, q2, q3, t.startMax, t.startMin, t.listedMax, t.listedMin);
    e.largest = t.startMax;
    e.smallest = t.startMin;
    constexpr std::uint32_t kNoLimit = std::numeric_limits<std::uint32_t>::max();
    detail::climbToLargest(*graph_, vertices_, up, e.largest, kNoLimit, t.climbSteps);
    detail::climbToLargest(*graph_, vertices_, down, e.smallest, kNoLimit, t.climbSteps);
  }
  e.largestSign = orient3d(q1, q2, q3, vertices_[e.largest]);
  e.smallestSign = orient3d(q1, q2, q3, vertices_[e.smallest]);
  t.crossing = crossingOf(e.largestSign, e.smallestSign);
  if (tracing) t.comparisons = up.comparisons + down.comparisons;
  if (tracing && method_ == PlaneMethod::Dual) t.direction = detail::DualCubemap3D::aim(q1, q2, q3);
  return t;
}

Crossing PlaneIntersector::classify(Vec3 q1, Vec3 q2, Vec3 q3) const noexcept {
  if (method_ == PlaneMethod::Vertices) return crossingBySides(vertices_, q1, q2, q3);
  return run(q1, q2, q3, false).crossing;
}

void PlaneIntersector::classify(std::span<const Vec3> planes,
                                std::span<Crossing> out) const noexcept {
  for (std::size_t i = 0; i < out.size(); ++i)
    out[i] = classify(planes[3 * i], planes[3 * i + 1], planes[3 * i + 2]);
}

PlaneTrace PlaneIntersector::trace(Vec3 q1, Vec3 q2, Vec3 q3) const {
  return run(q1, q2, q3, true);
}

PlaneStats PlaneIntersector::stats() const {
  PlaneStats s;
  s.vertices = vertices_.size();
  s.faces = faces_;
  s.bytes = detail::bytesOf(vertices_);
  s.buildSeconds = buildSeconds_;
  if (dual_) {
    s.dualVertices = dual_->dualVertices();
    s.dualFaces = dual_->dualFaces();
    s.cells = dual_->locator() ? dual_->locator()->stats().cells : 0;
    s.bytes +=
        dual_->bytes() + detail::bytesOf(graph_->offsets) + detail::bytesOf(graph_->neighbours);
  }
  return s;
}

const CubemapLocator* PlaneIntersector::dualLocator() const noexcept {
  return dual_ ? dual_->locator() : nullptr;
}

std::span<const std::uint32_t> PlaneIntersector::dualLabels() const noexcept {
  if (!dual_) return {};
  return dual_->labels();
}

}  // namespace convexloc
