// An independent exact reference for the 2D tests. It shares no code with core's predicates,
// polygon or locators: every sign comes from this file, in rational arithmetic (GMP mpq).
//
// The filters. cross(o, a, b) is the sign of (a - o) x (b - o). It is evaluated in two
// floating-point stages before exact rationals, each trusted only with a margin far above
// its true error:
//   1. double: kept when 1e-250 <= permanent <= 1e300 and |det| > 1e-10 * permanent, where
//      permanent = |(a.x - o.x)(b.y - o.y)| + |(a.y - o.y)(b.x - o.x)| as computed. While
//      nothing overflows, each difference is rounded once (a difference landing in the
//      subnormal range is exact), each product once and det once, so the computed det is
//      within about 4 * 2^-53 * permanent (< 5e-16 * permanent) of the true value, plus at
//      most 2^-1074 per underflowed product, negligible against 1e-10 * 1e-250. A NaN or
//      infinite permanent fails the range test.
//   2. x87 long double (64-bit significand, 15-bit exponent), only where it has that
//      format: every difference and product of finite doubles is then a normal number (no
//      overflow, no underflow: 2^-2148 and 2^2050 are far inside its range), so the computed
//      det is within about 4 * 2^-64 * permanent (< 3e-19 * permanent) of the true value;
//      kept when |det| > 1e-12 * permanent.
//   3. anything else: mpq_class, exact.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

#include "convexloc/geometry.hpp"

