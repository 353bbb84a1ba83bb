// Query points built to break a locator: vertices and their ulp neighbours, points exactly on
// edges (the reference says so) and one ulp off, the polar centre, polar cell borders, the
// axes and diagonals through the centre, slab boundaries of `slab` and `uniform`, extreme
// magnitudes, signed zeros and subnormals.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "convexloc/generate2d.hpp"
#include "convexloc/locate2d.hpp"
#include "convexloc/polygon.hpp"
#include "reference2d.hpp"

namespace adversarial {

using convexloc::Box2;
using convexloc::Vec2;

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr double kMax = std::numeric_limits<double>::max();
inline constexpr double kDenorm = std::numeric_limits<double>::denorm_min();

// x moved by k ulps (up for k > 0, down for k < 0)
inline double ulps(double x, int k) {
  for (; k > 0; --k) x = std::nextafter(x, kInf);
  for (; k < 0; ++k) x = std::nextafter(x, -kInf);
  return x;
}

// "(x, y)" with every digit needed to find the doubles again
inline std::string show(Vec2 p) {
  char buf[96];
  std::snprintf(buf, sizeof buf, "(%.17g, %.17g)", p.x, p.y);
  return buf;
}

// p, and p moved by up to `radius` ulps in x and/or y
inline void addUlpRing(std::vector<Vec2>& out, Vec2 p, int radius = 1) {
  for (int i = -radius; i <= radius; ++i)
    for (int j = -radius; j <= radius; ++j) out.push_back({ulps(p.x, i), ulps(p.y, j)});
}

// up to `limit` indices spread evenly over [0, n)
inline std::vector<std::size_t> spread(std::size_t n, std::size_t limit) {
  std::vector<std::size_t> idx;
  if (n <= limit) {
    for (std::size_t i = 0; i < n; ++i) idx.push_back(i);
    return idx;
  }
  for (std::size_t k = 0; k < limit; ++k) idx.push_back(k * n / limit);
  return idx;
}

// a finite double with an ordered integer image, for bisection over the doubles
inline std::int64_t ordered(double x) {
  std::int64_t b = std::bit_cast<std::int64_t>(x);
  return b < 0 ? std::numeric_limits<std::int64_t>::min() - b : b;
}

// the double with that ordered image
inline double fromOrdered(std::int64_t k) {
  return std::bit_cast<double>(k < 0 ? std::numeric_limits<std::int64_t>::min() - k : k);
}

// the smallest double y in [lo, hi] with pred(y), given pred(hi) and pred monotone
template <class Pred>
inline double firstTrue(double lo, double hi, Pred pred) {
  if (pred(lo)) return lo;
  std::int64_t a = ordered(lo), b = ordered(hi);  // pred false at a, true at b
  // the gap between two ordered images can exceed the int64 range: measure it unsigned
  auto gap = [&] { return static_cast<std::uint64_t>(b) - static_cast<std::uint64_t>(a); };
  while (gap() > 1) {
    std::int64_t m = static_cast<std::int64_t>(static_cast<std::uint64_t>(a) + gap() / 2);
    if (pred(fromOrdered(m)))
      b = m;
    else
      a = m;
  }
  return fromOrdered(b);
}

// Doubles exactly on the closed segment ab near a + t (b - a), searching a few ulps around
// the rounded point; the reference decides collinearity. Adds them and their ulp
// neighbours, and the rounded point with its neighbours.
inline void addOnSegment(std::vector<Vec2>& out, Vec2 a, Vec2 b, double t) {
  const Vec2 guess{a.x + t * (b.x - a.x), a.y + t * (b.y - a.y)};
  addUlpRing(out, guess);
  const double x0 = std::min(a.x, b.x), x1 = std::max(a.x, b.x);
  const double y0 = std::min(a.y, b.y), y1 = std::max(a.y, b.y);
  int found = 0;
  for (int i = -3; i <= 3 && found < 2; ++i)
    for (int j = -3; j <= 3 && found < 2; ++j) {
      Vec2 p{ulps(guess.x, i), ulps(guess.y, j)};
      if (!std::isfinite(p.x) || !std::isfinite(p.y)) continue;
      if (p.x < x0 || p.x > x1 || p.y < y0 || p.y > y1) continue;
      if (ref::cross(a, b, p) != 0) continue;
      addUlpRing(out, p);
      ++found;
    }
}

// x where the segment ab crosses height y (a.y != b.y), rounded
inline double crossingX(Vec2 a, Vec2 b, double y) {
  return a.x + (y - a.y) / (b.y - a.y) * (b.x - a.x);
}

// points on the horizontal line at height y: random x, the box sides, and a few ulps around
// where the boundary crosses that height
inline void addRow(std::vector<Vec2>& out, std::span<const Vec2> v, const Box2& box, double y,
                   convexloc::Rng& rng) {
  const double w = 0.1 * (box.hi.x - box.lo.x);
  out.push_back({box.lo.x, y});
  out.push_back({box.hi.x, y});
  for (int k = 0; k < 3; ++k) out.push_back({rng.uniform(box.lo.x - w, box.hi.x + w), y});
  const std::size_t n = v.size();
  int crossings = 0;
  for (std::size_t e = 0; e < n && crossings < 4; ++e) {
    Vec2 a = v[e], b = v[(e + 1) % n];
    if (std::min(a.y, b.y) > y || std::max(a.y, b.y) < y) continue;
    ++crossings;
    double x = a.y == b.y ? a.x : crossingX(a, b, y);
    if (!std::isfinite(x)) continue;
    for (int k = -2; k <= 2; ++k) out.push_back({ulps(x, k), y});
  }
}

// the locator-independent hard cases: vertices of the input, edges, slab heights, extremes
inline std::vector<Vec2> boundaryPoints(const convexloc::ConvexPolygon& polygon,
                                        std::span<const Vec2> input, convexloc::Rng& rng) {
  std::vector<Vec2> out;
  std::span<const Vec2> v = polygon.vertices();
  const std::size_t n = v.size();
  const Box2 box = polygon.bounds();
  // every input point (dropped ones lie on the boundary too), a sample with ulp neighbours
  out.insert(out.end(), input.begin(), input.end());
  for (std::size_t i : spread(input.size(), 512)) addUlpRing(out, input[i]);
  // points exactly on edges and one ulp off them
  const double ts[] = {0.5, 1.0 / 3, 1e-9, 1 - 1e-9};
  for (std::size_t e : spread(n, 128)) {
    for (double t : ts) addOnSegment(out, v[e], v[(e + 1) % n], t);
    addOnSegment(out, v[e], v[(e + 1) % n], rng.uniform());
  }
  // slab heights: each vertex's y and the doubles next to it
  for (std::size_t i : spread(n, 160))
    for (int k = -1; k <= 1; ++k) addRow(out, v, box, ulps(v[i].y, k), rng);
  // extreme magnitudes, signed zeros, subnormals, box corners
  const Vec2 mid{box.lo.x / 2 + box.hi.x / 2, box.lo.y / 2 + box.hi.y / 2};
  const double xs[] = {-kMax, -1e300, -1.0,      -kDenorm,   -0.0,  0.0,      kDenorm, 1.0,
                       1e300, kMax,   0x1p-1022, -0x1p-1022, mid.x, box.lo.x, box.hi.x};
  const double ys[] = {-kMax, -1e300, -1.0,      -kDenorm,   -0.0,  0.0,      kDenorm, 1.0,
                       1e300, kMax,   0x1p-1022, -0x1p-1022, mid.y, box.lo.y, box.hi.y};
  for (double x : xs)
    for (double y : ys) out.push_back({x, y});
  return out;
}

// the polar locator's hard cases: its centre, its cell borders, axes and diagonals, and
// the points of the polygon's edge lines nearest the centre
inline std::vector<Vec2> polarPoints(const convexloc::PolarLocator& polar,
                                     const convexloc::ConvexPolygon& polygon) {
  std::vector<Vec2> out;
  // without a centre, the fan's apex (vertex 0) stands in for it, as the query uses it
  const Vec2 c = polar.centre().value_or(polygon.vertex(0));
  const Box2 box = polar.box();
  addUlpRing(out, c, 2);
  const double size = std::max(box.hi.x - box.lo.x, box.hi.y - box.lo.y);
  int top = 0;
  std::frexp(std::isfinite(size) ? size : kMax, &top);
  // along the axes and diagonals, at scales from the tiniest to beyond the box
  const Vec2 dirs[] = {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}};
  for (Vec2 d : dirs)
    for (int e = top + 1; e >= std::max(top - 80, -1074); e -= 3) {
      Vec2 p{c.x + std::ldexp(d.x, e), c.y + std::ldexp(d.y, e)};
      if (std::isfinite(p.x) && std::isfinite(p.y)) addUlpRing(out, p);
    }
  for (Vec2 d : dirs) out.push_back({c.x + d.x * kDenorm, c.y + d.y * kDenorm});
  // the feet of the perpendiculars from the centre to sampled edge lines, where an edge lies
  // nearest the centre and the cells' inner radii must not reach past it; a hair either side
  {
    const std::span<const Vec2> v = polygon.vertices();
    for (std::size_t e : spread(v.size(), 96)) {
      using L = long double;
      const Vec2 a = v[e], b = v[(e + 1) % v.size()];
      const L ux = L(b.x) - a.x, uy = L(b.y) - a.y;
      const L k = ((L(c.x) - a.x) * ux + (L(c.y) - a.y) * uy) / (ux * ux + uy * uy);
      const L fx = a.x + k * ux, fy = a.y + k * uy;
      for (long double f : {1.0L - 1e-12L, 1.0L, 1.0L + 1e-12L}) {
        Vec2 p{static_cast<double>(c.x + f * (fx - c.x)), static_cast<double>(c.y + f * (fy - c.y))};
        if (std::isfinite(p.x) && std::isfinite(p.y)) addUlpRing(out, p);
      }
    }
  }
  // cell borders: along each sampled cell's lower ray, at several distances
  std::vector<convexloc::Cell2D> cells = polar.cells();
  for (std::size_t i : spread(cells.size(), 96)) {
    const convexloc::Cell2D& cell = cells[i];
    const double fractions[] = {1e-6, 0.25, 0.5, 0.999999, 1.0, 1.000001, 1.5, 3.0};
    for (double f : fractions) {
      Vec2 p{c.x + f * (cell.hitLo.x - c.x), c.y + f * (cell.hitLo.y - c.y)};
      if (std::isfinite(p.x) && std::isfinite(p.y)) addUlpRing(out, p);
    }
    // the border direction scaled by powers of two: differences from the centre near exact
    for (int e = top + 1; e >= top - 40; e -= 8) {
      Vec2 p{c.x + std::ldexp(cell.dirLo.x, e), c.y + std::ldexp(cell.dirLo.y, e)};
      if (std::isfinite(p.x) && std::isfinite(p.y)) addUlpRing(out, p);
    }
  }
  return out;
}

