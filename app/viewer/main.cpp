// convexloc-viewer — the interactive teaching app for the paper's polar slabs.
//
// main() opens the window and runs the frame loop in the order of Dear ImGui's
// GLFW + OpenGL 3 example: poll events, start the ImGui frame, build the UI (the camera
// moves only when ImGui does not want the mouse), render ImGui's lists, clear, draw the
// scene, draw ImGui over it, swap. Everything it shows lives in logic/ (GL-free) and is
// drawn by gl/; the panels are in ui/.
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <string>
#include <string_view>
#include <vector>

#include <unistd.h>

#include "gl/gl.hpp"
// GLFW after glad, so it does not pull in a GL header of its own
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "gl/renderer.hpp"
#include "gl/scene_view.hpp"
#include "logic/interaction.hpp"
#include "logic/model.hpp"
#include "logic/options.hpp"
#include "ui/panels.hpp"
#include "ui/screenshot.hpp"
#include "ui/style.hpp"

#ifndef CONVEXLOC_SHADER_DIR
#define CONVEXLOC_SHADER_DIR "shaders"
#endif
#ifndef CONVEXLOC_ASSET_DIR
#define CONVEXLOC_ASSET_DIR "assets"
#endif
#ifndef CONVEXLOC_VERSION
#define CONVEXLOC_VERSION "unknown"
#endif

namespace cv = convexloc::viewer;

