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

// whether the mouse, a key or a drop came in this frame
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
