// convexloc — exact geometric predicates.
//
// Each predicate first evaluates in double precision with a proven error bound
// (Shewchuk's orient2d bound, with guards for overflow and underflow, where the bound
// does not hold) and, only when that cannot decide the sign, recomputes exactly: with
// integers of at most 192 bits where the coordinates are close in scale, with floating-point
// expansions on the stack elsewhere in the ordinary exponent range (neither allocates), with
// multiprecision integers for extreme exponents (predicates.cpp states the ranges). The sign
// returned is the sign of the exact real value for the doubles given.
#pragma once

#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <limits>

#include "convexloc/geometry.hpp"

namespace convexloc {

namespace detail {
// unit roundoff of binary64 (half an ulp of 1)
inline constexpr double kEps = 0x1p-53;
// Shewchuk's bound for a 2x2 determinant of differences: |error| <= kCcwBound * permanent
inline constexpr double kCcwBound = (3.0 + 16.0 * kEps) * kEps;
// below this permanent a product may have underflowed, and the bound above does not hold
inline constexpr double kTinyPermanent = 0x1p-960;
// absolute slack for products that underflow: each errs by at most 2^-1075 (half the smallest
// subnormal) beyond its relative rounding, and this is eight times that
inline constexpr double kUnderflowSlack = 0x1p-1072;

// exact sign of (p1 - p0) x (q1 - q0) for finite doubles (the exact stage, predicates.cpp)
int crossExact(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1) noexcept;

// sign of (p1 - p0) x (q1 - q0): the filter, then the exact fallback when it cannot decide
inline int crossFiltered(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1) noexcept {
  double left = (p1.x - p0.x) * (q1.y - q0.y);
  double right = (p1.y - p0.y) * (q1.x - q0.x);
  double det = left - right;
  double permanent = std::fabs(left) + std::fabs(right);
  // A difference of doubles is exact where it underflows, and each product errs by at most
  // 2^-1075 beyond its relative rounding where it does, so kUnderflowSlack (four times the two
  // products' worst) keeps the bound valid at any finite permanent: a point a subnormal step
  // off an edge on the x axis is decided here.
  if (permanent <= std::numeric_limits<double>::max()) {  // false for NaN and infinity
    const double bound = kCcwBound * permanent + kUnderflowSlack;
    if (det > bound) return 1;
    if (-det > bound) return -1;
    if (permanent == 0.0 && (p1.x == p0.x || q1.y == q0.y) && (p1.y == p0.y || q1.x == q0.x))
      return 0;  // both products are exact zeros (axis-aligned data), not underflow
  }
  return crossExact(p0, p1, q0, q1);
}
}  // namespace detail

// Sign of (a - c) x (b - c): +1 when a, b, c turn counter-clockwise, -1 clockwise,
// 0 when exactly collinear.
inline int orient2d(Vec2 a, Vec2 b, Vec2 c) noexcept {
  return detail::crossFiltered(c, a, c, b);
}

// Sign of the cross product (b - a) x (d - c) of two segment directions.
inline int crossDiff2d(Vec2 a, Vec2 b, Vec2 c, Vec2 d) noexcept {
  return detail::crossFiltered(a, b, c, d);
}

namespace detail {
// Shewchuk's bound for the 3x3 determinant of differences: |error| <= kO3dBound * permanent
inline constexpr double kO3dBound = (7.0 + 56.0 * kEps) * kEps;

// exact sign of det[a-d; b-d; c-d] for finite doubles (the exact stage, predicates.cpp)
int orient3dExact(Vec3 a, Vec3 b, Vec3 c, Vec3 d) noexcept;

struct Orient3dTerms;
// where orient3d's filter cannot decide: the filter once more with room for underflow when no
// difference is over 2^250, then the exact stage (predicates.cpp)
int orient3dUntame(Vec3 a, Vec3 b, Vec3 c, Vec3 d, const Orient3dTerms& t) noexcept;

// a difference whose products in the 3D filter can neither underflow nor overflow
inline bool tame3d(double v) noexcept {
  const double a = std::fabs(v);
  return a == 0.0 || (a >= 0x1p-250 && a <= 0x1p250);
}

// whether all nine differences are tame: one test of the largest and one of the smallest
// magnitude, then each in turn only where one is zero (a shared coordinate) or tiny
inline bool tame3dAll(double a0, double a1, double a2, double a3, double a4, double a5, double a6,
                      double a7, double a8) noexcept {
  const double m0 = std::fabs(a0), m1 = std::fabs(a1), m2 = std::fabs(a2), m3 = std::fabs(a3),
               m4 = std::fabs(a4), m5 = std::fabs(a5), m6 = std::fabs(a6), m7 = std::fabs(a7),
               m8 = std::fabs(a8);
  // pairwise, not in a chain: the same values (no NaN: differences of finite doubles), a
  // shorter dependency for the hot face tests
  const double hi = std::max(std::max(std::max(m0, m1), std::max(m2, m3)),
                             std::max(std::max(m4, m5), std::max(m6, std::max(m7, m8))));
  const double lo = std::min(std::min(std::min(m0, m1), std::min(m2, m3)),
                             std::min(std::min(m4, m5), std::min(m6, std::min(m7, m8))));
  if (!(hi <= 0x1p250)) return false;
  if (lo >= 0x1p-250) return true;
  bool all = true;
  for (double a : {a0, a1, a2, a3, a4, a5, a6, a7, a8}) all = all && tame3d(a);
  return all;
}

// The floating-point terms of orient3d's filter: the determinant, its permanent, and
// whether every difference is tame (then |error| <= kO3dBound * permanent).
struct Orient3dTerms {
  double det, permanent;
  bool tame;
};
inline Orient3dTerms orient3dTerms(Vec3 a, Vec3 b, Vec3 c, Vec3 d) noexcept {
  const double adx = a.x - d.x, ady = a.y - d.y, adz = a.z - d.z;
  const double bdx = b.x - d.x, bdy = b.y - d.y, bdz = b.z - d.z;
  const double cdx = c.x - d.x, cdy = c.y - d.y, cdz = c.z - d.z;
  const double bdxcdy = bdx * cdy, cdxbdy = cdx * bdy;
  const double cdxady = cdx * ady, adxcdy = adx * cdy;
  const double adxbdy = adx * bdy, bdxady = bdx * ady;
  return {adz * (bdxcdy - cdxbdy) + bdz * (cdxady - adxcdy) + cdz * (adxbdy - bdxady),
          (std::fabs(bdxcdy) + std::fabs(cdxbdy)) * std::fabs(adz) +
              (std::fabs(cdxady) + std::fabs(adxcdy)) * std::fabs(bdz) +
              (std::fabs(adxbdy) + std::fabs(bdxady)) * std::fabs(cdz),
          tame3dAll(adx, ady, adz, bdx, bdy, bdz, cdx, cdy, cdz)};
}
// whether the terms decide the sign (then it is the sign of det, never 0)
inline bool orient3dSure(const Orient3dTerms& t) noexcept {
  return t.tame && std::fabs(t.det) > kO3dBound * t.permanent;
}
}  // namespace detail

// Sign of the determinant | a-d ; b-d ; c-d |: +1 when d lies below the plane through
// a, b, c oriented counter-clockwise seen from above (Shewchuk's convention), 0 when coplanar.
// The filter is inline (the hot face tests of the 3D locators inline it); the exact fallback
// is not.
inline int orient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d) noexcept {
  const detail::Orient3dTerms t = detail::orient3dTerms(a, b, c, d);
  if (detail::orient3dSure(t)) return t.det > 0 ? 1 : -1;
  // tame differences cannot underflow: a zero permanent means every term is exactly zero
  if (t.tame && t.permanent == 0.0) return 0;
  return detail::orient3dUntame(a, b, c, d, t);
}

