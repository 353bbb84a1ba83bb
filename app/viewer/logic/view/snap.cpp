// convexloc-viewer — snapping.
#include "logic/view/snap.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "convexloc/predicates.hpp"

namespace convexloc::viewer {
namespace {

// how many ulps either side of the projection the exact search looks
constexpr int kUlpReach = 3;
// the finest dyadic fraction of an edge tried: 2^-kDyadicLevels
constexpr int kDyadicLevels = 24;

double distance2(Vec2 a, Vec2 b) {
  const double dx = a.x - b.x, dy = a.y - b.y;
  return dx * dx + dy * dy;
}

// the point of the segment a-b nearest to p (double arithmetic: a drawing matter)
Vec2 nearestOnSegment(Vec2 a, Vec2 b, Vec2 p) {
  const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
  if (!(len2 > 0.0)) return a;
  const double t = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / len2, 0.0, 1.0);
  return {a.x + t * dx, a.y + t * dy};
}

// q lies in the closed box of a and b (with orient2d == 0: on the closed segment)
bool inSegmentBox(Vec2 a, Vec2 b, Vec2 q) {
  return std::min(a.x, b.x) <= q.x && q.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= q.y &&
         q.y <= std::max(a.y, b.y);
}

// `v` moved by k ulps (k may be negative)
double ulps(double v, int k) {
  for (; k > 0; --k) v = std::nextafter(v, std::numeric_limits<double>::infinity());
  for (; k < 0; ++k) v = std::nextafter(v, -std::numeric_limits<double>::infinity());
  return v;
}

// the exact candidates around (x, y): kept when on the segment and nearer to `aim`
void tryAround(Vec2 a, Vec2 b, Vec2 aim, Vec2 guess, std::optional<Vec2>& best) {
  for (int i = -kUlpReach; i <= kUlpReach; ++i)
    for (int j = -kUlpReach; j <= kUlpReach; ++j) {
      const Vec2 q{ulps(guess.x, i), ulps(guess.y, j)};
      if (!std::isfinite(q.x) || !std::isfinite(q.y) || !inSegmentBox(a, b, q)) continue;
      if (orient2d(a, b, q) != 0) continue;
      if (!best || distance2(q, aim) < distance2(*best, aim)) best = q;
    }
}

}  // namespace

const char* toString(SnapKind k) {
  switch (k) {
    case SnapKind::Vertex: return "vertex";
    case SnapKind::Edge: return "edge";
    case SnapKind::Centre: return "centre";
    case SnapKind::Grid: return "grid";
    case SnapKind::None: break;
  }
  return "";
}

std::optional<Vec2> pointOnSegment(Vec2 a, Vec2 b, Vec2 p, double reach) {
  const Vec2 q = nearestOnSegment(a, b, p);
  // an axis-aligned edge holds every double between its ends on its own line
  if (a.y == b.y) return Vec2{std::clamp(q.x, std::min(a.x, b.x), std::max(a.x, b.x)), a.y};
  if (a.x == b.x) return Vec2{a.x, std::clamp(q.y, std::min(a.y, b.y), std::max(a.y, b.y))};
  std::optional<Vec2> best;
  // y from x along the line, and x from y: each rounded once, then searched a few ulps about
  const double slope = (b.y - a.y) / (b.x - a.x), inverse = (b.x - a.x) / (b.y - a.y);
  tryAround(a, b, q, {q.x, a.y + (q.x - a.x) * slope}, best);
  tryAround(a, b, q, {a.x + (q.y - a.y) * inverse, q.y}, best);
  // a + t (b - a) at dyadic t near the projection's: exact where the ends have bits to spare
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double u =
      std::clamp(((q.x - a.x) * dx + (q.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
  for (int m = 1; m <= kDyadicLevels; ++m) {
    const double t = std::ldexp(std::round(std::ldexp(u, m)), -m);
    const Vec2 c{a.x + t * dx, a.y + t * dy};
    if (inSegmentBox(a, b, c) && orient2d(a, b, c) == 0 &&
        (!best || distance2(c, q) < distance2(*best, q)))
      best = c;
  }
  if (best && distance2(*best, p) > reach * reach) return std::nullopt;
  return best;
}

Snap snapPoint(Vec2 p, const SnapTargets& t, double radius) {
  const double r2 = radius * radius;
  const std::size_t n = t.ring.size();
  // the nearest vertex within reach
  std::optional<std::size_t> vertex;
  for (std::size_t i = 0; i < n; ++i)
    if (i != t.skip && distance2(t.ring[i], p) <= r2 &&
        (!vertex || distance2(t.ring[i], p) < distance2(t.ring[*vertex], p)))
      vertex = i;
  if (vertex) return {t.ring[*vertex], SnapKind::Vertex, *vertex, {}};
  if (t.centre && distance2(*t.centre, p) <= r2) return {*t.centre, SnapKind::Centre, 0, {}};
  // the nearest edge within reach; a dragged vertex's own edges move with it and are no target
  std::optional<std::size_t> edge;
  double edgeD2 = r2;
  for (std::size_t i = 0; i < n && n >= 2; ++i) {
    const std::size_t j = (i + 1) % n;
    if (i == t.skip || j == t.skip) continue;
    const double d2 = distance2(nearestOnSegment(t.ring[i], t.ring[j], p), p);
    if (d2 <= edgeD2) edgeD2 = d2, edge = i;
  }
  if (edge) {
    const Vec2 a = t.ring[*edge], b = t.ring[(*edge + 1) % n];
    if (const auto q = pointOnSegment(a, b, p, radius)) return {*q, SnapKind::Edge, *edge, {}};
    // no double near is exactly on the edge: its nearer end is
    const bool toA = distance2(a, p) <= distance2(b, p);
    return {toA ? a : b, SnapKind::Vertex, toA ? *edge : (*edge + 1) % n, *edge};
  }
  if (t.gridStep > 0.0) {
    const Vec2 g{std::round(p.x / t.gridStep) * t.gridStep,
                 std::round(p.y / t.gridStep) * t.gridStep};
    if (std::isfinite(g.x) && std::isfinite(g.y) && distance2(g, p) <= r2)
      return {g, SnapKind::Grid, 0, {}};
  }
  return {p, SnapKind::None, 0, {}};
}

double niceGridStep(double minWorld) {
  if (!(minWorld > 0.0) || !std::isfinite(minWorld)) return 0.0;
  const double decade = std::pow(10.0, std::floor(std::log10(minWorld)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * decade >= minWorld) return m * decade;
  return 10.0 * decade;
}

}  // namespace convexloc::viewer
