// convexloc-viewer — the split view: the 2D scene drawn twice side by side, the current
// method on the left and a second method on the right, over the same shape and the same
// points, with one camera (the right half's is the left's moved by half the scene area).
// The right half has its own locator, cells and placed-point trace: a Scene2D of its own,
// kept in step with the main scene's shape and placed point. 2D only; GL-free.
#pragma once

#include <array>
#include <cstdint>
#include <string>

#include "logic/scene/scene2d.hpp"
#include "logic/view/camera2d.hpp"

namespace convexloc::viewer {

class SecondView {
 public:
  bool enabled() const { return enabled_; }
  void setEnabled(bool on) { enabled_ = on; }
  Method2D method() const { return scene_.method(); }
  // the right half's method
  void setMethod(Method2D m) { scene_.setMethod(m); }

  // Brings the right half's scene in step with `main`: its shape (when main's shape
  // version changed), its placed point and its hovered point. Cheap when nothing changed.
  void sync(const Scene2D& main);
  // the right half's scene: its locator, cells, probe and trace
  const Scene2D& scene() const { return scene_; }

  // the scene area split in two halves (call every frame with the area the scene has): side
  // by side, or one over the other in an upright slide's room (a phone held upright), where
  // "left" is the upper half and "right" the lower
  void setArea(ScreenRect sceneArea) { area_ = sceneArea; }
  // whether an upright area stacks the halves (a slide's figure room; the live window's scene
  // keeps them side by side)
  void allowStacking(bool on) { stackable_ = on; }
  bool stacked() const { return stackable_ && area_.size().y > area_.size().x; }
  ScreenRect left() const;
  ScreenRect right() const;
  // the line between the halves: the right half's left edge, or the lower half's top
  std::array<glm::dvec2, 2> divider() const;
  // the right half's camera: `main` (the left half's) moved by the halves' offset
  Camera2D rightCamera(const Camera2D& main) const;
  // a position over the right half, moved to where the same world point is in the left one
  glm::dvec2 toLeft(glm::dvec2 pos) const;
  // a pointer input (PointerInput) with its position moved so
  template <class Pointer>
  Pointer toLeft(Pointer in) const {
    in.pos = toLeft(in.pos);
    return in;
  }

  // what the half shows in words: "polar: 1 predicate" ("" without a placed point)
  static std::string traceCaption(const Scene2D& scene);

 private:
  bool enabled_ = false;
  Scene2D scene_;
  ScreenRect area_;
  bool stackable_ = false;
  std::uint64_t shapeSeen_ = ~0ull, overlaySeen_ = ~0ull;
};

}  // namespace convexloc::viewer