namespace {

constexpr float kBaseFontPixels = 16.0f;

// files dropped on the window since the last frame
std::vector<std::string> gDropped;

void onDrop(GLFWwindow*, int count, const char** paths) {
  for (int i = 0; i < count; ++i) gDropped.emplace_back(paths[i]);
}

void onGlfwError(int code, const char* text) {
  std::cerr << "convexloc-viewer: GLFW error " << code << ": " << text << "\n";
}

// this program's own path, for re-running it under xvfb-run
std::string selfPath(const char* argv0) {
  char buf[4096];
  const ssize_t n = readlink("/proc/self/exe", buf, sizeof buf - 1);
  if (n <= 0) return argv0;
  buf[n] = '\0';
  return buf;
}

// Without a display there is no window to open: run again under xvfb-run, rendering the
// scene to a PNG. Returns only when that is impossible.
int rerunUnderXvfb(int argc, char** argv, const cv::Options& o) {
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

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string_view> args(argv + 1, argv + argc);
  const cv::ParsedOptions parsed = cv::parseOptions(args);
  if (!parsed.error.empty()) {
    std::cerr << "convexloc-viewer: " << parsed.error << "\n";
    return 2;
  }
  const cv::Options& options = parsed.options;
  if (options.help) {
    std::cout << cv::usageText();
    return 0;
  }
  if (options.version) {
    std::cout << "convexloc-viewer " CONVEXLOC_VERSION "\n";
    return 0;
  }
  const char* display = std::getenv("DISPLAY");
  const char* wayland = std::getenv("WAYLAND_DISPLAY");
  if ((!display || !*display) && (!wayland || !*wayland)) {
    if (options.noXvfb) {
      std::cerr << "convexloc-viewer: no display (DISPLAY is not set)\n";
      return 1;
    }
    return rerunUnderXvfb(argc, argv, options);
  }
  const bool headless = !options.screenshot.empty() || options.framesGiven;

  glfwSetErrorCallback(onGlfwError);
  if (!glfwInit()) {
    std::cerr << "convexloc-viewer: cannot initialise GLFW (is the display reachable?)\n";
    return 1;
  }
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  // The window needs no multisampling: the scene is drawn into an offscreen target that
  // has it (see SceneView), and ImGui anti-aliases its own shapes.
  glfwWindowHint(GLFW_SAMPLES, 0);
  GLFWwindow* window =
      glfwCreateWindow(options.width, options.height, "convexloc-viewer", nullptr, nullptr);
  if (!window) {
    std::cerr << "convexloc-viewer: cannot open an OpenGL 3.3 core window\n";
    glfwTerminate();
    return 1;
  }
  glfwMakeContextCurrent(window);
  if (!gladLoadGL(glfwGetProcAddress)) {
    std::cerr << "convexloc-viewer: cannot load the OpenGL functions\n";
    glfwTerminate();
    return 1;
  }
  // Multisampling costs a software renderer (Mesa's llvmpipe) about three times the frame
  // time, and the shaders anti-alias lines and points themselves: none there by default.
  const std::string rendererName = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
  const bool software = rendererName.find("llvmpipe") != std::string::npos ||
                        rendererName.find("softpipe") != std::string::npos ||
                        rendererName.find("SWR") != std::string::npos;
  int samples = options.samples >= 0 ? options.samples : (software ? 0 : 4);
  GLint maxSamples = 0;
  glGetIntegerv(GL_MAX_SAMPLES, &maxSamples);
  samples = std::min(samples, static_cast<int>(maxSamples));
  glfwSwapInterval(headless ? 0 : 1);
  glfwSetDropCallback(window, onDrop);
  glEnable(GL_MULTISAMPLE);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  ImGuiIO& io = ImGui::GetIO();
  io.IniFilename = nullptr;  // nothing written next to the user's files
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  cv::Model model;
  const std::string problem = model.apply(options);
  if (!problem.empty() && headless) {
    std::cerr << "convexloc-viewer: " << problem << "\n";
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    glfwDestroyWindow(window);
    glfwTerminate();
    return 1;
  }

  cv::UiState ui;
  ui.assetDir = CONVEXLOC_ASSET_DIR;
  cv::scanAssets(ui);
  ui.fontScaleEdit = model.settings.fontScale;
  if (options.compare) {
    if (model.dim == cv::Dim::Two)
      ui.compare = model.scene2d.compare();
    else
      ui.compare3 = model.scene3d().compare();
  }
  ui.glInfo = rendererName + ", GL " + reinterpret_cast<const char*>(glGetString(GL_VERSION)) +
              (samples > 0 ? ", MSAA " + std::to_string(samples) + "x" : ", no MSAA");
  float xscale = 1.0f, yscale = 1.0f;
  glfwGetWindowContentScale(window, &xscale, &yscale);
  const float dpi = std::max(1.0f, xscale);
  cv::loadFont(kBaseFontPixels * model.settings.fontScale * dpi, false);
  io.FontGlobalScale = 1.0f / dpi;
  cv::Theme styled = model.settings.theme;
  float styledScale = model.settings.fontScale;
  cv::applyStyle(styled, styledScale);

  cv::Renderer renderer;
  // the shaders: --shaders, else the source tree's, else an installed copy beside the binary
  std::string shaderDir = options.shaderDir;
  if (shaderDir.empty()) {
    namespace fs = std::filesystem;
    std::error_code ec;
    shaderDir = CONVEXLOC_SHADER_DIR;
    const fs::path installed =
        fs::path(selfPath(argv[0])).parent_path() / ".." / "share" / "convexloc" / "shaders";
    if (!fs::exists(fs::path(shaderDir) / "points.vert", ec) &&
        fs::exists(installed / "points.vert", ec))
      shaderDir = installed.lexically_normal().string();
  }
  if (!renderer.init(shaderDir)) {
    std::cerr << "convexloc-viewer: shader problems in " << shaderDir << ":\n"
              << renderer.shaderLog();
    model.fail("shaders failed to compile (see View > shaders): " + shaderDir);
    if (headless) return 1;
  }
  cv::SceneView view;
  cv::Interaction interaction;

  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto last = start;
  int frame = 0;
  double timedMs = 0.0;
  int timedFrames = 0;
  int exitCode = 0;
  int idleFrames = 0;  // frames since the last input; past a few, wait for events (no busy loop)
  while (!glfwWindowShouldClose(window)) {
    const auto frameStart = Clock::now();
    if (!headless && idleFrames > 3)
      glfwWaitEventsTimeout(0.25);
    else
      glfwPollEvents();

    // font and theme changes rebuild ImGui's atlas and style outside the frame
    if (ui.pendingFontScale > 0.0f) {
      model.settings.fontScale = ui.pendingFontScale;
      ui.pendingFontScale = 0.0f;
      cv::loadFont(kBaseFontPixels * model.settings.fontScale * dpi, true);
    }
    if (styled != model.settings.theme || styledScale != model.settings.fontScale) {
      styled = model.settings.theme;
      styledScale = model.settings.fontScale;
      cv::applyStyle(styled, styledScale);
    }

    ImGui_ImplOpenGL3_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();

    int winW = 0, winH = 0, fbW = 0, fbH = 0;
    glfwGetWindowSize(window, &winW, &winH);
    glfwGetFramebufferSize(window, &fbW, &fbH);
    const glm::dvec2 windowSize{std::max(winW, 1), std::max(winH, 1)};
    const float pixelRatio = winW > 0 ? static_cast<float>(fbW) / static_cast<float>(winW) : 1.0f;
    model.camera2d.setViewport(windowSize);
    model.camera3d.setViewport(windowSize);

    const bool noDrops = gDropped.empty();
    for (const std::string& path : gDropped) {
      if (model.open(path)) std::snprintf(ui.path, sizeof ui.path, "%s", path.c_str());
    }
    gDropped.clear();
    if (model.takeFitRequest()) model.fit(cv::sceneArea(model, windowSize));

    // the mouse moves the camera and the scene only when ImGui does not want it
    if (!headless) {
      cv::PointerInput in;
      in.pos = {io.MousePos.x, io.MousePos.y};
      in.delta = {io.MouseDelta.x, io.MouseDelta.y};
      if (!ImGui::IsMousePosValid()) in.delta = {0.0, 0.0};
      for (int b = 0; b < 3; ++b) {
        in.down[b] = io.MouseDown[b];
        in.pressed[b] = ImGui::IsMouseClicked(b);
        in.released[b] = ImGui::IsMouseReleased(b);
      }
      in.wheel = io.MouseWheel;
      in.captured = io.WantCaptureMouse;
      in.shift = io.KeyShift;
      in.hovering = ImGui::IsMousePosValid() && glfwGetWindowAttrib(window, GLFW_HOVERED);
      interaction.update(in, model);
      cv::handleKeys(model, ui);
    }
    // --animate: the camera moves a little every frame, as under a hand (for timing)
    if (options.animate && frame > 0) {
      if (model.dim == cv::Dim::Two)
        model.camera2d.pan({1.0, 0.5});
      else
        model.camera3d.orbit({2.0, 0.0});
    }
    model.collectErrors();
    bool input = io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f || io.MouseWheel != 0.0f ||
                 !noDrops || ui.pendingFontScale > 0.0f;
    for (bool b : io.MouseDown) input |= b;
    for (bool k : io.KeysDown) input |= k;
    idleFrames = input ? 0 : idleFrames + 1;

    const double now = std::chrono::duration<double>(Clock::now() - start).count();
    cv::drawUi(model, renderer, view, ui, now);
    view.sync(model, renderer);
    cv::drawLabels(model, view);
    ImGui::Render();

    glViewport(0, 0, fbW, fbH);
    const cv::Rgba bg = cv::paletteFor(model.settings.theme).background;
    glClearColor(bg.r, bg.g, bg.b, 1.0f);
    glDepthMask(GL_TRUE);  // a clear honours the depth mask
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const glm::vec2 fb{static_cast<float>(fbW), static_cast<float>(fbH)};
    if (!renderer.ensureTarget(fbW, fbH, samples) && samples > 0 &&
        renderer.ensureTarget(fbW, fbH, samples = 0))
      ui.glInfo += " (multisampled target refused: none)";
    view.drawBase(model, renderer, fb, pixelRatio);
    view.drawOverlay(model, renderer, fb, pixelRatio);
    ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());

    ++frame;
    const bool lastFrame = headless && frame >= options.frames;
    if (ui.screenshotRequested || (lastFrame && !options.screenshot.empty())) {
      const std::string path =
          lastFrame && !options.screenshot.empty() ? options.screenshot : cv::screenshotName();
      glReadBuffer(GL_BACK);
      const std::string err = cv::saveScreenshot(path, fbW, fbH);
      if (!err.empty()) {
        model.fail("screenshot: " + err);
        if (lastFrame) exitCode = 1;
      } else {
        ui.notice = "screenshot written: " + path;
        ui.noticeUntil = now + 4.0;
      }
      ui.screenshotRequested = false;
    }
    if (headless) glFinish();  // time what the GL really did
    glfwSwapBuffers(window);

    if (ui.reloadShaders) {
      ui.reloadShaders = false;
      if (!renderer.reload()) model.fail("shaders failed to compile: see View");
    }
    const auto frameEnd = Clock::now();
    const double ms = std::chrono::duration<double, std::milli>(frameEnd - frameStart).count();
    ui.frameMs = ui.frameMs == 0.0
                     ? ms
                     : 0.9 * ui.frameMs +
                           0.1 * std::chrono::duration<double, std::milli>(frameEnd - last).count();
    last = frameEnd;
    if (frame > 1) {  // the first frame uploads everything; time the steady state
      timedMs += ms;
      ++timedFrames;
    }
    if (lastFrame) break;
  }

  if (headless) {
    std::printf(
        "convexloc-viewer: %d frames at %dx%d, %zu points (%zu drawn in the last), %s, mean %.2f "
        "ms/frame after the first (%s)\n",
        frame, options.width, options.height, renderer.pointCount(), view.pointsDrawn(),
        options.animate ? "camera moving" : "camera still",
        timedFrames ? timedMs / timedFrames : 0.0, ui.glInfo.c_str());
  }

  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return exitCode;
}
