// convexloc — how large a refused fold is, for the message: the angle between two triangles
// across a reflex edge, how far the far corner lies off the other's plane, and whether the
// rounding of the coordinates (float32, or double) can explain it.
//
// The bound. Let the four corners be rounded copies of points in convex position (exactly
// flat at the edge, in the worst case), each coordinate off by at most half a unit in the
// last place u of the largest coordinate M: each corner by at most e = sqrt(3) u / 2. Write q's
// foot on the plane of (a, b, p) as la a + lb b + lp p (la + lb + lp = 1). Moving a, b and p
// moves the plane at that foot by at most (|la| + |lb| + |lp|) e, to first order, and moving
// q moves it by e: a fold whose far corner lies farther off than (1 + |la| + |lb| + |lp|) e
// cannot come from rounding alone. All of this is floating point: it words a message and
// decides nothing about the shape, which exact orient3d has already refused.
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>

#include "detail/polyhedron_build.hpp"

namespace convexloc::detail {
namespace {

struct Wide {
  long double x, y, z;
};

Wide minus(Vec3 a, Vec3 b) {
  return {static_cast<long double>(a.x) - b.x, static_cast<long double>(a.y) - b.y,
          static_cast<long double>(a.z) - b.z};
}
long double dot(Wide a, Wide b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
Wide cross(Wide a, Wide b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
long double norm(Wide a) {
  return std::sqrt(dot(a, a));
}

// v is exactly a float32 (through a volatile: GCC 12's vectorizer may fold the round trip)
bool isFloat(double v) {
  if (!(std::fabs(v) <= static_cast<double>(std::numeric_limits<float>::max()))) return false;
  volatile float f = static_cast<float>(v);
  return static_cast<double>(f) == v;
}

}  // namespace

Fold measureFold(Vec3 a, Vec3 b, Vec3 p, Vec3 q) {
  const Wide u = minus(b, a), w = minus(p, a), r = minus(q, a);
  const Wide n1 = cross(u, w), n2 = cross(minus(a, b), minus(q, b));
  Fold fold;
  fold.off = std::fabs(dot(n1, r)) / norm(n1);
  fold.degrees = std::atan2(norm(cross(n1, n2)), dot(n1, n2)) * 180 / 3.14159265358979323846L;
  // q's foot in the coordinates of u and w (the Gram system), then its weights on a, b, p
  const long double uu = dot(u, u), uw = dot(u, w), ww = dot(w, w);
  const long double det = uu * ww - uw * uw, ur = dot(u, r), wr = dot(w, r);
  const long double lb = (ur * ww - wr * uw) / det, lp = (wr * uu - ur * uw) / det;
  const long double weights = 1 + std::fabs(1 - lb - lp) + std::fabs(lb) + std::fabs(lp);
  double largest = 0;
  fold.float32 = true;
  for (const Vec3 c : {a, b, p, q})
    for (const double x : {c.x, c.y, c.z}) {
      largest = std::fmax(largest, std::fabs(x));
      fold.float32 = fold.float32 && isFloat(x);
    }
  const int digits = fold.float32 ? 24 : 53;
  const long double unit = std::ldexp(1.0L, std::ilogb(largest) + 1 - digits);
  fold.rounding = weights * std::sqrt(3.0L) / 2 * unit;
  return fold;
}

std::string roundingVerdict(const Fold& fold) {
  return std::string(fold.off <= fold.rounding ? "within" : "beyond") + " the rounding of " +
         (fold.float32 ? "float32" : "double") + " coordinates";
}

std::string describeFold(const Fold& fold) {
  char text[256];
  const char* kind = fold.float32 ? "float32" : "double";
  if (fold.off <= fold.rounding) {
    std::snprintf(text, sizeof text, "a fold of %.2Lg degrees, %.2Lg off the plane: ", fold.degrees,
                  fold.off);
    return std::string(text) + "within the rounding of " + kind + " coordinates, " +
           (fold.float32 ? "a float32 STL rounding fold: --hull is safe"
                         : "a rounding fold: --hull is safe") +
           " (hull=True in Python)";
  }
  std::snprintf(text, sizeof text,
                "a fold of %.2Lg degrees, %.2Lg off the plane: beyond the rounding of %s "
                "coordinates, a real dent (--hull would fill a dent of %.2Lg degrees; hull=True in "
                "Python)",
                fold.degrees, fold.off, kind, fold.degrees);
  return text;
}

}  // namespace convexloc::detail
