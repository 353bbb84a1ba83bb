// convexloc-viewer — mouse gestures turned into camera moves and scene actions, GL-free.
// The app fills a PointerInput from ImGui's IO each frame; when ImGui wants the mouse
// (`captured`), nothing here moves, except to finish a gesture already under way.
#pragma once

#include <glm/glm.hpp>

#include "logic/app/model.hpp"

namespace convexloc::viewer {

// the mouse this frame, in window pixels
struct PointerInput {
  glm::dvec2 pos{0.0};
  glm::dvec2 delta{0.0};  // movement since the last frame
  bool down[3] = {};      // left, right, middle
  bool pressed[3] = {};   // went down this frame
  bool released[3] = {};  // went up this frame
  double wheel = 0.0;     // notches, positive away from the user
  bool captured = false;  // ImGui wants the mouse (io.WantCaptureMouse)
  bool shift = false;     // a Shift key is down
  bool alt = false;       // an Alt key is down: placed freely, no snapping
  bool hovering = true;   // the cursor is over the window
  // a pinch (two fingers on a touch screen, or a touchpad's): the scene zoomed by `zoom`
  // about pos and moved by `pan` pixels, wherever the pointer is (1 and 0: none)
  double zoom = 1.0;
  glm::dvec2 pan{0.0};
};

class Interaction {
 public:
  // pixels the mouse may move between press and release and still count as a click
  static constexpr double kClickSlop = 4.0;
  // how close (pixels) a press must be to a vertex to grab it, or to a point to pick it
  static constexpr double kGrabRadius = 9.0;
  static constexpr double kPickRadius = 5.0;
  // zoom factor per wheel notch
  static constexpr double kWheelZoom = 1.2;
  // how close (pixels) a position must be to a vertex, an edge, the centre or a grid point
  // to snap to it, and the grid's least spacing (pixels)
  static constexpr double kSnapRadius = 8.0;
  static constexpr double kGridPixels = 80.0;

  void update(const PointerInput& in, Model& model);

  enum class Gesture { None, Pending, Pan, Orbit, DragVertex, DrawLine };
  Gesture gesture() const { return gesture_; }

 private:
  // what a left press has become
  enum class PressOutcome { Waiting, Dragged, Clicked };

  // a pinch's zoom and pan, whatever ImGui wants and whatever gesture is under way
  void pinch(const PointerInput& in, Model& model);
  void update2d(const PointerInput& in, Model& model);
  void update3d(const PointerInput& in, Model& model);
  void click2d(const PointerInput& in, Model& model);
  // a press: a vertex grabbed, a line begun, or a click or pan pending
  void begin2d(const PointerInput& in, Model& model);
  // a grabbed vertex follows the snapped pointer; released without moving, the point is
  // placed on the vertex
  void dragVertex(const PointerInput& in, Model& model);
  // the hovered cell and the snap indicator after the gesture
  void hover2d(const PointerInput& in, Model& model);
  // the pointer's world position snapped (none with Alt held); `skip` is no target
  Snap snapAt(const PointerInput& in, const Model& model, std::optional<std::size_t> skip,
              bool grid) const;
  // where a click would place the point: a snap, else a sprayed point under the cursor
  // (kind None, its exact doubles), else a grid point, else the cursor; `markOnly`: for the
  // indicator, which skips the spray's search where no grid point is near
  Snap clickTarget(const PointerInput& in, const Model& model, bool markOnly) const;
  void click3d(const PointerInput& in, Model& model);
  // the Lines mode: a left drag places the line from the press to the cursor
  void drawLine(const PointerInput& in, Model& model);
  // ImGui has the mouse and no gesture of ours is under way: nothing moves
  bool ignored(const PointerInput& in) const;
  // a left press may become a click or a drag; the others pan
  void startGesture(const PointerInput& in);
  // Pending: past the click slop the press becomes `drag`; released within it, a click
  PressOutcome followPress(const PointerInput& in, Gesture drag);
  // a pan ends when every button is up
  void endWhenReleased(const PointerInput& in);
  Gesture gesture_ = Gesture::None;
  glm::dvec2 pressAt_{0.0};
  Vec2 lineStart_{};          // the snapped start of a line being drawn
  bool vertexMoved_ = false;  // the grabbed vertex went past the click slop
  bool lastAlt_ = false;      // Alt was down in the last frame (its change moves the vertex)
};

}  // namespace convexloc::viewer