// the uniform locator's hard cases: the first y of each sampled slab, and the double below
inline std::vector<Vec2> uniformPoints(const convexloc::UniformLocator& uniform,
                                       const convexloc::ConvexPolygon& polygon,
                                       convexloc::Rng& rng) {
  std::vector<Vec2> out;
  const Box2 box = polygon.bounds();
  for (std::size_t s : spread(uniform.slabCount(), 160)) {
    if (s == 0) continue;
    const auto slab = static_cast<std::uint32_t>(s);
    double y = firstTrue(box.lo.y, box.hi.y, [&](double t) { return uniform.slabOf(t) >= slab; });
    addRow(out, polygon.vertices(), box, y, rng);
    addRow(out, polygon.vertices(), box, ulps(y, -1), rng);
  }
  return out;
}

// uniform queries in the box enlarged by 10% on each side, and a tenth as many spread over
// every scale around `centre` (log-uniform offsets of either sign)
inline std::vector<Vec2> randomPoints(const Box2& box, Vec2 centre, std::size_t count,
                                      convexloc::Rng& rng) {
  std::vector<Vec2> out;
  out.reserve(count + count / 10);
  const double wx = 0.1 * (box.hi.x - box.lo.x), wy = 0.1 * (box.hi.y - box.lo.y);
  for (std::size_t i = 0; i < count; ++i)
    out.push_back(
        {rng.uniform(box.lo.x - wx, box.hi.x + wx), rng.uniform(box.lo.y - wy, box.hi.y + wy)});
  auto offset = [&] {
    double m = std::ldexp(1 + rng.uniform(), static_cast<int>(rng.below(2070)) - 1074);
    return rng.below(2) ? m : -m;
  };
  for (std::size_t i = 0; i < count / 10; ++i) {
    Vec2 p{centre.x + offset(), centre.y + offset()};
    if (std::isfinite(p.x) && std::isfinite(p.y)) out.push_back(p);
  }
  return out;
}

}  // namespace adversarial
