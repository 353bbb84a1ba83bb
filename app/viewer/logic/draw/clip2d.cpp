// convexloc-viewer — boxes and lines clipped to them, for drawing.
#include "logic/draw/clip2d.hpp"

#include <algorithm>
#include <cmath>

namespace convexloc::viewer {

Box2 grow(const Box2& b, double fraction) {
  const double wx = fraction * (b.hi.x - b.lo.x), wy = fraction * (b.hi.y - b.lo.y);
  return {{b.lo.x - wx, b.lo.y - wy}, {b.hi.x + wx, b.hi.y + wy}};
}

bool clipLineToBox(glm::dvec2 a, glm::dvec2 b, const Box2& box, glm::dvec2& p, glm::dvec2& q) {
  // Liang and Barsky on the infinite line a + t (b - a)
  const glm::dvec2 d = b - a;
  double t0 = -INFINITY, t1 = INFINITY;
  auto clip = [&](double denom, double num) {
    // keep the part where denom * t <= num
    if (denom == 0.0) return num >= 0.0;
    const double t = num / denom;
    if (denom > 0.0)
      t1 = std::min(t1, t);
    else
      t0 = std::max(t0, t);
    return true;
  };
  if (!clip(-d.x, a.x - box.lo.x) || !clip(d.x, box.hi.x - a.x) || !clip(-d.y, a.y - box.lo.y) ||
      !clip(d.y, box.hi.y - a.y))
    return false;
  if (!(t0 <= t1) || !std::isfinite(t0) || !std::isfinite(t1)) return false;
  p = a + t0 * d;
  q = a + t1 * d;
  return true;
}

}  // namespace convexloc::viewer
