// convexloc-viewer — the frame's windows.
#include "ui/frame.hpp"

#include <algorithm>
#include <iterator>

#include <imgui.h>
#include <imgui_internal.h>

#include "ui/overlays.hpp"
#include "ui/panels/lecture_panel.hpp"
#include "ui/panels/panels2d.hpp"
#include "ui/panels/panels3d.hpp"
#include "ui/panels/scaling_panel.hpp"
#include "ui/panels/steps_panel.hpp"
#include "ui/panels/view_panel.hpp"
#include "ui/panels/views_panel.hpp"
#include "ui/scene_area.hpp"
#include "ui/slide_frame.hpp"
#include "ui/widgets.hpp"

namespace convexloc::viewer {

const ScenePanels& panelsOf(const Model& model) {
  return model.dim == Dim::Two ? panels2D() : panels3D();
}

namespace {

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

// a layout that leaves the scene other room fits again: a moment after a fit (the legend
// took its size), or while the view is as the last fit left it (a clicked point's Steps
// window appeared, a pinned cell made the legend taller)
void refitOnNewRoom(Model& model, const UiState& ui, glm::dvec2 window, double now) {
  if (now >= ui.refitUntil && !viewAsFitted(model, ui)) return;
  const ScreenRect room = fitRoom(model, ui, window, &ui.layout);
  const glm::dvec2 d =
      glm::abs(room.lo - ui.fittedScene.lo) + glm::abs(room.hi - ui.fittedScene.hi);
  if (d.x + d.y > 2.0) model.requestFit();
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
      std::min(360.0f * model.settings.uiScale(), static_cast<float>(area.size().x) * 0.6f);
  float ih = static_cast<float>(window.y) * 0.6f;
  if (model.settings.showLegend && !ui.legendMoved)
    ih = std::min(ih,
                  static_cast<float>(area.size().y) - ui.legendSize[1] - ui.captionHeight - 36.0f);
  ImGui::SetNextWindowPos(ImVec2(static_cast<float>(area.hi.x) - iw - 8.0f, 8.0f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(iw, 0.0f), ImVec2(iw, std::max(ih, 120.0f)));
  ImGui::SetNextWindowBgAlpha(0.9f);
  // a phone's: folded to its title bar at first, unfolded by a tap on it
  const bool drawer = model.settings.drawer;
  if (drawer) ImGui::SetNextWindowCollapsed(true, ImGuiCond_Once);
  ImGui::Begin("Inspector", nullptr,
               ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                   ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                   (drawer ? 0 : ImGuiWindowFlags_NoCollapse) |
                   ImGuiWindowFlags_NoFocusOnAppearing);
  panelsOf(model).inspector(model, false);
  ImGui::End();
}

// a small window of buttons at `pos`, its corner `pivot` (0..1 each way) there, over every
// other window (a Steps window that came later too)
bool beginButtons(const char* name, ImVec2 pos, ImVec2 pivot) {
  ImGui::SetNextWindowPos(pos, ImGuiCond_Always, pivot);
  ImGui::SetNextWindowBgAlpha(0.85f);
  const bool open = ImGui::Begin(name, nullptr,
                                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                                     ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoMove |
                                     ImGuiWindowFlags_NoFocusOnAppearing);
  ImGui::BringWindowToDisplayFront(ImGui::GetCurrentWindow());
  return open;
}

// A phone's buttons, big enough for a finger: the drawer's in the lower left corner and, in
// a lecture, the previous and next slide's at the bottom's middle.
void phoneButtons(Model& model, UiState& ui, glm::dvec2 window) {
  Settings& s = model.settings;
  const float pad = 8.0f, h = 2.2f * ImGui::GetFontSize();
  const float bottom = static_cast<float>(window.y) - pad;
  if (beginButtons("##drawer", ImVec2(pad, bottom), ImVec2(0.0f, 1.0f)) &&
      ImGui::Button(s.drawerOpen ? "Close panels" : "Panels", ImVec2(0.0f, h)))
    s.drawerOpen = !s.drawerOpen;
  ImGui::End();
  if (ui.show.lecture.slides.size() < 2) return;
  if (beginButtons("##slides", ImVec2(0.5f * static_cast<float>(window.x), bottom),
                   ImVec2(0.5f, 1.0f))) {
    if (ImGui::Button(" < ", ImVec2(0.0f, h))) moveSlide(ActionKind::PreviousSlide, model, ui);
    ImGui::SameLine();
    if (ImGui::Button(" > ", ImVec2(0.0f, h))) moveSlide(ActionKind::NextSlide, model, ui);
  }
  ImGui::End();
}

}  // namespace

void drawUi(Model& model, Renderer& renderer, UiState& ui, double now) {
  const ImGuiIO& io = ImGui::GetIO();
  const glm::dvec2 window{io.DisplaySize.x, io.DisplaySize.y};
  // the slide laid out once for this frame: every box below, the labels and the SVG use it
  tickStepPlayer(model, now);
  slideDrawOptions(model, ui);
  ui.layout = frameLayout(model, ui, window);
  refitOnNewRoom(model, ui, window, now);
  drawLetterbox(model, ui, window);
  const ScreenRect area = sceneArea(model, ui, window);
  const Settings& s = model.settings;
  if (s.drawer ? s.drawerOpen : s.showUi) leftPanel(model, renderer, ui, window);
  const float rw = rightPanelWidth(model, window);
  captionBox(model, ui, area);
  std::fill(std::begin(ui.legendRect), std::end(ui.legendRect), 0.0f);  // until drawn again
  if (rw > 0.0f) {
    rightPanel(model, window, rw);
  } else {
    // an open drawer covers the scene: nothing floats over it
    const bool drawerOpen = s.drawer && s.drawerOpen;
    // a plots slide has no scene to explain
    if (s.showLegend && !drawerOpen && !plotsSlide(model, ui))
      legendOverlay(model, ui, area, window, now);
    if (s.showUi && !drawerOpen && panelsOf(model).inspectable(model))
      floatingInspector(model, ui, area, window);
  }
  stepsWindow(model, ui, now);  // also with the panels hidden; the fit leaves it room
  slideCard(model, ui, area);
  if (s.drawer) phoneButtons(model, ui, window);
  toast(model, ui, area, now);
  // the teaching views: the split's halves and second scene, the build's clock, Why O(1)
  // (no halves in 3D or the Lines mode: the pointer then goes where it is)
  const bool halves = model.dim == Dim::Two && !model.lines2d.enabled();
  const ScreenRect room = figureRoomOf(model, ui);  // a slide's halves keep to its figure
  model.split.allowStacking(room.hi.x > room.lo.x);
  model.split.setArea(halves ? (room.hi.x > room.lo.x ? room : area) : ScreenRect{});
  if (model.split.enabled() && halves) model.split.sync(model.scene2d);
  splitHeadings(model, ui);
  advanceBuild(model, io.DeltaTime);
  scalingWindow(model, ui);
}

}  // namespace convexloc::viewer
