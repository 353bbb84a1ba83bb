// convexloc-viewer — the frame's windows: the left panel (Shape, Method, Points, View),
// the right panel (legend and inspector) or their floating forms, the toasts, the labels
// over the scene; and the keys' actions.
#include "ui/layout.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iostream>
#include <iterator>

#include <imgui.h>
#include <imgui_internal.h>

#include "logic/view/fit_room.hpp"
#include "logic/view/label_layout.hpp"
#include "logic/narration/text.hpp"
#include "ui/lecture_panel.hpp"
#include "ui/panels2d.hpp"
#include "ui/panels3d.hpp"
#include "ui/steps_panel.hpp"
#include "logic/view/scene_labels.hpp"
#include "ui/scaling_panel.hpp"
#include "ui/views_panel.hpp"
#include "ui/widgets.hpp"

namespace convexloc::viewer {
namespace {

// the panels of the scene shown
const ScenePanels& panelsOf(const Model& model) {
  return model.dim == Dim::Two ? panels2D() : panels3D();
}

// === View

// the presentation mode and legend check boxes
void presentControls(Model& model, UiState& ui) {
  Settings& s = model.settings;
  bool present = s.present;
  if (ImGui::Checkbox("presentation (P)", &present))
    perform({ActionKind::TogglePresent, 0}, model, ui);
  ImGui::SameLine();
  bool legend = s.showLegend;
  if (ImGui::Checkbox("legend (G)", &legend)) perform({ActionKind::ToggleLegend, 0}, model, ui);
}

// Screenshot and SVG, and the directory they write to
void exportButtons(UiState& ui, float half) {
  if (ImGui::Button("Screenshot", ImVec2(half, 0.0f))) ui.screenshotRequested = true;
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("F12: a PNG of the window, in the folder below");
  ImGui::SameLine();
  if (ImGui::Button("SVG", ImVec2(half, 0.0f))) ui.svgRequested = true;
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("V or Shift+F12: the scene as a vector figure, in the folder below");
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::InputTextWithHint("##exportdir", "save to: the working directory", ui.exportDirEdit,
                               sizeof ui.exportDirEdit))
    ui.exportDir = ui.exportDirEdit;
}

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

  presentControls(model, ui);
  const float half = 0.5f * (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x);
  exportButtons(ui, half);
  if (ImGui::Button("Fit (F)", ImVec2(half, 0.0f))) model.requestFit();
  ImGui::SameLine();
  if (ImGui::Button("Shaders", ImVec2(half, 0.0f))) ui.reloadShaders = true;
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
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  textAtSpaces(ui.glInfo);
  ImGui::PopStyleColor();
}

// The legend alone, over the scene's lower right corner (above the caption), or where the
// user dragged it; its size is kept for the next fit, which leaves room for it.
void legendOverlay(Model& model, UiState& ui, ScreenRect area, glm::dvec2 window, double now) {
  if (ui.legendMoved) {
    const float x = std::clamp(ui.legendPos[0], 0.0f, static_cast<float>(window.x) - 40.0f);
    const float y = std::clamp(ui.legendPos[1], 0.0f, static_cast<float>(window.y) - 30.0f);
    ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always);
  } else {
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(area.hi.x) - 10.0f,
                                   static_cast<float>(area.hi.y) - ui.captionHeight - 10.0f),
                            ImGuiCond_Always, ImVec2(1.0f, 1.0f));
  }
  ImGui::SetNextWindowBgAlpha(0.82f);
  ImGui::Begin("Legend", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
  panelsOf(model).legend(model);
  // dragged by hand (ImGui's own moving would fight the corner placement)
  const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  // a drag that began on the legend moves it until the button is let go
  if (ImGui::IsWindowHovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left))
    ui.legendDragging = true;
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) ui.legendDragging = false;
  const ImVec2 delta = ImGui::GetIO().MouseDelta;
  if (ui.legendDragging && (delta.x != 0.0f || delta.y != 0.0f) && ImGui::IsMousePosValid()) {
    ui.legendMoved = true;
    ui.legendPos[0] = pos.x + delta.x;
    ui.legendPos[1] = pos.y + delta.y;
  } else if (ImGui::IsWindowHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
    ui.legendMoved = false;  // back to the corner, and the scene fitted beside it
    model.requestFit();
  } else if (ImGui::IsWindowHovered()) {
    ImGui::SetTooltip("drag to move, double-click: back to the corner; G hides the legend");
  }
  if ((std::abs(size.x - ui.legendSize[0]) > 2.0f || std::abs(size.y - ui.legendSize[1]) > 2.0f) &&
      now < ui.refitUntil)
    model.requestFit();  // fitted a moment ago for another size: fit again
  ui.legendSize[0] = size.x;
  ui.legendSize[1] = size.y;
  // where it is, for the labels to keep off
  ui.legendRect[0] = pos.x, ui.legendRect[1] = pos.y;
  ui.legendRect[2] = pos.x + size.x, ui.legendRect[3] = pos.y + size.y;
  ImGui::End();
}

