// convexloc-viewer — the 3D orbit camera.
#include "logic/view/camera3d.hpp"

#include <algorithm>
#include <cmath>

namespace convexloc::viewer {
namespace {
constexpr double kPitchLimit = 1.55;  // just short of straight up or down
constexpr double kRadiansPerPixel = 0.008;
}  // namespace

void Camera3D::setViewport(glm::dvec2 size) {
  viewport_ = {std::max(size.x, 1.0), std::max(size.y, 1.0)};
}

void Camera3D::set(glm::dvec3 target, double distance, double yaw, double pitch) {
  target_ = target;
  distance_ = std::max(distance, 1e-300);
  yaw_ = yaw;
  pitch_ = std::clamp(pitch, -kPitchLimit, kPitchLimit);
}

glm::dvec3 Camera3D::forward() const {
  // from the eye toward the target: yaw turns it about z (yaw 0 looks along -x), pitch
  // tilts it down
  return {-std::cos(pitch_) * std::cos(yaw_), -std::cos(pitch_) * std::sin(yaw_),
          -std::sin(pitch_)};
}

glm::dvec3 Camera3D::right() const {
  return {-std::sin(yaw_), std::cos(yaw_), 0.0};
}

glm::dvec3 Camera3D::up() const {
  return glm::cross(right(), forward());
}

glm::dvec3 Camera3D::eye() const {
  return target_ - distance_ * forward();
}

void Camera3D::applyAsked(const AskedCamera& asked) {
  if (asked.look) {
    // the fitted picture's shift is the fitted target's: the asked target at the area's middle
    target_ = *asked.look;
  }
  if (asked.distance && *asked.distance > 0.0) distance_ = *asked.distance;
}

void Camera3D::lookAlong(glm::dvec3 direction) {
  const double across = std::hypot(direction.x, direction.y);
  if (!(across > 0.0) && !(std::abs(direction.z) > 0.0)) return;
  // forward() = (-cos p cos y, -cos p sin y, -sin p)
  if (across > 0.0) yaw_ = std::atan2(-direction.y, -direction.x);
  pitch_ = std::clamp(std::atan2(-direction.z, across), -kPitchLimit, kPitchLimit);
}

void Camera3D::orbit(glm::dvec2 deltaPx) {
  yaw_ -= deltaPx.x * kRadiansPerPixel;
  pitch_ = std::clamp(pitch_ + deltaPx.y * kRadiansPerPixel, -kPitchLimit, kPitchLimit);
}

void Camera3D::pan(glm::dvec2 deltaPx) {
  // world units per pixel at the target's depth
  const double perPixel = 2.0 * distance_ * std::tan(0.5 * fovY_) / viewport_.y;
  target_ -= right() * (deltaPx.x * perPixel);
  target_ += up() * (deltaPx.y * perPixel);
}

void Camera3D::zoom(double factor) {
  if (!(factor > 0.0) || !std::isfinite(factor)) return;
  distance_ = std::clamp(distance_ / factor, sceneRadius_ * 1e-6, sceneRadius_ * 1e3);
}

void Camera3D::fit(const Bounds3& box, ScreenRect area) {
  double r = box.radius();
  if (!(r > 0.0)) r = 1.0;
  sceneRadius_ = r;
  target_ = box.middle();
  glm::dvec2 size = area.size();
  if (!(size.x > 0.0) || !(size.y > 0.0)) {
    area = {{0.0, 0.0}, viewport_};
    size = viewport_;
  }
  // the sphere must fit the smaller of the area's two angular extents
  const double halfY = std::atan(std::tan(0.5 * fovY_) * size.y / viewport_.y);
  const double halfX = std::atan(std::tan(0.5 * fovY_) * size.x / viewport_.y);
  distance_ = 1.08 * r / std::sin(std::min(halfX, halfY));
  areaShift_ = area.middle() - 0.5 * viewport_;
}

void Camera3D::fitCorners(std::span<const Bounds3> boxes, ScreenRect area) {
  if (boxes.empty()) return;
  Bounds3 all = boxes[0];
  for (const Bounds3& b : boxes) all = {glm::min(all.lo, b.lo), glm::max(all.hi, b.hi)};
  fit(all, area);  // the target, the area's shift and a distance that surely holds them
  const glm::dvec2 size = area.size();
  if (!(size.x > 0.0) || !(size.y > 0.0)) return;
  const double tanY = std::tan(0.5 * fovY_) * size.y / viewport_.y;
  const double tanX = std::tan(0.5 * fovY_) * size.x / viewport_.y;
  const glm::dvec3 f = forward(), s = right(), u = up();
  double needed = 0.0, nearest = 0.0;
  for (int k = 0; k < 8 * static_cast<int>(boxes.size()); ++k) {
    const Bounds3& box = boxes[static_cast<std::size_t>(k / 8)];
    const glm::dvec3 corner{(k & 1) ? box.hi.x : box.lo.x, (k & 2) ? box.hi.y : box.lo.y,
                            (k & 4) ? box.hi.z : box.lo.z};
    const glm::dvec3 c = corner - target_;
    const double depth = glm::dot(c, f);  // beyond the target: positive
    // the corner at depth distance + depth must project within the area's half-angles
    needed = std::max(
        {needed, std::abs(glm::dot(c, s)) / tanX - depth, std::abs(glm::dot(c, u)) / tanY - depth});
    nearest = std::max(nearest, -depth);
  }
  // a margin, and the eye never among the corners
  const double d = std::max(1.04 * needed, 1.5 * nearest);
  if (d > 0.0 && d < distance_) distance_ = d;
}

void Camera3D::fitPoints(std::span<const glm::dvec3> points, ScreenRect area, double fill) {
  const glm::dvec2 room = area.size();
  if (points.empty() || !(room.x > 0.0) || !(room.y > 0.0)) return;
  // the drawn box: false where a point is behind the eye
  const auto drawnBox = [&](ScreenRect& box) {
    box = {glm::dvec2(1e300), glm::dvec2(-1e300)};
    for (const glm::dvec3& p : points) {
      const Projected q = toScreen(p);
      if (!q.visible()) return false;
      box.lo = glm::min(box.lo, q.screen);
      box.hi = glm::max(box.hi, q.screen);
    }
    return box.hi.x > box.lo.x && box.hi.y > box.lo.y;
  };
  // a few rounds: the drawn size goes about as the distance's inverse
  for (int round = 0; round < 4; ++round) {
    ScreenRect box;
    if (!drawnBox(box)) return;
    const glm::dvec2 size = box.size();
    const double grow = fill * std::min(room.x / size.x, room.y / size.y);
    distance_ = std::max(distance_ / grow, 1.2 * sceneRadius_);
    if (!drawnBox(box)) return;
    areaShift_ += area.middle() - box.middle();
  }
}

glm::dmat4 Camera3D::viewFromLocal(glm::dvec3 origin) const {
  const glm::dvec3 f = forward(), s = right(), u = up();
  const glm::dvec3 e = eye() - origin;
  glm::dmat4 m(1.0);
  m[0][0] = s.x;
  m[1][0] = s.y;
  m[2][0] = s.z;
  m[0][1] = u.x;
  m[1][1] = u.y;
  m[2][1] = u.z;
  m[0][2] = -f.x;
  m[1][2] = -f.y;
  m[2][2] = -f.z;
  m[3][0] = -glm::dot(s, e);
  m[3][1] = -glm::dot(u, e);
  m[3][2] = glm::dot(f, e);
  return m;
}

glm::dmat4 Camera3D::clipFromView() const {
  const double aspect = viewport_.x / viewport_.y;
  const double nearZ = std::max(distance_ - 3.0 * sceneRadius_, distance_ * 1e-3);
  const double farZ = distance_ + 3.0 * sceneRadius_;
  const double t = 1.0 / std::tan(0.5 * fovY_);
  glm::dmat4 p(0.0);
  p[0][0] = t / aspect;
  p[1][1] = t;
  p[2][2] = -(farZ + nearZ) / (farZ - nearZ);
  p[2][3] = -1.0;
  p[3][2] = -2.0 * farZ * nearZ / (farZ - nearZ);
  // shift the image so the fitted area's middle is where the view looks
  p[2][0] = -2.0 * areaShift_.x / viewport_.x;
  p[2][1] = 2.0 * areaShift_.y / viewport_.y;
  return p;
}

glm::mat4 Camera3D::clipFromLocal(glm::dvec3 origin) const {
  return glm::mat4(clipFromView() * viewFromLocal(origin));
}

Projected Camera3D::toScreen(glm::dvec3 world) const {
  const glm::dvec4 c = clipFromView() * viewFromLocal(target_) * glm::dvec4(world - target_, 1.0);
  Projected out;
  out.w = c.w;
  if (c.w == 0.0) return out;
  out.screen = {(0.5 + 0.5 * c.x / c.w) * viewport_.x, (0.5 - 0.5 * c.y / c.w) * viewport_.y};
  return out;
}

Ray3 Camera3D::rayThrough(glm::dvec2 screen) const {
  // undo the projection for a point on the far side of the near plane
  const glm::dmat4 inv = glm::inverse(clipFromView() * viewFromLocal(target_));
  const double x = 2.0 * screen.x / viewport_.x - 1.0, y = 1.0 - 2.0 * screen.y / viewport_.y;
  glm::dvec4 a = inv * glm::dvec4(x, y, -1.0, 1.0), b = inv * glm::dvec4(x, y, 1.0, 1.0);
  const glm::dvec3 pa = glm::dvec3(a) / a.w + target_, pb = glm::dvec3(b) / b.w + target_;
  Ray3 r;
  r.origin = eye();
  r.direction = glm::normalize(pb - pa);
  return r;
}

}  // namespace convexloc::viewer
