// convexloc-viewer — the frame's windows: the left panel (Shape, Method, Points, View),
// the right panel (legend and inspector) or their floating forms, the toasts, the labels
// over the scene; and the keys' actions.
#include "ui/layout.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>

#include <imgui.h>

#include "logic/text.hpp"
#include "ui/panels2d.hpp"
#include "ui/panels3d.hpp"
#include "ui/widgets.hpp"

namespace convexloc::viewer {
namespace {

// the panels of the scene shown
const ScenePanels& panelsOf(const Model& model) {
  return model.dim == Dim::Two ? panels2D() : panels3D();
}

// === View

void viewPanel(Model& model, Renderer& renderer, UiState& ui) {
  int theme = static_cast<int>(model.settings.theme);
  if (ImGui::RadioButton("dark", theme == 0)) model.settings.theme = Theme::Dark;
  ImGui::SameLine();
  if (ImGui::RadioButton("light", theme == 1)) model.settings.theme = Theme::Light;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::SliderFloat("##font", &ui.fontScaleEdit, 0.75f, 2.5f, "text %.2fx");
  if (ImGui::IsItemDeactivatedAfterEdit()) ui.pendingFontScale = ui.fontScaleEdit;

  panelsOf(model).viewOptions(model);

  const float third =
      (ImGui::GetContentRegionAvail().x - 2.0f * ImGui::GetStyle().ItemSpacing.x) / 3.0f;
  if (ImGui::Button("Fit (F)", ImVec2(third, 0.0f))) model.requestFit();
  ImGui::SameLine();
  if (ImGui::Button("Screenshot", ImVec2(third, 0.0f))) ui.screenshotRequested = true;
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("F12: a PNG of the window in the working directory");
  ImGui::SameLine();
  if (ImGui::Button("Shaders", ImVec2(third, 0.0f))) ui.reloadShaders = true;
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("Reload the shaders from %s", renderer.shaderDir().c_str());
  if (!renderer.shaderLog().empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, im(paletteFor(model.settings.theme).negative));
    ImGui::TextWrapped("%s", renderer.shaderLog().c_str());
    ImGui::PopStyleColor();
  }
  ImGui::TextDisabled("%.2f ms/frame (%.0f fps), %s points", ui.frameMs,
                      ui.frameMs > 0 ? 1000.0 / ui.frameMs : 0.0,
                      grouped(renderer.pointCount()).c_str());
  if (!ui.glInfo.empty()) ImGui::TextDisabled("%s", ui.glInfo.c_str());
}

// the legend alone, over the scene's lower right corner (panels hidden)
void legendOverlay(Model& model, ScreenRect area) {
  ImGui::SetNextWindowPos(
      ImVec2(static_cast<float>(area.hi.x) - 10.0f, static_cast<float>(area.hi.y) - 10.0f),
      ImGuiCond_Always, ImVec2(1.0f, 1.0f));
  ImGui::SetNextWindowBgAlpha(0.82f);
  ImGui::Begin("Legend", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
  panelsOf(model).legend(model);
  ImGui::End();
}

// === Toast

void toast(Model& model, UiState& ui, ScreenRect area, double now) {
  if (model.errorSerial() != ui.toastSerial) {
    ui.toastSerial = model.errorSerial();
    ui.toast = model.error();
    ui.toastUntil = now + 9.0;
    if (!ui.toast.empty()) std::cerr << "convexloc-viewer: " << ui.toast << "\n";
  }
  const Palette& pal = paletteFor(model.settings.theme);
  float y = 10.0f;
  auto banner = [&](const char* id, const std::string& text, Rgba colour, bool closable,
                    double& until) {
    if (text.empty() || now > until) return;
    const float w =
        std::min(static_cast<float>(area.size().x) - 40.0f, ImGui::GetFontSize() * 36.0f);
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(area.middle().x), y), ImGuiCond_Always,
                            ImVec2(0.5f, 0.0f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(w, 0.0f), ImVec2(w, 400.0f));
    ImGui::SetNextWindowBgAlpha(0.95f);
    ImGui::PushStyleColor(ImGuiCol_Border, im(colour));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 1.5f);
    ImGui::Begin(id, nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
    ImGui::PushStyleColor(ImGuiCol_Text, im(colour));
    ImGui::TextWrapped("%s", text.c_str());
    ImGui::PopStyleColor();
    if (closable && ImGui::SmallButton("dismiss")) until = 0.0;
    y += ImGui::GetWindowHeight() + 6.0f;
    ImGui::End();
    ImGui::PopStyleVar();
    ImGui::PopStyleColor();
  };
  banner("##error", ui.toast, pal.negative, true, ui.toastUntil);
  banner("##notice", ui.notice, pal.positive, false, ui.noticeUntil);
}

// a window pinned to the side of the main window, the whole height
void sideWindow(const char* name, float x, float width, double height) {
  ImGui::SetNextWindowPos(ImVec2(x, 0.0f));
  ImGui::SetNextWindowSize(ImVec2(width, static_cast<float>(height)));
  ImGui::Begin(name, nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                   ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoBringToFrontOnFocus);
}

// the title, and the 2D and 3D buttons
void dimensionButtons(Model& model) {
  ImGui::Text("convexloc-viewer");
  ImGui::SameLine();
  ImGui::TextDisabled("point in convex %s", model.dim == Dim::Two ? "polygon" : "polyhedron");
  const float half = 0.5f * (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x);
  for (Dim d : {Dim::Two, Dim::Three}) {
    const bool on = model.dim == d;
    if (d == Dim::Three) ImGui::SameLine();
    if (on) ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
    if (ImGui::Button(d == Dim::Two ? "2D: polygon" : "3D: polyhedron", ImVec2(half, 0.0f)))
      model.show(d);
    if (on) ImGui::PopStyleColor();
  }
  ImGui::Separator();
}

// the scene's own panels, in the left window
void scenePanels(Model& model, UiState& ui) {
  const ScenePanels& p = panelsOf(model);
  if (ImGui::CollapsingHeader("Shape", ImGuiTreeNodeFlags_DefaultOpen)) p.shape(model, ui);
  if (ImGui::CollapsingHeader("Method", ImGuiTreeNodeFlags_DefaultOpen)) p.method(model, ui);
  if (p.ownTitle && ImGui::CollapsingHeader(p.ownTitle, ImGuiTreeNodeFlags_DefaultOpen))
    p.own(model);
  if (ImGui::CollapsingHeader("Points", p.pointsOpen ? ImGuiTreeNodeFlags_DefaultOpen : 0))
    p.points(model, ui);
}

// the mouse and key hints under the panels
void hints(const Model& model) {
  ImGui::Spacing();
  for (const char* const* line = panelsOf(model).hints; *line; ++line)
    ImGui::TextDisabled("%s", *line);
}

// the left window: title, dimension, the scene's panels, View, hints
void leftPanel(Model& model, Renderer& renderer, UiState& ui, glm::dvec2 window) {
  sideWindow("convexloc", 0.0f, leftPanelWidth(model, window), window.y);
  dimensionButtons(model);
  scenePanels(model, ui);
  if (ImGui::CollapsingHeader("View")) viewPanel(model, renderer, ui);
  hints(model);
  ImGui::End();
}

// the right window: the legend over the inspector
void rightPanel(Model& model, glm::dvec2 window, float width) {
  sideWindow("What you see", static_cast<float>(window.x) - width, width, window.y);
  panelsOf(model).legend(model);
  ImGui::Separator();
  panelsOf(model).inspector(model, true);
  ImGui::End();
}

// the inspector floating over the scene's upper right corner (no right panel)
void floatingInspector(Model& model, ScreenRect area, glm::dvec2 window) {
  const float iw =
      std::min(360.0f * model.settings.fontScale, static_cast<float>(area.size().x) * 0.6f);
  ImGui::SetNextWindowPos(ImVec2(static_cast<float>(area.hi.x) - iw - 8.0f, 8.0f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(iw, 0.0f),
                                      ImVec2(iw, static_cast<float>(window.y) * 0.6f));
  ImGui::SetNextWindowBgAlpha(0.9f);
  ImGui::Begin("Inspector", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                   ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoFocusOnAppearing);
  panelsOf(model).inspector(model, false);
  ImGui::End();
}

}  // namespace

float leftPanelWidth(const Model& model, glm::dvec2 window) {
  if (!model.settings.showUi) return 0.0f;
  return std::min(345.0f * model.settings.fontScale,
                  std::max(300.0f, static_cast<float>(0.32 * window.x)));
}

float rightPanelWidth(const Model& model, glm::dvec2 window) {
  // narrower windows keep the scene wide: legend and inspector float over it instead
  if (!model.settings.showUi || window.x < 1280.0) return 0.0f;
  return std::min(330.0f * model.settings.fontScale, static_cast<float>(0.26 * window.x));
}

ScreenRect sceneArea(const Model& model, glm::dvec2 window) {
  return {{static_cast<double>(leftPanelWidth(model, window)), 0.0},
          {window.x - static_cast<double>(rightPanelWidth(model, window)), window.y}};
}

void scanAssets(UiState& ui) {
  ui.assets.clear();
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(ui.assetDir, ec)) {
    const std::string ext = e.path().extension().string();
    const std::string name = e.path().filename().string();
    if ((ext == ".txt" || ext == ".off" || ext == ".obj") &&
        name.find("points") == std::string::npos)
      ui.assets.push_back(e.path().string());
  }
  std::sort(ui.assets.begin(), ui.assets.end());
}

