// convexloc — deterministic polygon and point generators.
#include "convexloc/generate2d.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "convexloc/error.hpp"
#include "convexloc/predicates.hpp"
#include "detail/names.hpp"

namespace convexloc {
namespace {

constexpr double kPi = std::numbers::pi;

// n points on an ellipse, rotated by `turn` radians and moved to `centre`
std::vector<Vec2> ellipse(std::size_t n, double a, double b, double turn, Vec2 centre) {
  std::vector<Vec2> v(n);
  const double c = std::cos(turn), s = std::sin(turn);
  for (std::size_t i = 0; i < n; ++i) {
    double t = 2 * kPi * static_cast<double>(i) / static_cast<double>(n);
    double x = a * std::cos(t), y = b * std::sin(t);
    v[i] = {centre.x + c * x - s * y, centre.y + s * x + c * y};
  }
  return v;
}

// Valtr's random convex polygon: random x and y increments split into two chains each,
// paired at random, sorted by angle and laid end to end
std::vector<Vec2> valtr(std::size_t n, Rng& rng) {
  auto increments = [&](std::vector<double>& out) {
    std::vector<double> xs(n);
    for (double& x : xs) x = rng.uniform();
    std::sort(xs.begin(), xs.end());
    double lo = xs.front(), hi = xs.back();
    double lastTop = lo, lastBottom = lo;
    for (std::size_t i = 1; i + 1 < n; ++i) {
      if (rng.next() & 1) {
        out.push_back(xs[i] - lastTop);
        lastTop = xs[i];
      } else {
        out.push_back(lastBottom - xs[i]);
        lastBottom = xs[i];
      }
    }
    out.push_back(hi - lastTop);
    out.push_back(lastBottom - hi);
  };
  std::vector<double> dx, dy;
  increments(dx);
  increments(dy);
  for (std::size_t i = dy.size(); i > 1; --i) std::swap(dy[i - 1], dy[rng.below(i)]);
  std::vector<Vec2> steps(n);
  for (std::size_t i = 0; i < n; ++i) steps[i] = {dx[i], dy[i]};
  std::sort(steps.begin(), steps.end(),
            [](Vec2 a, Vec2 b) { return std::atan2(a.y, a.x) < std::atan2(b.y, b.x); });
  std::vector<Vec2> v(n);
  Vec2 at{0, 0};
  for (std::size_t i = 0; i < n; ++i) {
    v[i] = at;
    at = {at.x + steps[i].x, at.y + steps[i].y};
  }
  return v;
}

// in the order of PolygonKind
constexpr std::string_view kNames[] = {"regular",    "random", "ellipse",    "sliver",
                                       "tiny-edges", "offset", "degenerate", "triangle"};

}  // namespace

std::string_view toString(PolygonKind k) {
  return detail::nameOf(kNames, k);
}

std::optional<PolygonKind> parsePolygonKind(std::string_view name) {
  return detail::enumNamed<PolygonKind>(kNames, name);
}

std::vector<Vec2> convexHull(std::span<const Vec2> points) {
  std::vector<Vec2> p(points.begin(), points.end());
  std::sort(p.begin(), p.end(),
            [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<Vec2> h(2 * p.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    while (k >= 2 && orient2d(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  for (std::size_t i = p.size() - 1, t = k + 1; i-- > 0;) {
    while (k >= t && orient2d(h[k - 2], h[k - 1], p[i]) <= 0) --k;
    h[k++] = p[i];
  }
  h.resize(k - 1);
  return h;
}

std::vector<Vec2> generatePolygon(PolygonKind kind, std::size_t n, std::uint64_t seed) {
  if (n < 3) throw UsageError("a polygon needs at least 3 vertices");
  if (n > (std::size_t{1} << 26)) throw UsageError("at most 2^26 vertices can be generated");
  Rng rng(seed);
  std::vector<Vec2> v;
  switch (kind) {
    case PolygonKind::Regular: v = ellipse(n, 1, 1, 0, {0, 0}); break;
    case PolygonKind::Random: v = valtr(n, rng); break;
    case PolygonKind::Ellipse: v = ellipse(n, 2, 1, 0, {0, 0}); break;
    case PolygonKind::Sliver: v = ellipse(n, 1, 1e-9, kPi / 6, {0.25, 0.5}); break;
    case PolygonKind::Offset: v = ellipse(n, 1, 1, rng.uniform(), {1e9, -1e9}); break;
    case PolygonKind::TinyEdges: {
      // a quarter arc of radius 1e-10 at the top-right corner of [-1, 1]^2
      const double r = 1e-10;
      v = {{-1, -1}, {1, -1}};
      std::size_t arc = n - 3;
      for (std::size_t i = 0; i < arc; ++i) {
        double t = 0.5 * kPi * static_cast<double>(i) / static_cast<double>(arc > 1 ? arc - 1 : 1);
        v.push_back({1 - r + r * std::cos(t), 1 - r + r * std::sin(t)});
      }
      v.push_back({-1, 1});
      break;
    }
    case PolygonKind::Degenerate: {
      // integer points along each side of [0, k]^2, each corner twice: exact collinearity
      std::size_t k = std::max<std::size_t>(1, n / 4);
      double s = static_cast<double>(k);
      for (int side = 0; side < 4; ++side)
        for (std::size_t i = 0; i < k; ++i) {
          double t = static_cast<double>(i);
          Vec2 p = side == 0   ? Vec2{t, 0}
                   : side == 1 ? Vec2{s, t}
                   : side == 2 ? Vec2{s - t, s}
                               : Vec2{0, s - t};
          v.push_back(p);
          if (i == 0) v.push_back(p);
        }
      return v;
    }
    case PolygonKind::Triangle:
      v = {{rng.uniform(-1, 1), rng.uniform(-1, 1)},
           {rng.uniform(-1, 1), rng.uniform(-1, 1)},
           {rng.uniform(-1, 1), rng.uniform(-1, 1)}};
      break;
  }
  // rounding can leave a vertex a hair inside its neighbours; keep the strictly convex hull
  return convexHull(v);
}

std::vector<Vec2> generatePoints(const ConvexPolygon& polygon, std::size_t count,
                                 std::uint64_t seed, bool nearBoundary) {
  Rng rng(seed);
  Box2 b = polygon.bounds();
  double wx = 0.1 * (b.hi.x - b.lo.x), wy = 0.1 * (b.hi.y - b.lo.y);
  std::vector<Vec2> out;
  out.reserve(count);
  const std::size_t n = polygon.size();
  const double inf = std::numeric_limits<double>::infinity();
  while (out.size() < count) {
    if (!nearBoundary) {
      out.push_back({rng.uniform(b.lo.x - wx, b.hi.x + wx), rng.uniform(b.lo.y - wy, b.hi.y + wy)});
      continue;
    }
    std::size_t e = rng.below(n);
    Vec2 a = polygon.edgeStart(e), c = polygon.edgeEnd(e);
    double t = rng.uniform();
    Vec2 on{a.x + t * (c.x - a.x), a.y + t * (c.y - a.y)};
    switch (rng.below(5)) {
      case 0: out.push_back(a); break;  // a vertex
      case 1: {                         // one ulp off a vertex
        double dx = rng.below(2) ? inf : -inf, dy = rng.below(2) ? inf : -inf;
        out.push_back({std::nextafter(a.x, dx), std::nextafter(a.y, dy)});
        break;
      }
      case 2: {  // exactly on the edge, where a nearby double is; else the nearest try
        Vec2 best = on;
        for (int k = 0; k < 64; ++k) {
          Vec2 p{on.x, on.y};
          for (int j = 0; j < (k & 7); ++j) p.x = std::nextafter(p.x, (k & 8) ? inf : -inf);
          for (int j = 0; j < (k >> 4); ++j) p.y = std::nextafter(p.y, (k & 8) ? -inf : inf);
          if (orient2d(a, c, p) == 0) {
            best = p;
            break;
          }
        }
        out.push_back(best);
        break;
      }
      case 3: {  // one ulp off the segment, either side
        double d = rng.below(2) ? inf : -inf;
        out.push_back(rng.below(2) ? Vec2{std::nextafter(on.x, d), on.y}
                                   : Vec2{on.x, std::nextafter(on.y, d)});
        break;
      }
      default: {  // a hair inside or outside along the normal
        double h = (rng.uniform() - 0.5) * 1e-9;
        out.push_back({on.x - h * (c.y - a.y), on.y + h * (c.x - a.x)});
        break;
      }
    }
  }
  return out;
}

}  // namespace convexloc
