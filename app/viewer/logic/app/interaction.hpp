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
  bool hovering = true;   // the cursor is over the window
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

  void update(const PointerInput& in, Model& model);

  enum class Gesture { None, Pending, Pan, Orbit, DragVertex, DrawLine };
  Gesture gesture() const { return gesture_; }

 private:
  // what a left press has become
  enum class PressOutcome { Waiting, Dragged, Clicked };

  void update2d(const PointerInput& in, Model& model);
  void update3d(const PointerInput& in, Model& model);
  void click2d(const PointerInput& in, Model& model);
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
};

}  // namespace convexloc::viewer
