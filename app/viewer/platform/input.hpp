// convexloc-viewer — what the user did this frame, read from GLFW and ImGui's IO: files
// dropped on the window, the mouse as a PointerInput, keys as the viewer's Actions, and
// whether anything came in at all (an untouched window waits for events).
#pragma once

#include <string>
#include <vector>

#include "logic/app/actions.hpp"
#include "logic/app/interaction.hpp"

struct GLFWwindow;

namespace convexloc::viewer {

// starts collecting the files dropped on `window`
void watchDrops(GLFWwindow* window);
// every key press seen, for keyActions (installed after ImGui's backend, which it calls)
void watchKeys(GLFWwindow* window);
// the files dropped since the last call, oldest first
std::vector<std::string> takeDroppedFiles();
// `path` opens at the next frame, as a file dropped on the window does
void openLater(const std::string& path);

// the mouse this frame, from ImGui's IO; `hovering`: the cursor is over the window
PointerInput pointerInput(bool hovering);

// The actions the keys pressed since the last call ask for, one a press, in order: F12
// always; the others only when ImGui did not want the keyboard (see logic/app/key_queue.hpp).
std::vector<Action> keyActions();

// whether the mouse, a key, a gesture or a drop came in this frame
bool hadInput(bool dropped);

// Counts the frames since the last input: past a few, the loop waits for events instead
// of drawing again.
class IdleCounter {
 public:
  void note(bool input) { idleFrames_ = input ? 0 : idleFrames_ + 1; }
  bool idle() const { return idleFrames_ > 3; }

 private:
  int idleFrames_ = 0;
};

}  // namespace convexloc::viewer

// The web page's wheel and touch gestures, which its script (input.js) has normalised: the
// browser's units and sign made GLFW's, touches made mouse events or these. Each adds to
// what the next pointerInput gives.
extern "C" {
// a wheel or a touchpad's scroll in notches, positive up and left (GLFW's sign); with
// `sceneZoom` (a touchpad's pinch, a Ctrl+wheel), the scene zoomed by y notches at the
// pointer, over a panel too
void convexloc_wheel(double x, double y, bool sceneZoom);
// two fingers: the scene zoomed by `factor` about the pointer and moved (dx, dy) pixels
void convexloc_pinch(double factor, double dx, double dy);
// a finger dragged over a panel: the panel under the pointer scrolled so that its content
// follows the finger by `dy` pixels (down positive)
void convexloc_scroll_pixels(double dy);
// the page's lecture buttons and swipes: the next slide (`direction` > 0) or the previous
void convexloc_lecture_step(int direction);
}
