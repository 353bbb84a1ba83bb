// convexloc — PlaneIntersector: the vertices baseline, the dual cube map, and what they share.
//
// Both methods reach a vertex where G is largest and one where it is smallest and read the
// crossing from their exact signs (crossingOf); the baseline's classify reads every vertex's
// sign instead, stopping once both sides are seen.
#include <algorithm>
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
#include "intersect/blocks.hpp"
#include "intersect/dual_cubemap.hpp"
#include "intersect/graph3d.hpp"
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
    const detail::VertexGraph graph(polyhedron);  // the records keep all a climb needs of it
    dual_ = std::make_unique<detail::DualCubemap3D>(polyhedron, graph);
  }
  buildSeconds_ = secondsSince(t0);
}

PlaneIntersector::~PlaneIntersector() = default;
PlaneIntersector::PlaneIntersector(PlaneIntersector&&) noexcept = default;
PlaneIntersector& PlaneIntersector::operator=(PlaneIntersector&&) noexcept = default;

std::uint32_t PlaneIntersector::largestFrom(const std::uint64_t* record, detail::PlaneProbe& probe,
                                            Vec3& at, std::uint32_t& steps) const noexcept {
  for (;;) {
    const detail::StarRecord star{record};
    const std::uint32_t degree = star.degree();
    const Vec3 centre = star.point(0);
    std::uint32_t higher = 0;
    for (std::uint32_t k = 1; k <= degree; ++k)
      if (probe.rise(centre, star.point(k)) > 0) {
        higher = k;
        break;
      }
    if (higher == 0) {  // no neighbour is strictly larger: a largest vertex
      at = centre;
      return star.vertex();
    }
    record = dual_->record(star.link(higher));
    ++steps;
  }
}

Crossing PlaneIntersector::classifyFrom(Vec3 q1, Vec3 q2, Vec3 q3, const std::uint64_t* up,
                                        const std::uint64_t* down) const noexcept {
  detail::PlaneProbe high{q1, q2, q3}, low = high.swapped();
  Vec3 largest, smallest;
  std::uint32_t steps = 0;
  largestFrom(up, high, largest, steps);
  largestFrom(down, low, smallest, steps);
  return crossingOf(orient3d(q1, q2, q3, largest), orient3d(q1, q2, q3, smallest));
}

PlaneTrace PlaneIntersector::run(Vec3 q1, Vec3 q2, Vec3 q3, bool tracing) const noexcept {
  PlaneTrace t;
  t.method = method_;
  detail::PlaneProbe up{q1, q2, q3}, down = up.swapped();
  ExtremeVertices& e = t.extremes;
  if (method_ == PlaneMethod::Vertices) {
    e.largest = detail::scanLargest<Vec3>(vertices_, up);
    e.smallest = detail::scanLargest<Vec3>(vertices_, down);
  } else {
    std::int64_t cellUp = -1, cellDown = -1;
    t.proposed = dual_->cells(q1, q2, q3, cellUp, cellDown);
    const std::uint64_t* high = t.proposed ? dual_->cell(cellUp) : dual_->first();
    const std::uint64_t* low = t.proposed ? dual_->cell(cellDown) : dual_->first();
    t.startMax = detail::StarRecord{high}.vertex();
    t.startMin = detail::StarRecord{low}.vertex();
    if (tracing) dual_->listed(q1, q2, q3, t.listedMax, t.listedMin);
    Vec3 at;
    e.largest = largestFrom(high, up, at, t.climbSteps);
    e.smallest = largestFrom(low, down, at, t.climbSteps);
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
  std::int64_t up = -1, down = -1;
  if (dual_->cells(q1, q2, q3, up, down)) {
    dual_->prefetch(up);  // every line of both cells requested at once
    dual_->prefetch(down);
    return classifyFrom(q1, q2, q3, dual_->cell(up), dual_->cell(down));
  }
  return run(q1, q2, q3, false).crossing;
}

// The dual batch through detail::inBlocks (blocks.hpp): the grid cells of the next block are
// found and their records prefetched while this block climbs. Every plane gets what
// classify(q1, q2, q3) gives it.
void PlaneIntersector::classify(std::span<const Vec3> planes,
                                std::span<Crossing> out) const noexcept {
  const std::size_t n = std::min(planes.size() / 3, out.size());
  if (method_ == PlaneMethod::Vertices) {
    for (std::size_t i = 0; i < n; ++i)
      out[i] = classify(planes[3 * i], planes[3 * i + 1], planes[3 * i + 2]);
    return;
  }
  detail::inBlocks(
      n,
      [&](std::size_t i, std::int64_t& up, std::int64_t& down) {
        const Vec3* q = planes.data() + 3 * i;
        if (!dual_->cells(q[0], q[1], q[2], up, down)) return false;
        dual_->prefetch(up);
        dual_->prefetch(down);
        return true;
      },
      [&](std::size_t i, std::int64_t up, std::int64_t down) {
        const Vec3* q = planes.data() + 3 * i;
        out[i] = up < 0 ? classify(q[0], q[1], q[2])
                        : classifyFrom(q[0], q[1], q[2], dual_->cell(up), dual_->cell(down));
      });
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
    s.bytes += dual_->bytes();
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
