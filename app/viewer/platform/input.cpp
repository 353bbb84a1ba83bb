// convexloc-viewer — GLFW callbacks and keys, turned into the viewer's input and actions.
#include "platform/input.hpp"

#include <algorithm>
#include <cmath>

#define GLFW_INCLUDE_NONE  // the GL declarations come from gl/ alone
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

#include "logic/app/key_queue.hpp"

namespace convexloc::viewer {
namespace {

// files dropped on the window since the last takeDroppedFiles
std::vector<std::string> gDropped;

void onDrop(GLFWwindow*, int count, const char** paths) {
  for (int i = 0; i < count; ++i) gDropped.emplace_back(paths[i]);
}

// every key the viewer acts on, and its action
constexpr KeyBinding kKeys[] = {
    // F12 always (a screenshot even while typing), Shift+F12 the SVG
    {GLFW_KEY_F12, {ActionKind::SaveSvg, 0}, false, true, 1},
    {GLFW_KEY_F12, {ActionKind::Screenshot, 0}, false, true, 0},
    {GLFW_KEY_F, {ActionKind::Fit, 0}},
    {GLFW_KEY_H, {ActionKind::ToggleUi, 0}},
    {GLFW_KEY_T, {ActionKind::ToggleTheme, 0}},
    {GLFW_KEY_ESCAPE, {ActionKind::ClearPoint, 0}},
    {GLFW_KEY_SPACE, {ActionKind::NewSpray, 0}},
    {GLFW_KEY_L, {ActionKind::ToggleLines, 0}},
    {GLFW_KEY_V, {ActionKind::SaveSvg, 0}},
    {GLFW_KEY_P, {ActionKind::TogglePresent, 0}},
    {GLFW_KEY_G, {ActionKind::ToggleLegend, 0}},
    {GLFW_KEY_R, {ActionKind::ToggleRadii, 0}},
    // the text zoom: + (= unshifted) and -, on the main keys and the keypad
    {GLFW_KEY_EQUAL, {ActionKind::TextLarger, 0}},
    {GLFW_KEY_KP_ADD, {ActionKind::TextLarger, 0}},
    {GLFW_KEY_MINUS, {ActionKind::TextSmaller, 0}},
    {GLFW_KEY_KP_SUBTRACT, {ActionKind::TextSmaller, 0}},
    // a lecture's keys: what a presentation clicker sends (its blank key sends B or '.')
    {GLFW_KEY_PAGE_DOWN, {ActionKind::NextSlide, 0}},
    {GLFW_KEY_PAGE_UP, {ActionKind::PreviousSlide, 0}},
    {GLFW_KEY_HOME, {ActionKind::FirstSlide, 0}},
    {GLFW_KEY_END, {ActionKind::LastSlide, 0}},
    {GLFW_KEY_B, {ActionKind::ToggleBlank, 0}},
    {GLFW_KEY_PERIOD, {ActionKind::ToggleBlank, 0}},
    {GLFW_KEY_N, {ActionKind::ToggleNotes, 0}},
    {GLFW_KEY_D, {ActionKind::DismissProblems, 0}},
    // keys 1..5 choose a method
    {GLFW_KEY_1, {ActionKind::ChooseMethod, 0}},
    {GLFW_KEY_2, {ActionKind::ChooseMethod, 1}},
    {GLFW_KEY_3, {ActionKind::ChooseMethod, 2}},
    {GLFW_KEY_4, {ActionKind::ChooseMethod, 3}},
    {GLFW_KEY_5, {ActionKind::ChooseMethod, 4}},
    // the placed point's query step by step (the arrows repeat while held)
    {GLFW_KEY_LEFT, {ActionKind::PrevStep, 0}, true},
    {GLFW_KEY_RIGHT, {ActionKind::NextStep, 0}, true},
};

// Every key press since the last keyActions, as actions in order. A presentation clicker's
// press and release can both fall between two frames, where ImGui's key state (down at the
// frame or not) would miss the press, and three quick presses would read as one; the
// callback sees every one.
KeyQueue gKeys(kKeys);
bool gPressedSince = false;  // a key went down since the last keyActions
bool gHadPresses = false;    // the last keyActions took some: the frames go on a while

// the page's pinches since the last pointerInput, and whether a gesture came this frame
double gZoom = 1.0;
glm::dvec2 gPan{0.0};
bool gGestured = false;
// the actions the page's own buttons and swipes asked for since the last keyActions
std::vector<Action> gPageActions;

void onKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
  ImGui_ImplGlfw_KeyCallback(window, key, scancode, action, mods);
  if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
  gPressedSince = true;
  // whether a text field has the keyboard, as ImGui decided at the last frame
  gKeys.press({key, action == GLFW_REPEAT, (mods & GLFW_MOD_SHIFT) != 0},
              ImGui::GetIO().WantCaptureKeyboard);
}

}  // namespace