// the caption, large, in a box along the bottom of the scene area
void captionBox(Model& model, UiState& ui, ScreenRect area) {
  // a caption of another height (a new slide's) leaves the scene other room: refit
  struct Refit {
    Model& model;
    const float before;
    const float& now;
    ~Refit() {
      if (std::abs(now - before) > 1.0f) model.requestFit();
    }
  } refit{model, ui.captionHeight, ui.captionHeight};
  ui.captionHeight = 0.0f;
  if (model.settings.caption.empty()) return;
  const float w = static_cast<float>(area.size().x) * 0.9f;
  ImGui::SetNextWindowPos(
      ImVec2(static_cast<float>(area.middle().x), static_cast<float>(area.hi.y) - 8.0f),
      ImGuiCond_Always, ImVec2(0.5f, 1.0f));
  ImGui::SetNextWindowBgAlpha(0.9f);
  ImGui::Begin("##caption", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav |
                   ImGuiWindowFlags_NoInputs);
  ImGui::SetWindowFontScale(1.5f);
  const auto measure = [](std::string_view t) { return measureText(t); };
  for (const std::string& line :
       breakAtSpaces(model.settings.caption, w - 2.0f * ImGui::GetStyle().WindowPadding.x, measure))
    ImGui::TextUnformatted(line.c_str());
  ui.captionHeight = ImGui::GetWindowHeight() + 8.0f;
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
    // broken at spaces only: a number never splits across lines
    for (const std::string& line :
         breakAtSpaces(text, w - 2.0f * ImGui::GetStyle().WindowPadding.x, measureText))
      ImGui::TextUnformatted(line.c_str());
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
  ImGui::SetNextWindowBgAlpha(1.0f);  // opaque: the scene never shows through a panel
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
  // a new comparison table folds the Shape panel, so that the table shows without scrolling
  const std::size_t compared = ui.compare2d.size() + ui.compare3d.size();
  if (compared != ui.compareSeen && compared > 0) ImGui::SetNextItemOpen(false);
  ui.compareSeen = compared;
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
  ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
  for (const char* const* line = panelsOf(model).hints; *line; ++line)
    ImGui::TextWrapped("%s", *line);
  ImGui::PopStyleColor();
}

// the left window: title, dimension, the scene's panels, View, hints
void leftPanel(Model& model, Renderer& renderer, UiState& ui, glm::dvec2 window) {
  sideWindow("convexloc", 0.0f, leftPanelWidth(model, window), window.y);
  dimensionButtons(model);
  // a lecture's slides first, where one is open; else the figures at the end
  const bool lecture = ui.show.lecture.slides.size() > 1;
  if (lecture) lecturePanel(model, ui);
  scenePanels(model, ui);
  if (ImGui::CollapsingHeader("View")) viewPanel(model, renderer, ui);
  if (!lecture) lecturePanel(model, ui);
  hints(model);
  ImGui::End();
}

// the right window: the legend over the inspector
void rightPanel(Model& model, glm::dvec2 window, float width) {
  sideWindow("What you see", static_cast<float>(window.x) - width, width, window.y);
  if (model.settings.showLegend) {
    panelsOf(model).legend(model);
    ImGui::Separator();
  }
  panelsOf(model).inspector(model, true);
  ImGui::End();
}

