// convexloc-viewer — the speaker notes' own window.
#include "platform/notes_window.hpp"

#define GLFW_INCLUDE_NONE  // the GL declarations come from gl/ alone
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "gl/gl.hpp"
#include "platform/input.hpp"

namespace convexloc::viewer {
namespace {

// the notes' text size: large enough to read at arm's length
constexpr float kNotesFontPixels = 26.0f;

// makes `window`'s GL context and `context` current, and gives back the ones that were
class CurrentContexts {
 public:
  CurrentContexts(GLFWwindow* window, ImGuiContext* context)
      : window_(glfwGetCurrentContext()), context_(ImGui::GetCurrentContext()) {
    glfwMakeContextCurrent(window);
    ImGui::SetCurrentContext(context);
  }
  ~CurrentContexts() {
    glfwMakeContextCurrent(window_);
    ImGui::SetCurrentContext(context_);
  }
  CurrentContexts(const CurrentContexts&) = delete;
  CurrentContexts& operator=(const CurrentContexts&) = delete;

 private:
  GLFWwindow* window_;
  ImGuiContext* context_;
};

}  // namespace

NotesWindow::~NotesWindow() {
  close();
}

bool NotesWindow::open(GLFWwindow* main, const std::function<void(float)>& fonts) {
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SAMPLES, 0);
  window_ = glfwCreateWindow(900, 520, "convexloc-viewer: speaker notes", nullptr, nullptr);
  if (!window_) {
    failed_ = true;
    return false;
  }
  ImGuiContext* before = ImGui::GetCurrentContext();
  context_ = ImGui::CreateContext();
  {
    const CurrentContexts here(window_, context_);
    glfwSwapInterval(0);  // the main window keeps the display's pace
    ImGui::GetIO().IniFilename = nullptr;
    ImGui::StyleColorsDark();
    // no ImGui callbacks: the keys pressed here are the lecture's, as in the main window
    ImGui_ImplGlfw_InitForOpenGL(window_, false);
    watchKeys(window_);
    ImGui_ImplOpenGL3_Init("#version 330 core");
    fonts(kNotesFontPixels);
  }
  ImGui::SetCurrentContext(before);
  glfwMakeContextCurrent(main);
  return true;
}

void NotesWindow::close() {
  if (!window_) return;
  {
    const CurrentContexts here(window_, context_);
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
  }
  ImGui::DestroyContext(context_);
  glfwDestroyWindow(window_);
  window_ = nullptr;
  context_ = nullptr;
}

bool NotesWindow::update(bool& wanted, GLFWwindow* main, const std::function<void(float)>& fonts,
                         const std::function<void()>& contents) {
  if (window_ && glfwWindowShouldClose(window_)) wanted = false;
  if (!wanted) {
    close();
    return !failed_;
  }
  if (failed_ || (!window_ && !open(main, fonts))) return false;
  const CurrentContexts here(window_, context_);
  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  contents();
  ImGui::Render();
  int w = 0, h = 0;
  glfwGetFramebufferSize(window_, &w, &h);
  glViewport(0, 0, w, h);
  glClearColor(0.1f, 0.1f, 0.11f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  glfwSwapBuffers(window_);
  return true;
}

}  // namespace convexloc::viewer
