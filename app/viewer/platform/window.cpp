// convexloc-viewer — the window, its context and ImGui's backends; the xvfb-run fallback.
#include "platform/window.hpp"

#include <algorithm>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include <unistd.h>

#ifdef __EMSCRIPTEN__
#include <emscripten/emscripten.h>
#include <emscripten/html5.h>
#endif

#include "gl/context.hpp"
#include "platform/page.hpp"
#define GLFW_INCLUDE_NONE  // the GL declarations come from gl/ alone
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

namespace convexloc::viewer {
namespace {

void onGlfwError(int code, const char* text) {
  std::cerr << "convexloc-viewer: GLFW error " << code << ": " << text << "\n";
}

#ifndef __EMSCRIPTEN__
// whether an environment variable is set and not empty
bool isSet(const char* name) {
  const char* v = std::getenv(name);
  return v && *v;
}
#endif

// the GL context every window asks for (the web page: WebGL 2, chosen at link time)
void contextHints() {
#ifndef __EMSCRIPTEN__
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
#endif
  // The window needs no multisampling: the scene is drawn into an offscreen target that
  // has it (see SceneView), and ImGui anti-aliases its own shapes.
  glfwWindowHint(GLFW_SAMPLES, 0);
}

#ifdef __EMSCRIPTEN__
// Whether the page saw input (the mouse, the keyboard, a touch, a drop, a resize) since the
// last call: an idle viewer draws again at once for it.
// clang-format off
EM_JS(bool, convexlocTakeInput, (), {
  if (!Module.convexlocInputWatched) {
    Module.convexlocInputWatched = true;
    const note = () => { Module.convexlocInput = true; };
    for (const kind of ['mousemove', 'mousedown', 'mouseup', 'wheel', 'keydown', 'keyup',
                        'touchstart', 'touchmove', 'touchend', 'drop', 'resize', 'focus'])
      window.addEventListener(kind, note, {capture: true, passive: true});
  }
  const input = !!Module.convexlocInput;
  Module.convexlocInput = false;
  return input;
});
// clang-format on

// a page narrower than this (CSS pixels) is a phone's: the panels go into a drawer
constexpr double kNarrowPage = 700.0;

// The canvas's size on the page in device pixels: the page's style sizes it, the window
// (GLFW's, Emscripten's) follows, so a HiDPI screen gets every pixel it has. True when the
// size changed; `narrow` tells whether the page is a phone's.
bool fitCanvas(GLFWwindow* window, bool& narrow) {
  double cssW = 0.0, cssH = 0.0;
  if (emscripten_get_element_css_size("#canvas", &cssW, &cssH) != EMSCRIPTEN_RESULT_SUCCESS)
    return false;
  narrow = cssW < kNarrowPage;
  const double ratio = emscripten_get_device_pixel_ratio();
  const int w = std::max(1, static_cast<int>(cssW * ratio + 0.5));
  const int h = std::max(1, static_cast<int>(cssH * ratio + 0.5));
  int winW = 0, winH = 0;
  glfwGetWindowSize(window, &winW, &winH);
  if (w == winW && h == winH) return false;
  glfwSetWindowSize(window, w, h);
  return true;
}
#endif

}  // namespace

bool displayAvailable() {
#ifdef __EMSCRIPTEN__
  return true;  // the page's canvas
#else
  return isSet("DISPLAY") || isSet("WAYLAND_DISPLAY");
#endif
}

std::string selfPath(const char* argv0) {
  char buf[4096];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return argv0;
  buf[n] = '\0';
  return buf;
}

int rerunUnderXvfb(int argc, char** argv, const Options& o) {
  const std::string png = o.screenshot.empty() ? "convexloc-viewer.png" : o.screenshot;
  std::cerr << "convexloc-viewer: no display (DISPLAY is not set); rendering the scene to " << png
            << " through xvfb-run instead\n";
  std::vector<std::string> args = {
      "xvfb-run", "-a", "-s",
      "-screen 0 " + std::to_string(o.width + 64) + "x" + std::to_string(o.height + 64) + "x24",
      selfPath(argv[0])};
  for (int i = 1; i < argc; ++i) args.emplace_back(argv[i]);
  args.emplace_back("--no-xvfb");
  if (o.screenshot.empty()) {
    args.emplace_back("--screenshot");
    args.emplace_back(png);
  }
  std::vector<char*> cargs;
  for (std::string& a : args) cargs.push_back(a.data());
  cargs.push_back(nullptr);
  execvp("xvfb-run", cargs.data());
  std::cerr
      << "convexloc-viewer: cannot run xvfb-run (install the Debian packages xvfb and xauth), "
         "or run with a display\n";
  return 1;
}

// === Window

bool Window::open(const Options& options, bool headless) {
  glfwSetErrorCallback(onGlfwError);
  if (!glfwInit()) {
    std::cerr << "convexloc-viewer: cannot initialise GLFW (is the display reachable?)\n";
    return false;
  }
  glfwStarted_ = true;
  contextHints();
  window_ = glfwCreateWindow(options.width, options.height, "convexloc-viewer", nullptr, nullptr);
  if (!window_) {
#ifdef __EMSCRIPTEN__
    showPageProblem(
        "This browser gives the page no WebGL 2, which the viewer draws with. Try another "
        "browser (a recent Firefox, Chrome, Edge or Safari), or turn the browser's hardware "
        "acceleration on and open the page again.");
#endif
    std::cerr << "convexloc-viewer: cannot open an OpenGL 3.3 core window\n";
    return false;
  }
  glfwMakeContextCurrent(window_);
  if (!loadGlFunctions(glfwGetProcAddress)) {
    std::cerr << "convexloc-viewer: cannot load the OpenGL functions\n";
    return false;
  }
  glfwSwapInterval(headless ? 0 : 1);
  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGui::GetIO().IniFilename = nullptr;  // nothing written next to the user's files
  ImGui_ImplGlfw_InitForOpenGL(window_, true);
#ifdef __EMSCRIPTEN__
  ImGui_ImplOpenGL3_Init("#version 300 es");
  fitCanvas(window_, narrow_);
#else
  ImGui_ImplOpenGL3_Init("#version 330 core");
#endif
  imguiStarted_ = true;
  return true;
}

Window::~Window() {
  if (imguiStarted_) {
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
  }
  if (window_) glfwDestroyWindow(window_);
  if (glfwStarted_) glfwTerminate();
}

bool Window::shouldClose() const {
  return glfwWindowShouldClose(window_);
}

bool Window::takeEvents(bool idle) {
#ifdef __EMSCRIPTEN__
  // the browser delivers the events between frames; the page's size may have changed
  const bool resized = fitCanvas(window_, narrow_);
  const bool input = convexlocTakeInput();
  const double now = emscripten_get_now();
  if (idle && !resized && !input && now - lastDrawnMs_ < 250.0) return false;
  lastDrawnMs_ = now;
  return true;
#else
  if (idle)
    glfwWaitEventsTimeout(0.25);
  else
    glfwPollEvents();
  return true;
#endif
}

void Window::newFrame() {
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
}

void Window::renderImGui() {
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
}

void Window::swapBuffers() {
  glfwSwapBuffers(window_);
}

FrameSize Window::frameSize() const {
  int winW = 0, winH = 0;
  FrameSize s;
  glfwGetWindowSize(window_, &winW, &winH);
  glfwGetFramebufferSize(window_, &s.framebufferWidth, &s.framebufferHeight);
  s.window = {std::max(winW, 1), std::max(winH, 1)};
  s.pixelRatio =
      winW > 0 ? static_cast<float>(s.framebufferWidth) / static_cast<float>(winW) : 1.0f;
  return s;
}

float Window::contentScale() const {
#ifdef __EMSCRIPTEN__
  return 1.0f;  // the canvas has the screen's pixels; the page scales the text (page.js)
#else
  float xscale = 1.0f, yscale = 1.0f;
  glfwGetWindowContentScale(window_, &xscale, &yscale);
  return std::max(1.0f, xscale);
#endif
}

bool Window::hovered() const {
#ifdef __EMSCRIPTEN__
  return true;  // the canvas fills the page; Emscripten's GLFW does not say
#else
  return glfwGetWindowAttrib(window_, GLFW_HOVERED) != 0;
#endif
}

}  // namespace convexloc::viewer
