// convexloc-viewer — mouse gestures.
#include "logic/app/interaction.hpp"

#include <cmath>

namespace convexloc::viewer {

void Interaction::update(const PointerInput& in, Model& model) {
  pinch(in, model);
  if (model.dim == Dim::Two)
    update2d(in, model);
  else
    update3d(in, model);
}

void Interaction::pinch(const PointerInput& in, Model& model) {
  if (in.zoom == 1.0 && in.pan == glm::dvec2(0.0)) return;
  if (model.dim == Dim::Two) {
    model.camera2d.pan(in.pan);
    model.camera2d.zoomAt(in.pos, in.zoom);
  } else {
    model.camera3d.pan(in.pan);
    model.camera3d.zoom(in.zoom);
  }
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
    scene.setSnapMark(std::nullopt);
    return;
  }
  if (gesture_ == Gesture::None) begin2d(in, model);
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
    case Gesture::DragVertex: dragVertex(in, model); break;
    case Gesture::DrawLine: drawLine(in, model); break;
    case Gesture::None:
    case Gesture::Orbit: break;
  }
  hover2d(in, model);
}

void Interaction::begin2d(const PointerInput& in, Model& model) {
  Camera2D& cam = model.camera2d;
  Scene2D& scene = model.scene2d;
  if (in.wheel != 0.0) cam.zoomAt(in.pos, std::pow(kWheelZoom, in.wheel));
  const auto v = scene.polygon().vertices();
  const bool lines = model.lines2d.enabled();
  const bool handles = !lines && model.settings.view2d.showHandles && v.size() <= kMaxHandles;
  const std::ptrdiff_t grab =
      in.pressed[0] && handles ? pickVertex(v, cam, in.pos, kGrabRadius) : -1;
  if (grab >= 0) {
    scene.beginDrag(static_cast<std::size_t>(grab));
    gesture_ = Gesture::DragVertex;
    pressAt_ = in.pos;
    vertexMoved_ = false;
  } else if (lines && in.pressed[0]) {
    gesture_ = Gesture::DrawLine;
    pressAt_ = in.pos;
    lineStart_ = snapAt(in, model, std::nullopt, true).point;
  } else {
    startGesture(in);
  }
}

void Interaction::dragVertex(const PointerInput& in, Model& model) {
  Scene2D& scene = model.scene2d;
  if (!scene.drag()) {
    gesture_ = Gesture::None;
    return;
  }
  vertexMoved_ = vertexMoved_ || glm::length(in.pos - pressAt_) > kClickSlop;
  const std::size_t vertex = scene.drag()->vertex;
  if (vertexMoved_ && (in.delta != glm::dvec2(0.0) || in.alt != lastAlt_))
    scene.dragTo(snapAt(in, model, vertex, true).point);
  lastAlt_ = in.alt;
  if (in.down[0]) return;
  scene.endDrag();
  gesture_ = Gesture::None;
  // a click on a vertex: the point placed on it, its very doubles (on the boundary)
  if (!vertexMoved_) scene.place(scene.polygon().vertex(vertex));
}

void Interaction::hover2d(const PointerInput& in, Model& model) {
  Scene2D& scene = model.scene2d;
  const Camera2D& cam = model.camera2d;
  const bool free = gesture_ == Gesture::None || gesture_ == Gesture::Pending;
  if (model.lines2d.enabled()) {
    if (scene.hoverPoint()) scene.hover(std::nullopt);
    if (free) scene.setSnapMark(snapAt(in, model, std::nullopt, true));
  } else if (free) {
    scene.hover(toVec2(cam.toWorld(in.pos)));
    scene.setSnapMark(clickTarget(in, model, true));
  } else if (gesture_ == Gesture::Pan) {
    if (scene.hoverPoint()) scene.hover(std::nullopt);
  }
  if (gesture_ == Gesture::Pan) scene.setSnapMark(std::nullopt);
  if (gesture_ == Gesture::DragVertex && scene.drag())
    scene.setSnapMark(vertexMoved_ ? snapAt(in, model, scene.drag()->vertex, true) : Snap{});
}

Snap Interaction::snapAt(const PointerInput& in, const Model& model,
                         std::optional<std::size_t> skip, bool grid) const {
  const Camera2D& cam = model.camera2d;
  const Vec2 w = toVec2(cam.toWorld(in.pos));
  if (in.alt) return {w, SnapKind::None, 0, {}};
  const Scene2D& scene = model.scene2d;
  const double gridStep = grid ? niceGridStep(kGridPixels * cam.worldPerPixel()) : 0.0;
  const SnapTargets targets{scene.polygon().vertices(), scene.centre(), gridStep, skip};
  return snapPoint(w, targets, kSnapRadius * cam.worldPerPixel());
}

Snap Interaction::clickTarget(const PointerInput& in, const Model& model, bool markOnly) const {
  const Snap shape = snapAt(in, model, std::nullopt, false);
  if (shape.kind != SnapKind::None) return shape;
  const Snap grid = snapAt(in, model, std::nullopt, true);
  // the indicator needs no search of the spray where nothing snaps
  if (markOnly && grid.kind == SnapKind::None) return grid;
  const Scene2D& scene = model.scene2d;
  const std::ptrdiff_t hit = pickPoint(scene.points(), scene.classes(), model.settings.visibleMask,
                                       model.camera2d, in.pos, kPickRadius);
  if (hit >= 0) return {scene.points()[static_cast<std::size_t>(hit)], SnapKind::None, 0, {}};
  return grid;
}

void Interaction::drawLine(const PointerInput& in, Model& model) {
  // a press without a drag leaves the line as it was; both ends snap
  const Snap end = snapAt(in, model, std::nullopt, true);
  model.scene2d.setSnapMark(end);
  if (glm::length(in.pos - pressAt_) > kClickSlop) model.lines2d.setLine(lineStart_, end.point);
  if (!in.down[0]) gesture_ = Gesture::None;
}

void Interaction::click2d(const PointerInput& in, Model& model) {
  // a snap (a vertex, an edge, the centre), a sprayed point (its exact doubles), a grid
  // point, or the cursor
  model.scene2d.place(clickTarget(in, model, false).point);
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