namespace detail {
// orient3d(a, b, k, d) for one a, b, d and many k (a bisection around the axis through a and
// b): det[a - d; b - d; k - d] = (k - d) . w with w = (a - d) x (b - d) computed once. The
// filter is orient3d's: the same operations (a difference times a difference of two products
// of differences, three such terms summed left to right) with the roles of the rows exchanged,
// which Shewchuk's bound kO3dBound * permanent does not see; the exact stage is orient3d.
class Orient3dAround {
 public:
  Orient3dAround(Vec3 a, Vec3 b, Vec3 d) noexcept : a_(a), b_(b), d_(d) {
    const double ax = a.x - d.x, ay = a.y - d.y, az = a.z - d.z;
    const double bx = b.x - d.x, by = b.y - d.y, bz = b.z - d.z;
    const double yz = ay * bz, zy = az * by, zx = az * bx, xz = ax * bz, xy = ax * by, yx = ay * bx;
    w_[0] = yz - zy, w_[1] = zx - xz, w_[2] = xy - yx;
    m_[0] = std::fabs(yz) + std::fabs(zy), m_[1] = std::fabs(zx) + std::fabs(xz),
    m_[2] = std::fabs(xy) + std::fabs(yx);
    tame_ = tame3d(ax) && tame3d(ay) && tame3d(az) && tame3d(bx) && tame3d(by) && tame3d(bz);
  }
  // the exact sign of orient3d(a, b, k, d)
  int operator()(Vec3 k) const noexcept {
    const double kx = k.x - d_.x, ky = k.y - d_.y, kz = k.z - d_.z;
    const double det = kx * w_[0] + ky * w_[1] + kz * w_[2];
    const double permanent = std::fabs(kx) * m_[0] + std::fabs(ky) * m_[1] + std::fabs(kz) * m_[2];
    if (tame_ && tame3d(kx) && tame3d(ky) && tame3d(kz) && std::fabs(det) > kO3dBound * permanent)
      return det > 0 ? 1 : -1;
    return orient3d(a_, b_, k, d_);
  }

 private:
  Vec3 a_, b_, d_;
  double w_[3], m_[3];  // the cross product and its permanents
  bool tame_;
};
}  // namespace detail

// How many times the exact fallback ran in this thread (for tests and statistics).
unsigned long long exactFallbackCount() noexcept;

// The exact fallbacks of this thread by the stage that decided them: integers of at most 192
// bits (coordinates within 61 bits of each other), floating-point expansions (the ordinary
// exponent range), multiprecision integers (extreme exponents; the only stage that allocates).
struct ExactStageCounts {
  unsigned long long narrowIntegers, expansions, multiprecision;
};
ExactStageCounts exactStageCounts() noexcept;

}  // namespace convexloc
