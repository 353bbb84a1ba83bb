// convexloc-viewer — the 3D orbit camera: it looks at a target from a distance, turned by
// yaw about the world's z axis and tilted by pitch. Double precision throughout.
#pragma once

#include <optional>
#include <span>

#include <glm/glm.hpp>

#include "logic/view/camera2d.hpp"

namespace convexloc::viewer {

// an axis-aligned box in space
struct Bounds3 {
  glm::dvec3 lo{0.0};
  glm::dvec3 hi{0.0};
  glm::dvec3 middle() const { return 0.5 * (lo + hi); }
  double radius() const { return 0.5 * glm::length(hi - lo); }
};

// a 3D view asked for by name (a lecture's `camera`, `look`): the eye's azimuth about z from
// +x and elevation above the xy plane, in degrees, its distance from the target (none: the
// fit's), and the target (none: the fit's)
struct AskedCamera {
  std::optional<glm::dvec2> angles;  // azimuth, elevation
  std::optional<double> distance;
  std::optional<glm::dvec3> look;
};

// a ray in world coordinates; `direction` has unit length
struct Ray3 {
  glm::dvec3 origin{0.0};
  glm::dvec3 direction{0.0, 0.0, -1.0};
  glm::dvec3 at(double t) const { return origin + t * direction; }
};

// an axis-aligned plane: coordinate `axis` (0 x, 1 y, 2 z) equals `offset`
struct SlicePlane {
  int axis = 2;
  double offset = 0.0;
};

// a window pixel with the clip-space w of the point it came from (w <= 0: behind the eye)
struct Projected {
  glm::dvec2 screen{0.0};
  double w = 0.0;
  bool visible() const { return w > 0.0; }
};

class Camera3D {
 public:
  void setViewport(glm::dvec2 size);
  glm::dvec2 viewport() const { return viewport_; }

  glm::dvec3 target() const { return target_; }
  double distance() const { return distance_; }
  double yaw() const { return yaw_; }
  double pitch() const { return pitch_; }
  void set(glm::dvec3 target, double distance, double yaw, double pitch);

  // the eye position and the unit vectors of the view: forward, right, up
  glm::dvec3 eye() const;
  glm::dvec3 forward() const;
  glm::dvec3 right() const;
  glm::dvec3 up() const;

  // the asked view: its angles, then its target and distance where given (after a fit)
  void applyAsked(const AskedCamera& asked);
  // turns the view to look along `direction` (any length; its pitch kept short of the poles)
  void lookAlong(glm::dvec3 direction);
  // turns the view as when the mouse drags by `deltaPx` (left-right: yaw, up-down: pitch)
  void orbit(glm::dvec2 deltaPx);
  // moves the target in the view plane so that the content follows the mouse
  void pan(glm::dvec2 deltaPx);
  // divides the distance by `factor` (> 1 comes closer)
  void zoom(double factor);
  // looks at the box's middle from a distance at which its bounding sphere fills `area`
  void fit(const Bounds3& box, ScreenRect area);
  // looks at the middle of the boxes' union from the nearest distance at which the corners
  // of every box, seen as the camera is turned now, lie in `area` (the polyhedron and its
  // dual beside it then fill a wide area, not their bounding sphere's square)
  void fitCorners(std::span<const Bounds3> boxes, ScreenRect area);

  // after a fit, comes nearer (or goes farther) and shifts the picture so that the points'
  // drawn bounding box is centred in `area` and `fill` of its width or height
  void fitPoints(std::span<const glm::dvec3> points, ScreenRect area, double fill);
  // window pixel of a world point
  Projected toScreen(glm::dvec3 world) const;
  // the ray from the eye through a window pixel
  Ray3 rayThrough(glm::dvec2 screen) const;

  // matrices relative to `origin`: local coordinates are world minus origin
  glm::dmat4 viewFromLocal(glm::dvec3 origin) const;
  glm::dmat4 clipFromView() const;
  glm::mat4 clipFromLocal(glm::dvec3 origin) const;

 private:
  glm::dvec2 viewport_{1280.0, 800.0};
  glm::dvec3 target_{0.0};
  double distance_ = 5.0;
  double yaw_ = 0.6;
  double pitch_ = 0.45;
  double fovY_ = 0.6981317007977318;  // the vertical field of view: 40 degrees
  double sceneRadius_ = 1.0;
  glm::dvec2 areaShift_{0.0};  // pixels the fitted area's middle lies from the viewport's
};

}  // namespace convexloc::viewer
