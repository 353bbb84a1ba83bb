// convexloc-viewer — the speaker notes in a window of their own, which the lecturer drags to
// the laptop's screen while the main window fills the projector: a second GLFW window with
// its own GL context and its own Dear ImGui context, drawn after the main window each frame.
// Where a second window cannot be opened (a browser's canvas), it says so and the caller
// shows the notes inside the main window instead.
#pragma once

#include <functional>

#include "gl/no_copy.hpp"

struct GLFWwindow;
struct ImGuiContext;

namespace convexloc::viewer {

class NotesWindow : NoCopy {
 public:
  ~NotesWindow();
  // Draws one frame of the notes window with `contents` (ImGui calls, in the window's own
  // context; `fonts` loads its font at the given pixel size first), opening the window when
  // `wanted` and closing it when not, or when the user closed it (then `wanted` becomes
  // false). The main window's GL and ImGui contexts are current again afterwards. False
  // when no second window can be opened.
  bool update(bool& wanted, GLFWwindow* main, const std::function<void(float)>& fonts,
              const std::function<void()>& contents);

 private:
  bool open(GLFWwindow* main, const std::function<void(float)>& fonts);
  void close();
  GLFWwindow* window_ = nullptr;
  ImGuiContext* context_ = nullptr;
  bool failed_ = false;
};

}  // namespace convexloc::viewer
