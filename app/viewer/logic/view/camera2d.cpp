// convexloc-viewer — the 2D camera.
#include "logic/view/camera2d.hpp"

#include <algorithm>
#include <cmath>

namespace convexloc::viewer {

void Camera2D::setViewport(glm::dvec2 size) {
  viewport_ = {std::max(size.x, 1.0), std::max(size.y, 1.0)};
}

void Camera2D::set(glm::dvec2 centre, double scale) {
  centre_ = centre;
  scale_ = std::clamp(scale, kMinScale, kMaxScale);
}

glm::dvec2 Camera2D::toScreen(glm::dvec2 world) const {
  return {0.5 * viewport_.x + (world.x - centre_.x) * scale_,
          0.5 * viewport_.y - (world.y - centre_.y) * scale_};
}

glm::dvec2 Camera2D::toWorld(glm::dvec2 screen) const {
  return {centre_.x + (screen.x - 0.5 * viewport_.x) / scale_,
          centre_.y - (screen.y - 0.5 * viewport_.y) / scale_};
}

void Camera2D::pan(glm::dvec2 deltaPx) {
  centre_.x -= deltaPx.x / scale_;
  centre_.y += deltaPx.y / scale_;
}

void Camera2D::zoomAt(glm::dvec2 screen, double factor) {
  if (!(factor > 0.0) || !std::isfinite(factor)) return;
  const glm::dvec2 anchor = toWorld(screen);
  scale_ = std::clamp(scale_ * factor, kMinScale, kMaxScale);
  // put the anchor back under the cursor
  const glm::dvec2 moved = toScreen(anchor);
  pan(screen - moved);
}

void Camera2D::fit(const Box2& box, ScreenRect area, double margin) {
  double w = box.hi.x - box.lo.x, h = box.hi.y - box.lo.y;
  const glm::dvec2 mid{0.5 * box.lo.x + 0.5 * box.hi.x, 0.5 * box.lo.y + 0.5 * box.hi.y};
  // a flat box gets the other side's extent, a point a unit square
  if (!(w > 0.0) && !(h > 0.0))
    w = h = 1.0;
  else if (!(w > 0.0))
    w = h;
  else if (!(h > 0.0))
    h = w;
  w *= 1.0 + 2.0 * margin;
  h *= 1.0 + 2.0 * margin;
  glm::dvec2 size = area.size();
  if (!(size.x > 0.0) || !(size.y > 0.0)) {
    area = {{0.0, 0.0}, viewport_};
    size = viewport_;
  }
  scale_ = std::clamp(std::min(size.x / w, size.y / h), kMinScale, kMaxScale);
  // the box's middle at the area's middle
  centre_ = mid;
  const glm::dvec2 offset = area.middle() - 0.5 * viewport_;
  centre_.x -= offset.x / scale_;
  centre_.y += offset.y / scale_;
}

Box2 Camera2D::visible() const {
  const glm::dvec2 a = toWorld({0.0, viewport_.y}), b = toWorld({viewport_.x, 0.0});
  return {{a.x, a.y}, {b.x, b.y}};
}

glm::mat4 Camera2D::clipFromLocal(glm::dvec2 origin) const {
  const double sx = 2.0 * scale_ / viewport_.x, sy = 2.0 * scale_ / viewport_.y;
  glm::dmat4 m(1.0);
  m[0][0] = sx;
  m[1][1] = sy;
  m[3][0] = sx * (origin.x - centre_.x);
  m[3][1] = sy * (origin.y - centre_.y);
  return glm::mat4(m);
}

}  // namespace convexloc::viewer