// the inspector floating over the scene's upper right corner (no right panel), above the
// legend when that sits in the corner below
void floatingInspector(Model& model, const UiState& ui, ScreenRect area, glm::dvec2 window) {
  const float iw =
      std::min(360.0f * model.settings.fontScale, static_cast<float>(area.size().x) * 0.6f);
  float ih = static_cast<float>(window.y) * 0.6f;
  if (model.settings.showLegend && !ui.legendMoved)
    ih = std::min(ih,
                  static_cast<float>(area.size().y) - ui.legendSize[1] - ui.captionHeight - 36.0f);
  ImGui::SetNextWindowPos(ImVec2(static_cast<float>(area.hi.x) - iw - 8.0f, 8.0f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(iw, 0.0f), ImVec2(iw, std::max(ih, 120.0f)));
  ImGui::SetNextWindowBgAlpha(0.9f);
  ImGui::Begin("Inspector", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                   ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoFocusOnAppearing);
  panelsOf(model).inspector(model, false);
  ImGui::End();
}

// the labels of `lists` over the scene, placed as the SVG places them: no two overlap, none
// sits on a marker
void writeLabels(const Model& model, ImDrawList* dl, const ScreenProjection& project,
                 std::span<const DrawList* const> lists, std::span<const PixelBox> windows) {
  const glm::dvec2 vp =
      model.dim == Dim::Two ? model.camera2d.viewport() : model.camera3d.viewport();
  const ScreenRect area = sceneArea(model, vp);
  const Palette& pal = paletteFor(model.settings.theme);
  const ImU32 shadow = packAbgr(withAlpha(pal.background, 0.85f));
  const float halo = std::max(1.0f, std::round(model.settings.drawScale()));
  for (const PlacedSceneLabel& p :
       layoutSceneLabels(lists, 1, project, {area.lo, area.hi}, measureText,
                         model.settings.drawScale(), 400, windows)) {
    const char* text = p.label->text.c_str();
    const ImVec2 at(std::round(static_cast<float>(p.place.centre.x - 0.5 * p.place.size.x)),
                    std::round(static_cast<float>(p.place.centre.y - 0.5 * p.place.size.y)));
    if (p.place.leader)
      dl->AddLine(
          ImVec2(static_cast<float>(p.anchor.x), static_cast<float>(p.anchor.y)),
          ImVec2(static_cast<float>(p.place.centre.x), static_cast<float>(p.place.centre.y)),
          packAbgr(withAlpha(p.label->colour, 0.6f)), 1.0f);
    // a halo of the background all round, as thick as the lines are scaled
    for (const ImVec2 d : {ImVec2(-1, 0), ImVec2(1, 0), ImVec2(0, -1), ImVec2(0, 1), ImVec2(-1, -1),
                           ImVec2(1, -1), ImVec2(-1, 1), ImVec2(1, 1)})
      dl->AddText(ImVec2(at.x + d.x * halo, at.y + d.y * halo), shadow, text);
    dl->AddText(at, packAbgr(readableOn(p.label->colour, pal.background, pal.text)), text);
  }
}

// === Fitting beside the Steps window

// the drawn shape's width over its height, about (the 3D scenes as a square)
double shapeAspect(const Model& model) {
  if (model.dim == Dim::Three) return model.planes3d.enabled() ? 2.0 : 1.0;
  if (model.lines2d.enabled()) return 2.0;  // the dual view sits beside
  const Box2 b = model.scene2d.polygon().bounds();
  const double w = b.hi.x - b.lo.x, h = b.hi.y - b.lo.y;
  return w > 0.0 && h > 0.0 ? std::clamp(w / h, 0.2, 5.0) : 1.0;
}

// a rectangle of the window as ImGui's clip rectangle
void pushClip(ImDrawList* dl, const ScreenRect& r) {
  dl->PushClipRect(ImVec2(static_cast<float>(r.lo.x), static_cast<float>(r.lo.y)),
                   ImVec2(static_cast<float>(r.hi.x), static_cast<float>(r.hi.y)));
}

}  // namespace

float leftPanelWidth(const Model& model, glm::dvec2 window) {
  if (!model.settings.showUi) return 0.0f;
  // as wide as the text needs at its scale, up to 45% of the window (longer lines wrap)
  const float cap = std::max(300.0f, static_cast<float>(0.45 * window.x));
  return std::min(345.0f * model.settings.fontScale, cap);
}

float rightPanelWidth(const Model& model, glm::dvec2 window) {
  // narrower windows keep the scene wide: legend and inspector float over it instead
  const float fs = model.settings.fontScale;
  if (!model.settings.showUi || window.x < 1280.0 * std::max(1.0f, 0.75f * fs)) return 0.0f;
  return std::min(330.0f * fs, static_cast<float>(0.26 * window.x));
}

namespace {

// the Steps window's strip, and the legend's with it (logic/view/fit_room.hpp)
void leaveRoomForSteps(ScreenRect& a, const UiState& ui, ScreenRect full, double aspect) {
  full.hi.y -= ui.captionHeight;
  CornerBoxes boxes;
  boxes.steps = {ui.stepsSize[0], ui.stepsSize[1]};
  if (a.hi.x < full.hi.x || a.hi.y < full.hi.y)  // the fit gave the legend a strip
    boxes.legend = {ui.legendSize[0] + 20.0, ui.legendSize[1] + 20.0};
  a = roomBesideCorners(a, full, boxes, aspect);
}

}  // namespace

void fitScene(Model& model, UiState& ui, glm::dvec2 window, double now) {
  ScreenRect a = sceneArea(model, window);
  a.hi.y -= ui.captionHeight;
  const bool floatingLegend = model.settings.showLegend && rightPanelWidth(model, window) == 0.0f;
  if (floatingLegend && !ui.legendMoved && ui.legendSize[0] > 0.0f) {
    // give up the strip, right or bottom, that costs the scene less
    const glm::dvec2 s = a.size();
    const double lw = ui.legendSize[0] + 20.0, lh = ui.legendSize[1] + 20.0;
    if (s.x > lw && s.y > lh) {
      if ((s.x - lw) / s.x >= (s.y - lh) / s.y)
        a.hi.x -= lw;
      else
        a.hi.y -= lh;
    }
  }
  // (the split view's halves share the whole area: its Steps window stays over it)
  if (ui.stepsSize[0] > 0.0f && !(model.dim == Dim::Two && model.split.enabled()))
    leaveRoomForSteps(a, ui, sceneArea(model, window), shapeAspect(model));
  model.fit(a);
  ui.refitUntil = now + 1.5;
}

