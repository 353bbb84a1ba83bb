// convexloc-viewer — the window: GLFW, its OpenGL 3.3 core context, Dear ImGui's GLFW and
// OpenGL 3 backends; and, without a display, the run again under xvfb-run that renders the
// scene to a PNG instead.
#pragma once

#include <string>

#include <glm/glm.hpp>

#include "gl/no_copy.hpp"
#include "logic/app/options.hpp"

struct GLFWwindow;

namespace convexloc::viewer {

// whether an X11 or a Wayland display is there to open a window on
bool displayAvailable();

// Runs this program again under xvfb-run (rendering to --screenshot, or to
// convexloc-viewer.png), replacing this process. Returns the exit code only when that
// is impossible (after saying so on stderr).
int rerunUnderXvfb(int argc, char** argv, const Options& options);

// this program's own path (for xvfb-run and the installed shaders beside it)
std::string selfPath(const char* argv0);

// the window's size in window pixels and its framebuffer's in device pixels
struct FrameSize {
  glm::dvec2 window{1.0};  // at least 1 x 1
  int framebufferWidth = 0, framebufferHeight = 0;
  float pixelRatio = 1.0f;  // framebuffer pixels per window pixel
};

// one GLFW window with its GL context and ImGui on it
class Window : NoCopy {
 public:
  // closes ImGui's backends, the window and GLFW
  ~Window();

  // Opens a window of the options' size with a GL 3.3 core context, loads the GL
  // functions and starts ImGui on it; false (with the reason on stderr) when it cannot.
  // A `headless` window does not wait for the display's refresh.
  bool open(const Options& options, bool headless);
  GLFWwindow* handle() const { return window_; }

  bool shouldClose() const;
  // Takes the events that came in; with `idle`, first waits for one (a quarter second).
  // Returns whether to draw a frame: always on the desktop; in the web page, which must not
  // wait, false while idle with nothing new and less than a quarter second since the last.
  bool takeEvents(bool idle);
  // starts an ImGui frame
  void newFrame();
  // draws ImGui's lists over the scene
  void renderImGui();
  void swapBuffers();

  FrameSize frameSize() const;
  // window pixels per screen point (HiDPI), at least 1
  float contentScale() const;
  // whether the cursor is over the window
  bool hovered() const;
  // the web page on a narrow screen (a phone: under 700 CSS pixels wide); the desktop: false
  bool narrow() const { return narrow_; }

 private:
  GLFWwindow* window_ = nullptr;
  bool glfwStarted_ = false;
  bool imguiStarted_ = false;
  double lastDrawnMs_ = 0.0;  // the web page: when takeEvents last asked for a frame
  bool narrow_ = false;
};

}  // namespace convexloc::viewer