void watchDrops(GLFWwindow* window) {
  glfwSetDropCallback(window, onDrop);
}

void watchKeys(GLFWwindow* window) {
  glfwSetKeyCallback(window, onKey);
}

std::vector<std::string> takeDroppedFiles() {
  std::vector<std::string> files;
  files.swap(gDropped);
  return files;
}

void openLater(const std::string& path) {
  gDropped.push_back(path);
}

PointerInput pointerInput(bool hovering) {
  const ImGuiIO& io = ImGui::GetIO();
  PointerInput in;
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
  in.alt = io.KeyAlt;
  in.hovering = ImGui::IsMousePosValid() && hovering;
  in.zoom = gZoom;
  in.pan = gPan;
  gZoom = 1.0;
  gPan = glm::dvec2(0.0);
  return in;
}

std::vector<Action> keyActions() {
  gHadPresses = gPressedSince;
  gPressedSince = false;
  std::vector<Action> actions = gKeys.drain();
  actions.insert(actions.end(), gPageActions.begin(), gPageActions.end());
  gPageActions.clear();
  return actions;
}

bool hadInput(bool dropped) {
  const ImGuiIO& io = ImGui::GetIO();
  bool input = io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f || io.MouseWheel != 0.0f ||
               dropped || gHadPresses || gGestured;
  gGestured = false;
  for (bool b : io.MouseDown) input |= b;
  for (bool k : io.KeysDown) input |= k;
  return input;
}

}  // namespace convexloc::viewer

extern "C" void convexloc_wheel(double x, double y, bool sceneZoom) {
  using convexloc::viewer::gZoom;
  convexloc::viewer::gGestured = true;
  if (sceneZoom) {
    gZoom *= std::pow(convexloc::viewer::Interaction::kWheelZoom, y);
    return;
  }
  ImGuiIO& io = ImGui::GetIO();
  io.MouseWheelH += static_cast<float>(x);
  io.MouseWheel += static_cast<float>(y);
}

extern "C" void convexloc_pinch(double factor, double dx, double dy) {
  convexloc::viewer::gGestured = true;
  if (factor > 0.0 && std::isfinite(factor)) convexloc::viewer::gZoom *= factor;
  convexloc::viewer::gPan += glm::dvec2(dx, dy);
}

extern "C" void convexloc_scroll_pixels(double dy) {
  convexloc::viewer::gGestured = true;
  // ImGui scrolls a window by a step of five lines a notch (at most two thirds of it)
  const float step = std::max(1.0f, std::floor(5.0f * ImGui::GetFontSize()));
  ImGui::GetIO().MouseWheel += static_cast<float>(dy) / step;
}

extern "C" void convexloc_lecture_step(int direction) {
  using convexloc::viewer::ActionKind;
  convexloc::viewer::gGestured = true;
  convexloc::viewer::gPageActions.push_back(
      {direction > 0 ? ActionKind::NextSlide : ActionKind::PreviousSlide, 0});
}
