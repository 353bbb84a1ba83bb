// convexloc-viewer — GLFW callbacks and keys, turned into the viewer's input and actions.
#include "platform/input.hpp"

#include <algorithm>

#define GLFW_INCLUDE_NONE  // the GL declarations come from gl/ alone
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <imgui.h>

namespace convexloc::viewer {
namespace {

// files dropped on the window since the last takeDroppedFiles
std::vector<std::string> gDropped;

void onDrop(GLFWwindow*, int count, const char** paths) {
  for (int i = 0; i < count; ++i) gDropped.emplace_back(paths[i]);
}

// Keys that went down since the last keyActions, in order. A presentation clicker's press
// and release can both fall between two frames, where ImGui's key state (down at the frame
// or not) would miss the press; the callback sees every one.
std::vector<int> gPressed;
bool gHadPresses = false;  // the last keyActions took some: the frames go on a while

void onKey(GLFWwindow* window, int key, int scancode, int action, int mods) {
  ImGui_ImplGlfw_KeyCallback(window, key, scancode, action, mods);
  if (action == GLFW_PRESS) gPressed.push_back(key);
}

// a key went down since the last frame (no repeats)
bool pressed(int key) {
  return std::find(gPressed.begin(), gPressed.end(), key) != gPressed.end();
}

// the keys that ask for one action each, while ImGui does not want the keyboard
struct KeyBinding {
  int key;
  ActionKind kind;
};
constexpr KeyBinding kKeys[] = {
    {GLFW_KEY_F, ActionKind::Fit},          {GLFW_KEY_H, ActionKind::ToggleUi},
    {GLFW_KEY_T, ActionKind::ToggleTheme},  {GLFW_KEY_ESCAPE, ActionKind::ClearPoint},
    {GLFW_KEY_SPACE, ActionKind::NewSpray}, {GLFW_KEY_L, ActionKind::ToggleLines},
    {GLFW_KEY_V, ActionKind::SaveSvg},      {GLFW_KEY_P, ActionKind::TogglePresent},
    {GLFW_KEY_G, ActionKind::ToggleLegend},
};
// a lecture's keys: what a presentation clicker sends
constexpr KeyBinding kSlideKeys[] = {
    {GLFW_KEY_PAGE_DOWN, ActionKind::NextSlide},
    {GLFW_KEY_PAGE_UP, ActionKind::PreviousSlide},
    {GLFW_KEY_HOME, ActionKind::FirstSlide},
    {GLFW_KEY_END, ActionKind::LastSlide},
};
// keys 1..5 choose a method
constexpr int kMethodKeys = 5;
// the placed point's query step by step (the arrows repeat while held)
constexpr KeyBinding kStepKeys[] = {{GLFW_KEY_LEFT, ActionKind::PrevStep},
                                    {GLFW_KEY_RIGHT, ActionKind::NextStep}};

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
  return in;
}

std::vector<Action> keyActions() {
  std::vector<Action> actions;
  // the presses are taken once, whether ImGui wants the keyboard or not
  gHadPresses = !gPressed.empty();
  struct Taken {
    ~Taken() { gPressed.clear(); }
  } taken;
  if (pressed(GLFW_KEY_F12))
    actions.push_back({ImGui::GetIO().KeyShift ? ActionKind::SaveSvg : ActionKind::Screenshot, 0});
  if (ImGui::GetIO().WantCaptureKeyboard) return actions;
  for (const KeyBinding& b : kKeys)
    if (pressed(b.key)) actions.push_back({b.kind, 0});
  for (const KeyBinding& b : kSlideKeys)
    if (pressed(b.key)) actions.push_back({b.kind, 0});
  for (int k = 0; k < kMethodKeys; ++k)
    if (pressed(GLFW_KEY_1 + k)) actions.push_back({ActionKind::ChooseMethod, k});
  for (const KeyBinding& b : kStepKeys)
    if (ImGui::IsKeyPressed(b.key, true)) actions.push_back({b.kind, 0});
  if (pressed(GLFW_KEY_R)) actions.push_back({ActionKind::ToggleRadii, 0});
  return actions;
}

bool hadInput(bool dropped) {
  const ImGuiIO& io = ImGui::GetIO();
  bool input = io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f || io.MouseWheel != 0.0f ||
               dropped || gHadPresses;
  for (bool b : io.MouseDown) input |= b;
  for (bool k : io.KeysDown) input |= k;
  return input;
}

}  // namespace convexloc::viewer
