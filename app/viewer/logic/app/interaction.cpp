// convexloc-viewer — mouse gestures.
#include "logic/app/interaction.hpp"

#include <cmath>

namespace convexloc::viewer {

void Interaction::update(const PointerInput& in, Model& model) {
  if (model.dim == Dim::Two)
    update2d(in, model);
  else
    update3d(in, model);
}

bool Interaction::ignored(const PointerInput& in) const {
  return gesture_ == Gesture::None && (in.captured || !in.hovering);
}

void Interaction::startGesture(const PointerInput& in) {
  if (in.pressed[0]) {
    gesture_ = Gesture::Pending;
    pressAt_ = in.pos;
  } else if (in.pressed[1] || in.pressed[2]) {
    gesture_ = Gesture::Pan;
  }
}

Interaction::PressOutcome Interaction::followPress(const PointerInput& in, Gesture drag) {
  if (glm::length(in.pos - pressAt_) > kClickSlop) {
    gesture_ = drag;
    return PressOutcome::Dragged;
  }
  if (!in.released[0] && in.down[0]) return PressOutcome::Waiting;
  gesture_ = Gesture::None;
  return PressOutcome::Clicked;
}

void Interaction::endWhenReleased(const PointerInput& in) {
  if (!in.down[0] && !in.down[1] && !in.down[2]) gesture_ = Gesture::None;
}

void Interaction::update2d(const PointerInput& in, Model& model) {
  Camera2D& cam = model.camera2d;
  Scene2D& scene = model.scene2d;
  if (ignored(in)) {
    if (scene.hoverPoint()) scene.hover(std::nullopt);
    return;
  }
  if (gesture_ == Gesture::None) {
    if (in.wheel != 0.0) cam.zoomAt(in.pos, std::pow(kWheelZoom, in.wheel));
    const auto v = scene.polygon().vertices();
    const bool lines = model.lines2d.enabled();
    const bool handles = !lines && model.settings.view2d.showHandles && v.size() <= kMaxHandles;
    const std::ptrdiff_t grab =
        in.pressed[0] && handles ? pickVertex(v, cam, in.pos, kGrabRadius) : -1;
    if (grab >= 0) {
      scene.beginDrag(static_cast<std::size_t>(grab));
      gesture_ = Gesture::DragVertex;
    } else if (lines && in.pressed[0]) {
      gesture_ = Gesture::DrawLine;
      pressAt_ = in.pos;
    } else {
      startGesture(in);
    }
  }
  switch (gesture_) {
    case Gesture::Pending: {
      const PressOutcome outcome = followPress(in, Gesture::Pan);
      if (outcome == PressOutcome::Dragged) cam.pan(in.pos - pressAt_);
      if (outcome == PressOutcome::Clicked) click2d(in, model);
      break;
    }
    case Gesture::Pan:
      cam.pan(in.delta);
      endWhenReleased(in);
      break;
    case Gesture::DragVertex:
      if (in.delta != glm::dvec2(0.0)) scene.dragTo(toVec2(cam.toWorld(in.pos)));
      if (!in.down[0]) {
        scene.endDrag();
        gesture_ = Gesture::None;
      }
      break;
    case Gesture::DrawLine: drawLine(in, model); break;
    case Gesture::None:
    case Gesture::Orbit: break;
  }
  if (model.lines2d.enabled()) {
    if (scene.hoverPoint()) scene.hover(std::nullopt);
  } else if (gesture_ == Gesture::None || gesture_ == Gesture::Pending)
    scene.hover(toVec2(cam.toWorld(in.pos)));
  else if (gesture_ == Gesture::Pan && scene.hoverPoint())
    scene.hover(std::nullopt);
}

void Interaction::drawLine(const PointerInput& in, Model& model) {
  // a press without a drag leaves the line as it was
  if (glm::length(in.pos - pressAt_) > kClickSlop)
    model.lines2d.setLine(toVec2(model.camera2d.toWorld(pressAt_)),
                          toVec2(model.camera2d.toWorld(in.pos)));
  if (!in.down[0]) gesture_ = Gesture::None;
}

void Interaction::click2d(const PointerInput& in, Model& model) {
  // on a sprayed point, that very point (its exact doubles); else the cursor
  Scene2D& scene = model.scene2d;
  const Camera2D& cam = model.camera2d;
  const std::ptrdiff_t hit = pickPoint(scene.points(), scene.classes(), model.settings.visibleMask,
                                       cam, in.pos, kPickRadius);
  scene.place(hit >= 0 ? scene.points()[static_cast<std::size_t>(hit)]
                       : toVec2(cam.toWorld(in.pos)));
}

void Interaction::update3d(const PointerInput& in, Model& model) {
  Camera3D& cam = model.camera3d;
  Scene3D& scene = model.scene3d();
  if (ignored(in)) {
    scene.hover(std::nullopt);
    return;
  }
  if (gesture_ == Gesture::None) {
    if (in.wheel != 0.0) cam.zoom(std::pow(kWheelZoom, in.wheel));
    startGesture(in);
  }
  if (gesture_ == Gesture::Pending) {
    const PressOutcome outcome = followPress(in, Gesture::Orbit);
    if (outcome == PressOutcome::Dragged) cam.orbit(in.pos - pressAt_);
    if (outcome == PressOutcome::Clicked) click3d(in, model);
  } else if (gesture_ == Gesture::Orbit) {
    cam.orbit(in.delta);
    if (!in.down[0]) gesture_ = Gesture::None;
  } else if (gesture_ == Gesture::Pan) {
    cam.pan(in.delta);
    endWhenReleased(in);
  }
  if (gesture_ == Gesture::None || gesture_ == Gesture::Pending)
    scene.hover(cam.rayThrough(in.pos));
  else
    scene.hover(std::nullopt);
}

void Interaction::click3d(const PointerInput& in, Model& model) {
  // Shift pins the cell under the cursor; else a point on the slicing plane, or, off the
  // plane, the cell under the cursor is pinned. A hidden slicing plane takes no point, and
  // the Planes mode, which draws neither the method's cells nor the placed point, takes
  // no click at all (its plane moves with the panel's sliders).
  if (model.planes3d.enabled()) return;
  Scene3D& scene = model.scene3d();
  const Ray3 ray = model.camera3d.rayThrough(in.pos);
  const bool onSlice = !in.shift && model.settings.view3d.showSlice;
  const auto hit = onSlice ? scene.hitSlice(ray) : std::nullopt;
  if (hit)
    scene.place(toVec3(*hit));
  else
    scene.pin(scene.pickCell(ray));
}

}  // namespace convexloc::viewer