void perform(const Action& action, Model& model, UiState& ui) {
  const SpraySettings spray{static_cast<std::size_t>(ui.sprayCount), ui.spraySeed + 1,
                            ui.sprayNear};
  switch (action.kind) {
    case ActionKind::Screenshot: ui.screenshotRequested = true; break;
    case ActionKind::Fit: model.requestFit(); break;
    case ActionKind::ToggleLines:
      if (model.dim == Dim::Two) model.setLinesMode(!model.lines2d.enabled());
      // 3D: the Planes mode
      if (model.dim == Dim::Three) model.setPlanesMode(!model.planes3d.enabled());
      break;
    case ActionKind::ToggleUi:
      model.settings.showUi = !model.settings.showUi;
      model.requestFit();  // the scene's area changed
      break;
    case ActionKind::ToggleTheme:
      model.settings.theme = model.settings.theme == Theme::Dark ? Theme::Light : Theme::Dark;
      break;
    case ActionKind::ClearPoint:
      if (model.dim == Dim::Two) {
        model.scene2d.clearProbe();
        model.lines2d.clearLine();
      } else {
        model.scene3d().clearProbe();
        model.scene3d().pin(-1);
      }
      break;
    case ActionKind::NewSpray:
      ++ui.spraySeed;
      if (model.dim == Dim::Two)
        model.scene2d.spray(spray);
      else
        model.scene3d().spray(spray);
      break;
    case ActionKind::ChooseMethod:
      if (model.dim == Dim::Two)
        model.scene2d.setMethod(kAllMethods2D[action.method]);
      else if (action.method < static_cast<int>(std::size(kAllMethods3D)))
        model.scene3d().setMethod(kAllMethods3D[action.method]);
      break;
  }
}

