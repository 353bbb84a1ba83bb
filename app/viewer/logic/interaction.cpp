// convexloc-viewer — mouse gestures.
#include "logic/interaction.hpp"

#include <cmath>

namespace convexloc::viewer {

void Interaction::update(const PointerInput& in, Model& model) {
  if (model.dim == Dim::Two)
    update2d(in, model);
  else
    update3d(in, model);
}

void Interaction::update2d(const PointerInput& in, Model& model) {
  Camera2D& cam = model.camera2d;
  Scene2D& scene = model.scene2d;

  // ImGui has the mouse and no gesture of ours is under way: leave everything as it is
  if (gesture_ == Gesture::None && (in.captured || !in.hovering)) {
    if (scene.hoverPoint()) scene.hover(std::nullopt);
    return;
  }

  if (gesture_ == Gesture::None) {
    if (in.wheel != 0.0) cam.zoomAt(in.pos, std::pow(kWheelZoom, in.wheel));
    if (in.pressed[0]) {
      const auto v = scene.polygon().vertices();
      const std::ptrdiff_t grab = model.settings.view2d.showHandles && v.size() <= kMaxHandles
                                      ? pickVertex(v, cam, in.pos, kGrabRadius)
                                      : -1;
      if (grab >= 0) {
        scene.beginDrag(static_cast<std::size_t>(grab));
        gesture_ = Gesture::DragVertex;
      } else {
        gesture_ = Gesture::Pending;
        pressAt_ = in.pos;
      }
    } else if (in.pressed[1] || in.pressed[2]) {
      gesture_ = Gesture::Pan;
    }
  }

  switch (gesture_) {
    case Gesture::Pending:
      if (glm::length(in.pos - pressAt_) > kClickSlop) {
        gesture_ = Gesture::Pan;
        cam.pan(in.pos - pressAt_);
      } else if (in.released[0] || !in.down[0]) {
        // a click: on a sprayed point, that very point (its exact doubles); else the cursor
        const std::ptrdiff_t hit = pickPoint(scene.points(), scene.classes(),
                                             model.settings.visibleMask, cam, in.pos, kPickRadius);
        scene.place(hit >= 0 ? scene.points()[static_cast<std::size_t>(hit)]
                             : toVec2(cam.toWorld(in.pos)));
        gesture_ = Gesture::None;
      }
      break;
    case Gesture::Pan:
      cam.pan(in.delta);
      if (!in.down[0] && !in.down[1] && !in.down[2]) gesture_ = Gesture::None;
      break;
    case Gesture::DragVertex:
      if (in.delta != glm::dvec2(0.0)) scene.dragTo(toVec2(cam.toWorld(in.pos)));
      if (!in.down[0]) {
        scene.endDrag();
        gesture_ = Gesture::None;
      }
      break;
    case Gesture::None:
    case Gesture::Orbit: break;
  }

  if (gesture_ == Gesture::None || gesture_ == Gesture::Pending)
    scene.hover(toVec2(cam.toWorld(in.pos)));
  else if (gesture_ == Gesture::Pan && scene.hoverPoint())
    scene.hover(std::nullopt);
}

void Interaction::update3d(const PointerInput& in, Model& model) {
  Camera3D& cam = model.camera3d;
  Scene3D& scene = model.scene3d();
  if (gesture_ == Gesture::None && (in.captured || !in.hovering)) {
    scene.hover(std::nullopt);
    return;
  }
  if (gesture_ == Gesture::None) {
    if (in.wheel != 0.0) cam.zoom(std::pow(kWheelZoom, in.wheel));
    if (in.pressed[0]) {
      gesture_ = Gesture::Pending;
      pressAt_ = in.pos;
    } else if (in.pressed[1] || in.pressed[2]) {
      gesture_ = Gesture::Pan;
    }
  }
  switch (gesture_) {
    case Gesture::Pending:
      if (glm::length(in.pos - pressAt_) > kClickSlop) {
        gesture_ = Gesture::Orbit;
        cam.orbit(in.pos - pressAt_);
      } else if (in.released[0] || !in.down[0]) {
        // a click: Shift pins the cell under the cursor; else a point on the slicing plane,
        // or, off the plane, the cell under the cursor is pinned
        const Ray3 ray = cam.rayThrough(in.pos);
        const auto hit = in.shift ? std::nullopt : scene.hitSlice(ray);
        if (hit)
          scene.place(toVec3(*hit));
        else
          scene.pin(scene.pickCell(ray));
        gesture_ = Gesture::None;
      }
      break;
    case Gesture::Orbit:
      cam.orbit(in.delta);
      if (!in.down[0]) gesture_ = Gesture::None;
      break;
    case Gesture::Pan:
      cam.pan(in.delta);
      if (!in.down[0] && !in.down[1] && !in.down[2]) gesture_ = Gesture::None;
      break;
    case Gesture::None:
    case Gesture::DragVertex: break;
  }
  if (gesture_ == Gesture::None || gesture_ == Gesture::Pending)
    scene.hover(cam.rayThrough(in.pos));
  else
    scene.hover(std::nullopt);
}

}  // namespace convexloc::viewer
