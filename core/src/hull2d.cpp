// convexloc — the exact convex hull of a 2D point cloud as a ConvexPolygon: convexHull's
// monotone chain (generate2d.cpp), which decides every turn with the exact orient2d and keeps
// only strict left turns, so every input point is inside or on the result, every vertex is
// an input point and an extreme one (no vertex on the segment joining its neighbours). The
// chain runs over the points sorted by coordinates and starts at the smallest, so the same
// points give the same polygon in any order; then the vertices are named by their first
// index in the input.
#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/polygon.hpp"
#include "detail/polyhedron_build.hpp"

namespace convexloc {
namespace {

// x, then y
bool lexLess(Vec2 a, Vec2 b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

// Throws GeometryError when the cloud has no hull with an area: a coordinate that is not
// finite, fewer than 3 points, all points equal or on one line (`hull` is convexHull's).
void refuseDegenerate(std::span<const Vec2> points, const std::vector<Vec2>& hull) {
  const std::size_t n = points.size();
  if (n < 3)
    throw GeometryError("a hull needs at least 3 points not on one line, got " +
                        (n == 0 ? std::string("none") : std::to_string(n)));
  const std::string zero = "the hull has zero area: the " + std::to_string(n) + " points ";
  if (hull.size() == 1) throw GeometryError(zero + "are all equal to " + detail::show(hull[0]));
  if (hull.size() == 2)
    throw GeometryError(zero + "are collinear, on the segment from " + detail::show(hull[0]) +
                        " to " + detail::show(hull[1]));
}

}  // namespace

ConvexPolygon ConvexPolygon::hullOf(std::span<const Vec2> points) {
  for (std::size_t i = 0; i < points.size(); ++i)
    if (!std::isfinite(points[i].x) || !std::isfinite(points[i].y))
      throw GeometryError("point " + std::to_string(i) +
                          " has a coordinate that is not a finite number");
  if (points.size() > kMaxPolygonVertices)
    throw UsageError("too many points for a hull: " + std::to_string(points.size()));
  std::vector<Vec2> hull = points.size() < 3 ? std::vector<Vec2>{} : convexHull(points);
  refuseDegenerate(points, hull);
  // -0 written as +0, so that equal hulls have equal bytes
  for (Vec2& p : hull) p = {p.x + 0.0, p.y + 0.0};
  ConvexPolygon polygon(hull);
  // each vertex's first index in the input
  std::vector<std::pair<Vec2, std::uint32_t>> corners;
  for (std::uint32_t i = 0; i < polygon.size(); ++i) corners.emplace_back(polygon.vertex(i), i);
  std::sort(corners.begin(), corners.end(),
            [](const auto& a, const auto& b) { return lexLess(a.first, b.first); });
  std::vector<std::uint8_t> named(corners.size(), 0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto at = std::lower_bound(
        corners.begin(), corners.end(), points[i],
        [](const std::pair<Vec2, std::uint32_t>& c, Vec2 p) { return lexLess(c.first, p); });
    if (at == corners.end() || !(at->first == points[i])) continue;
    const std::size_t k = static_cast<std::size_t>(at - corners.begin());
    if (!named[k]) polygon.source_[at->second] = static_cast<std::uint32_t>(i), named[k] = 1;
  }
  polygon.dropped_ = points.size() - polygon.size();
  return polygon;
}

}  // namespace convexloc
