// convexloc — the polar locator's radii: per cell, two squared distances from the centre
// that decide most points before any edge test (the argument: detail/radii.hpp).
//
// A cell's inner bound is the nearest that any point of its edges seen from the cell's
// wedge can be (the lower of a bound on each edge line's distance and, where the piece of
// the edge the wedge sees stops short of the perpendicular's foot, the nearer end of that
// piece); its outer bound the farthest such point, or where every ray of the wedge meets
// one edge line ahead, however far the edge's piece reaches. Each is computed in long double
// with slack far above its rounding, then rounded outward to a float.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "convexloc/locate2d.hpp"
#include "convexloc/predicates.hpp"
#include "detail/radii.hpp"
#include "polar/index.hpp"

namespace convexloc {
namespace {

// A lower bound on the squared distance from c to the line through a and b, for c strictly
// on its inner side (0 when the doubles cannot bound it: underflow, overflow). The cross
// product's filter bound makes the numerator a lower bound; the rest is a few roundings,
// which the radius slack covers. The distance is formed before it is squared: the cross
// product squared overflows long before the distance does, and an infinite square would let
// the cell claim every point inside.
double lineDistance2Below(Vec2 a, Vec2 b, Vec2 c) {
  using detail::kCcwBound;
  const double ux = b.x - a.x, uy = b.y - a.y, wx = c.x - a.x, wy = c.y - a.y;
  const double l = ux * wy, m = uy * wx;
  const double permanent = std::fabs(l) + std::fabs(m);
  const double num = (l - m) - (kCcwBound * permanent + detail::kUnderflowSlack);
  const double len2 = ux * ux + uy * uy;
  if (!(permanent >= detail::kTinyPermanent) || !(num > 0) || !(len2 >= 0x1p-900) ||
      !(len2 <= std::numeric_limits<double>::max()))
    return 0.0;
  const double d = num / std::sqrt(len2);  // at most |c - a|, which is finite
  return d * d;  // infinity only where the true square exceeds the double range
}

// Tighter bounds for one cell and one of its edges: the points of edge (a, b) that rays from
// c with pseudo-angles in [angleLo, angleHi] (a cell's range, widened) can meet form a piece
// of it, from where the lower ray meets the edge's line to where the upper one does (the
// edge runs counter-clockwise around c). Its ends are computed in long double, moved out by
// 2^-20 of the edge, and fall back to the edge's ends where a ray misses the line or runs
// nearly along it. Over that piece the squared distance from c lies in [in2, out2]; each
// is also bounded by the whole edge's (edgeIn2, edgeOut2), and the tighter one is kept.
//
// Returns a bound on the squared distance from c to the edge's line along every ray of the
// range, where both boundary rays meet that line ahead (infinity otherwise): a ray leaves a
// convex polygon at the nearest edge line it meets ahead, so that bound alone bounds the
// exit point of every point of the cell.
double pieceBounds(Vec2 a, Vec2 b, Vec2 c, double angleLo, double angleHi, double& in2,
                   double& out2) {
  using L = long double;
  const L ux = L(b.x) - a.x, uy = L(b.y) - a.y, wx = L(a.x) - c.x, wy = L(a.y) - c.y;
  const L size = std::fabs(ux) + std::fabs(uy);
  constexpr L kMiss = std::numeric_limits<L>::infinity();
  auto along = [&](double angle) {
    const Vec2 d = polar::directionOf(angle < 0 ? angle + 8 : (angle >= 8 ? angle - 8 : angle));
    const L den = L(d.x) * uy - L(d.y) * ux;  // > 0: the ray meets the line ahead of c
    if (!(den > 0x1p-30L * (std::fabs(L(d.x)) + std::fabs(L(d.y))) * size)) return kMiss;
    return -(L(d.x) * wy - L(d.y) * wx) / den;
  };
  auto dist = [&](L t) {
    const L x = wx + t * ux, y = wy + t * uy;
    return std::sqrt(x * x + y * y);
  };
  // rounding in the ends and distances stays far below this
  const L slack = 0x1p-50L * (std::fabs(wx) + std::fabs(wy) + size);
  const L lineLo = along(angleLo), lineHi = along(angleHi);
  double line2 = HUGE_VAL;
  if (lineLo != kMiss && lineHi != kMiss) {
    // where the boundary rays meet the line (far outside the edge, possibly), each moved by
    // far more than its rounding: the guard on den keeps t's error below 2^-30 of
    // |w| / size + |t|
    auto reach = [&](L t) {
      return dist(t) + 0x1p-30L * (std::fabs(t) * size + std::fabs(wx) + std::fabs(wy) + size) +
             slack;
    };
    const L far = std::max(reach(lineLo), reach(lineHi));
    line2 = static_cast<double>(far * far);
  }
  constexpr L kWiden = 0x1p-20L;
  const L t0 = std::clamp((lineLo != kMiss ? lineLo : 0) - kWiden, L(0), L(1));
  const L t1 = std::clamp((lineHi != kMiss ? lineHi : 1) + kWiden, L(0), L(1));
  if (!(t0 <= t1)) return line2;  // keep the whole edge's bounds
  const L d0 = dist(t0), d1 = dist(t1);
  const L far = std::max(d0, d1) + slack;
  out2 = std::min(out2, static_cast<double>(far * far));
  // the nearest point: the foot of the perpendicular if the piece holds it (then the line's
  // bound stands), else the nearer end
  const L foot = -(wx * ux + wy * uy) / (ux * ux + uy * uy);
  if (!(foot >= t0 - kWiden && foot <= t1 + kWiden)) {
    const L near = std::min(d0, d1) - slack;
    if (near > 0) in2 = std::max(in2, static_cast<double>(near * near));
  }
  return line2;
}

}  // namespace

void PolarLocator::buildRadii() {
  const std::uint32_t cells = cellCount();
  const Vec2 c = index_.centre;
  const double q = index_.slabScale;
  // a cell's range in pseudo-angle, widened far beyond the query's index error (2^-50) and
  // the rounding of the directions drawn from it
  constexpr double kWidenAngle = 0x1p-30;
  radii_.resize(cells);
  for (std::uint32_t k = 0; k < cells; ++k) {
    double lo = std::numeric_limits<double>::infinity(), hi = 0.0, anyLine = HUGE_VAL;
    const double angleLo = k / q - kWidenAngle, angleHi = (k + 1) / q + kWidenAngle;
    for (std::uint32_t i = offsets_[k]; i < offsets_[k + 1]; ++i) {
      // the whole edge's bounds, then its piece's (computed per entry: no array per edge,
      // so the build's peak memory stays that of the table)
      const std::uint32_t e = entries_[i];
      const Vec2 a = vertices_[e], b = vertices_[e + 1 == vertexCount_ ? 0 : e + 1];
      double edgeIn2 = lineDistance2Below(a, b, c);
      double edgeOut2 = std::max(polar::distance2(a, c), polar::distance2(b, c));
      anyLine = std::min(anyLine, pieceBounds(a, b, c, angleLo, angleHi, edgeIn2, edgeOut2));
      lo = std::min(lo, edgeIn2);
      hi = std::max(hi, edgeOut2);
    }
    hi = std::min(hi, anyLine);
    if (offsets_[k] == offsets_[k + 1]) lo = 0.0, hi = std::numeric_limits<double>::infinity();
    radii_[k] = {detail::innerBound(lo), detail::outerBound(hi)};
  }
}

}  // namespace convexloc
