// convexloc-viewer — a rectangle of window pixels: the scene's area, a panel, a plot.
#pragma once

#include <glm/glm.hpp>

namespace convexloc::viewer {

// a rectangle in window pixels (y grows downward)
struct ScreenRect {
  glm::dvec2 lo{0.0, 0.0};
  glm::dvec2 hi{0.0, 0.0};
  glm::dvec2 size() const { return hi - lo; }
  glm::dvec2 middle() const { return 0.5 * (lo + hi); }
  bool contains(glm::dvec2 p) const {
    return p.x >= lo.x && p.x < hi.x && p.y >= lo.y && p.y < hi.y;
  }
};

// Liang-Barsky: the part t0 <= t <= t1 of the segment a + t (b - a), 0 <= t <= 1, inside the
// rectangle lo..hi (window pixels, for drawing only); false when the segment misses it
inline bool clipSegment(glm::dvec2 a, glm::dvec2 b, glm::dvec2 lo, glm::dvec2 hi, double& t0,
                        double& t1) {
  t0 = 0.0;
  t1 = 1.0;
  const glm::dvec2 d = b - a;
  const double p[4] = {-d.x, d.x, -d.y, d.y};
  const double q[4] = {a.x - lo.x, hi.x - a.x, a.y - lo.y, hi.y - a.y};
  for (int i = 0; i < 4; ++i) {
    if (p[i] == 0.0) {
      if (q[i] < 0.0) return false;
      continue;
    }
    const double t = q[i] / p[i];
    if (p[i] < 0.0)
      t0 = t > t0 ? t : t0;
    else
      t1 = t < t1 ? t : t1;
    if (t0 > t1) return false;
  }
  return true;
}

}  // namespace convexloc::viewer