ScreenRect sceneArea(const Model& model, glm::dvec2 window) {
  return {{static_cast<double>(leftPanelWidth(model, window)),
           static_cast<double>(model.settings.slideCardHeight)},
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
  // the panel's settings, taken from the scene first where the scene's changed
  followSpray(
      ui, model.dim == Dim::Two ? model.scene2d.spraySettings() : model.scene3d().spraySettings());
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
    // the placed point's query step by step
    case ActionKind::PrevStep: model.stepBy(false); break;
    case ActionKind::NextStep: model.stepBy(true); break;
    case ActionKind::ToggleRadii: model.setPaperMode(!model.settings.paperMode); break;
    case ActionKind::SaveSvg: ui.svgRequested = true; break;
    case ActionKind::TogglePresent:
      model.settings.present = !model.settings.present;
      model.settings.showUi = !model.settings.present;
      model.requestFit();
      break;
    case ActionKind::ToggleLegend:
      model.settings.showLegend = !model.settings.showLegend;
      model.requestFit();
      break;
    case ActionKind::ChooseMethod:
      if (model.dim == Dim::Two)
        model.scene2d.setMethod(kAllMethods2D[action.method]);
      else if (action.method < static_cast<int>(std::size(kAllMethods3D)))
        model.scene3d().setMethod(kAllMethods3D[action.method]);
      break;
    // a lecture's slides
    case ActionKind::NextSlide:
    case ActionKind::PreviousSlide:
    case ActionKind::FirstSlide:
    case ActionKind::LastSlide: moveSlide(action.kind, model, ui); break;
  }
}

void drawUi(Model& model, Renderer& renderer, UiState& ui, double now) {
  const ImGuiIO& io = ImGui::GetIO();
  const glm::dvec2 window{io.DisplaySize.x, io.DisplaySize.y};
  const ScreenRect area = sceneArea(model, window);
  if (model.settings.showUi) leftPanel(model, renderer, ui, window);
  const float rw = rightPanelWidth(model, window);
  captionBox(model, ui, area);
  std::fill(std::begin(ui.legendRect), std::end(ui.legendRect), 0.0f);  // until drawn again
  if (rw > 0.0f) {
    rightPanel(model, window, rw);
  } else {
    if (model.settings.showLegend) legendOverlay(model, ui, area, window, now);
    if (model.settings.showUi && panelsOf(model).inspectable(model))
      floatingInspector(model, ui, area, window);
  }
  stepsWindow(model, ui, area, now);  // also with the panels hidden; the fit leaves it room
  slideCard(model, ui, area);
  toast(model, ui, area, now);
  // the teaching views: the split's halves and second scene, the build's clock, Why O(1)
  // (no halves in 3D or the Lines mode: the pointer then goes where it is)
  const bool halves = model.dim == Dim::Two && !model.lines2d.enabled();
  model.split.setArea(halves ? area : ScreenRect{});
  if (model.split.enabled() && halves) model.split.sync(model.scene2d);
  advanceBuild(model, io.DeltaTime);
  scalingWindow(model, ui);
}

void drawLabels(Model& model, const UiState& ui, const SceneView& view) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  // the windows floating over the scene, which labels keep off where they can
  std::vector<PixelBox> windows;
  for (const float* w : {ui.legendRect, ui.stepsRect})
    if (w[2] > w[0]) windows.push_back({{w[0], w[1]}, {w[2], w[3]}});
  const DrawList* lists[] = {&view.structure(), &view.overlay()};
  const bool split = model.dim == Dim::Two && model.split.enabled() && !model.lines2d.enabled();
  if (!split) {
    writeLabels(model, dl, sceneProjection(model), lists, windows);
    return;
  }
  // each half's labels, clipped to it, the right half's through its own camera
  pushClip(dl, model.split.left());
  writeLabels(model, dl, sceneProjection(model), lists, windows);
  dl->PopClipRect();
  pushClip(dl, model.split.right());
  const Camera2D right = model.split.rightCamera(model.camera2d);
  const DrawList* rightLists[] = {&view.splitStructure(), &view.splitOverlay()};
  writeLabels(
      model, dl,
      [right](glm::dvec3 p) -> std::optional<glm::dvec3> {
        return glm::dvec3(right.toScreen({p.x, p.y}), 0.0);
      },
      rightLists, windows);
  dl->PopClipRect();
  splitDecorations(model);
}

}  // namespace convexloc::viewer
