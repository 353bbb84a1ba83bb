// convexloc-viewer — the 2D camera: a centre and a scale, in double precision, so that a
// polygon at 10^9 from the origin or 10^-9 wide can be looked at as closely as any other.
#pragma once

#include <glm/glm.hpp>

#include "convexloc/geometry.hpp"
#include "logic/base/screen_rect.hpp"

namespace convexloc::viewer {

// a 2D view asked for by name: the world point at the scene's middle and the width of world
// shown across it
struct AskedView {
  Vec2 centre;
  double width = 1.0;
};

// Maps world coordinates (y up) to window pixels (y down) and back. The world point
// `centre` sits at the middle of the viewport, and one world unit spans `scale` pixels.
class Camera2D {
 public:
  // the smallest and largest scales zooming reaches, in pixels per world unit
  static constexpr double kMinScale = 1e-250;
  static constexpr double kMaxScale = 1e250;

  // the viewport size in window pixels (width, height), both > 0
  void setViewport(glm::dvec2 size);
  glm::dvec2 viewport() const { return viewport_; }

  glm::dvec2 centre() const { return centre_; }
  double scale() const { return scale_; }
  void set(glm::dvec2 centre, double scale);

  // window pixel of a world point, and back
  glm::dvec2 toScreen(glm::dvec2 world) const;
  glm::dvec2 toWorld(glm::dvec2 screen) const;
  // a length in pixels, in world units
  double worldPerPixel() const { return 1.0 / scale_; }

  // moves the content by `deltaPx` pixels, as when the mouse drags it
  void pan(glm::dvec2 deltaPx);
  // multiplies the scale by `factor`, keeping the world point under `screen` in place
  void zoomAt(glm::dvec2 screen, double factor);
  // the largest scale at which `box`, grown by `margin` of its size on each side, fits
  // in `area` (a part of the viewport), centred there
  void fit(const Box2& box, ScreenRect area, double margin = 0.13);

  // the world box the viewport shows
  Box2 visible() const;

  // the matrix taking local coordinates (world minus `origin`, as floats) to clip space;
  // computed in double so that only the small local coordinates go through floats
  glm::mat4 clipFromLocal(glm::dvec2 origin) const;

 private:
  glm::dvec2 viewport_{1280.0, 800.0};
  glm::dvec2 centre_{0.0, 0.0};
  double scale_ = 100.0;
};

// conversions between core's points and GLM's vectors
inline glm::dvec2 toGlm(Vec2 p) {
  return {p.x, p.y};
}
inline Vec2 toVec2(glm::dvec2 p) {
  return {p.x, p.y};
}

}  // namespace convexloc::viewer
