// convexloc (internal) — the radius filter shared by the polar and cubemap locators.
//
// A cell of a centred subdivision lists every edge (face) that a point mapped to it can exit
// through. If p is nearer to the centre than every point of those edges (faces) that the
// cell's wedge (pyramid) sees, its ray leaves the shape beyond p: p is inside. If p is
// farther than a bound on where any ray of the cell leaves (the farthest of those points,
// or of one line (plane) every ray of the cell meets ahead: a ray leaves a convex shape at
// the nearest it meets), p is outside. Each cell stores those two squared distances as
// floats, rounded outward with a relative slack far above the few ulps of error of the
// query's d^2 and of the build's estimates; a point between them goes on to the exact
// tests. The answer is therefore exact, and most points of a large shape are decided by one
// 8-byte load.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>

#include "convexloc/geometry.hpp"

namespace convexloc::detail {

// relative slack on every squared radius (the errors it covers are below 2^-48)
inline constexpr double kRadiusSlack = 0x1p-30;

// the largest float not above x (0 for x <= 0 or NaN)
inline float floatBelow(double x) noexcept {
  if (!(x > 0)) return 0.0f;
  if (x >= static_cast<double>(std::numeric_limits<float>::max()))
    return std::numeric_limits<float>::max();
  float f = static_cast<float>(x);
  if (static_cast<double>(f) > x) f = std::nextafter(f, 0.0f);
  return f;
}

// the smallest float not below x (infinity for larger values and NaN)
inline float floatAbove(double x) noexcept {
  if (!(x <= static_cast<double>(std::numeric_limits<float>::max())))
    return std::numeric_limits<float>::infinity();
  float f = static_cast<float>(x);
  if (static_cast<double>(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

// the stored inner bound for a cell whose nearest line (plane) lies at squared distance x
inline float innerBound(double x) noexcept {
  return floatBelow(x * (1.0 - kRadiusSlack));
}
// below this, squared distances computed in doubles may have underflowed (to 0 even); an
// outer bound is never stored smaller, and a point is decided outside only when its own d^2,
// then computed without underflow, exceeds it
inline constexpr double kSmallestOuterBound = 0x1p-140;

// the stored outer bound for a cell whose farthest endpoint lies at squared distance x
inline float outerBound(double x) noexcept {
  return floatAbove(std::max(x * (1.0 + kRadiusSlack), kSmallestOuterBound));
}

// Whether the radii decide a point at squared distance d2: nearer than in2 or farther than
// out2. As one comparison of a product, so that the compiler emits one branch, which most
// points take, rather than two that random points mispredict: the signs of the two
// differences are exact, and a product that underflows to 0 only leaves a point undecided.
inline bool radiiDecide(double d2, float in2, float out2) noexcept {
  return (d2 - static_cast<double>(in2)) * (d2 - static_cast<double>(out2)) > 0;
}

// Outside when `farther`, else Inside, without a branch (the two come at random)
inline Location insideOrOutside(bool farther) noexcept {
  static_assert(static_cast<int>(Location::Inside) == 0 &&
                static_cast<int>(Location::Outside) == 2);
  return static_cast<Location>(2 * static_cast<int>(farther));
}

}  // namespace convexloc::detail