void drawUi(Model& model, Renderer& renderer, UiState& ui, double now) {
  const ImGuiIO& io = ImGui::GetIO();
  const glm::dvec2 window{io.DisplaySize.x, io.DisplaySize.y};
  const ScreenRect area = sceneArea(model, window);
  if (model.settings.showUi) leftPanel(model, renderer, ui, window);
  const float rw = rightPanelWidth(model, window);
  if (rw > 0.0f) {
    rightPanel(model, window, rw);
  } else {
    legendOverlay(model, area);
    if (model.settings.showUi && panelsOf(model).inspectable(model))
      floatingInspector(model, area, window);
  }
  toast(model, ui, area, now);
}

void drawLabels(Model& model, const SceneView& view) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const Camera2D& cam = model.camera2d;
  const Camera3D& cam3 = model.camera3d;
  const glm::dvec2 vp = cam.viewport();
  const Palette& pal = paletteFor(model.settings.theme);
  const ImU32 shadow = packAbgr(withAlpha(pal.background, 0.85f));
  int budget = 400;
  for (const DrawList* list : {&view.structure(), &view.overlay()})
    for (const Label& l : list->labels) {
      if (--budget < 0) return;
      glm::dvec2 s;
      if (model.dim == Dim::Two) {
        s = cam.toScreen({l.p.x, l.p.y}) + glm::dvec2(l.offset);
      } else {
        const Projected pr = cam3.toScreen(l.p);
        if (!pr.visible()) continue;
        s = pr.screen + glm::dvec2(l.offset);
      }
      if (s.x < -200.0 || s.y < -50.0 || s.x > vp.x + 200.0 || s.y > vp.y + 50.0) continue;
      const ImVec2 size = ImGui::CalcTextSize(l.text.c_str());
      const ImVec2 at(std::round(static_cast<float>(s.x) - 0.5f * size.x),
                      std::round(static_cast<float>(s.y) - 0.5f * size.y));
      for (const ImVec2 d : {ImVec2(-1, 0), ImVec2(1, 0), ImVec2(0, -1), ImVec2(0, 1)})
        dl->AddText(ImVec2(at.x + d.x, at.y + d.y), shadow, l.text.c_str());
      dl->AddText(at, packAbgr(l.colour), l.text.c_str());
    }
}

}  // namespace convexloc::viewer
