// convexloc-viewer — picking.
#include "logic/view/picking.hpp"

#include <cmath>
#include <limits>

namespace convexloc::viewer {

bool outlineContains(std::span<const Vec2> outline, Vec2 p) {
  const std::size_t n = outline.size();
  if (n < 3) return false;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec2 a = outline[i], b = outline[i + 1 == n ? 0 : i + 1];
    // a drawing test: double arithmetic, the closed side counts
    const double cross = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
    if (cross < 0.0) return false;
  }
  return true;
}

std::ptrdiff_t pickCell(std::span<const Cell2D> cells, Vec2 p) {
  for (std::size_t i = 0; i < cells.size(); ++i)
    if (outlineContains(cells[i].outline, p)) return static_cast<std::ptrdiff_t>(i);
  return -1;
}

std::ptrdiff_t pickVertex(std::span<const Vec2> vertices, const Camera2D& camera, glm::dvec2 screen,
                          double radiusPx) {
  std::ptrdiff_t best = -1;
  double bestDistance = radiusPx * radiusPx;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const glm::dvec2 d = camera.toScreen(toGlm(vertices[i])) - screen;
    const double dd = glm::dot(d, d);
    if (dd <= bestDistance) {
      bestDistance = dd;
      best = static_cast<std::ptrdiff_t>(i);
    }
  }
  return best;
}

std::ptrdiff_t pickPoint(std::span<const Vec2> points, std::span<const Location> classes,
                         unsigned visibleMask, const Camera2D& camera, glm::dvec2 screen,
                         double radiusPx) {
  // compare in world units: one conversion of the cursor instead of one per point
  const glm::dvec2 w = camera.toWorld(screen);
  const double r = radiusPx * camera.worldPerPixel();
  double best = r * r;
  std::ptrdiff_t found = -1;
  const std::size_t n = std::min(points.size(), classes.size());
  for (std::size_t i = 0; i < n; ++i) {
    if (!(visibleMask & classBit(classes[i]))) continue;
    const double dx = points[i].x - w.x, dy = points[i].y - w.y;
    const double dd = dx * dx + dy * dy;
    if (dd <= best) {
      best = dd;
      found = static_cast<std::ptrdiff_t>(i);
    }
  }
  return found;
}

}  // namespace convexloc::viewer