namespace ref {

using convexloc::Location;
using convexloc::Vec2;

// relative margin the double filter must clear
inline constexpr double kFilterMargin = 1e-10;
// permanents outside [kFilterFloor, kFilterCeiling] skip the double stage
inline constexpr double kFilterFloor = 1e-250;
inline constexpr double kFilterCeiling = 1e300;
// relative margin the long double stage must clear
inline constexpr long double kWideMargin = 1e-12L;
// the long double stage runs only where long double is the x87 extended format
inline constexpr bool kWideStage = std::numeric_limits<long double>::digits >= 64 &&
                                   std::numeric_limits<long double>::max_exponent >= 16384;

// the sign of a rational
inline int sign(const mpq_class& q) {
  return mpq_sgn(q.get_mpq_t());
}

// exact sign of (a - o) x (b - o), in rationals only
inline int crossRational(Vec2 o, Vec2 a, Vec2 b) {
  const mpq_class ox(o.x), oy(o.y);
  const mpq_class ax = mpq_class(a.x) - ox, ay = mpq_class(a.y) - oy;
  const mpq_class bx = mpq_class(b.x) - ox, by = mpq_class(b.y) - oy;
  return sign(mpq_class(ax * by - ay * bx));
}

// the sign of l - r from the double stage, 0 when it cannot tell
inline int doubleStage(double l, double r) {
  const double det = l - r;
  const double permanent = std::fabs(l) + std::fabs(r);
  if (permanent >= kFilterFloor && permanent <= kFilterCeiling) {
    if (det > kFilterMargin * permanent) return 1;
    if (det < -kFilterMargin * permanent) return -1;
  }
  return 0;
}

// the sign of l - r from the long double stage, 0 when it cannot tell
inline int wideStage(long double l, long double r) {
  if constexpr (kWideStage) {
    const long double det = l - r;
    const long double permanent = std::fabs(l) + std::fabs(r);
    if (det > kWideMargin * permanent) return 1;
    if (det < -kWideMargin * permanent) return -1;
  }
  return 0;
}

// exact sign of (a - o) x (b - o): the filters, else rationals
inline int cross(Vec2 o, Vec2 a, Vec2 b) {
  if (int s = doubleStage((a.x - o.x) * (b.y - o.y), (a.y - o.y) * (b.x - o.x))) return s;
  using W = long double;
  if (int s =
          wideStage((W(a.x) - W(o.x)) * (W(b.y) - W(o.y)), (W(a.y) - W(o.y)) * (W(b.x) - W(o.x))))
    return s;
  return crossRational(o, a, b);
}

// exact sign of the direction cross product d x (v - c), with d a direction and c an origin
// (the same filters: here only one factor of each product is a rounded difference)
inline int crossDirection(Vec2 c, Vec2 d, Vec2 v) {
  if (int s = doubleStage(d.x * (v.y - c.y), d.y * (v.x - c.x))) return s;
  using W = long double;
  if (int s = wideStage(W(d.x) * (W(v.y) - W(c.y)), W(d.y) * (W(v.x) - W(c.x)))) return s;
  const mpq_class vx = mpq_class(v.x) - mpq_class(c.x), vy = mpq_class(v.y) - mpq_class(c.y);
  return sign(mpq_class(mpq_class(d.x) * vy - mpq_class(d.y) * vx));
}

// the sign of point p against edge e of a counter-clockwise ring: > 0 on the inner side
inline int edgeSign(std::span<const Vec2> ccw, std::size_t e, Vec2 p) {
  return cross(ccw[e], ccw[(e + 1) % ccw.size()], p);
}

// Where p lies with respect to the closed polygon whose strictly convex, counter-clockwise
// vertices are `ccw`: inside iff strictly on the inner side of every edge line, boundary iff
// on the inner side or on the line of every edge and on at least one line.
inline Location locate(std::span<const Vec2> ccw, Vec2 p) {
  bool onLine = false;
  for (std::size_t e = 0; e < ccw.size(); ++e) {
    const int s = edgeSign(ccw, e, p);
    if (s < 0) return Location::Outside;
    onLine |= s == 0;
  }
  return onLine ? Location::Boundary : Location::Inside;
}

// lexicographic order by x, then y
inline bool lexLess(Vec2 a, Vec2 b) {
  return a.x < b.x || (a.x == b.x && a.y < b.y);
}

// The strictly convex hull of `points`, counter-clockwise, starting at the lexicographically
// smallest point (Andrew's monotone chain over exact signs). Fewer than 3 points when the
// points are all collinear.
inline std::vector<Vec2> hull(std::span<const Vec2> points) {
  std::vector<Vec2> p(points.begin(), points.end());
  std::sort(p.begin(), p.end(), lexLess);
  p.erase(std::unique(p.begin(), p.end()), p.end());
  if (p.size() < 3) return p;
  std::vector<Vec2> lower, upper;
  for (Vec2 q : p) {
    while (lower.size() >= 2 && cross(lower[lower.size() - 2], lower.back(), q) <= 0)
      lower.pop_back();
    lower.push_back(q);
  }
  for (auto it = p.rbegin(); it != p.rend(); ++it) {
    while (upper.size() >= 2 && cross(upper[upper.size() - 2], upper.back(), *it) <= 0)
      upper.pop_back();
    upper.push_back(*it);
  }
  lower.pop_back();
  upper.pop_back();
  lower.insert(lower.end(), upper.begin(), upper.end());
  if (lower.size() < 3) lower.resize(std::min<std::size_t>(lower.size(), 2));
  return lower;
}

// a and b are the same cyclic sequence (one is a rotation of the other)
inline bool sameCycle(std::span<const Vec2> a, std::span<const Vec2> b) {
  if (a.size() != b.size()) return false;
  if (a.empty()) return true;
  const std::size_t n = a.size();
  for (std::size_t shift = 0; shift < n; ++shift) {
    if (!(b[shift] == a[0])) continue;
    bool all = true;
    for (std::size_t i = 0; i < n && all; ++i) all = a[i] == b[(i + shift) % n];
    if (all) return true;
  }
  return false;
}

// every turn of the ring is strictly counter-clockwise
inline bool strictlyConvexTurns(std::span<const Vec2> ring) {
  const std::size_t n = ring.size();
  for (std::size_t i = 0; i < n; ++i)
    if (cross(ring[(i + n - 1) % n], ring[i], ring[(i + 1) % n]) <= 0) return false;
  return true;
}

}  // namespace ref
