// convexloc-viewer — small ImGui pieces the 2D and 3D panels share: legend swatches, help
// marks, the file box, the gallery, the points panel, the trace lines.
#pragma once

#include <cstddef>
#include <initializer_list>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <imgui.h>

#include "logic/app/legend.hpp"
#include "logic/app/model.hpp"
#include "logic/base/colour.hpp"
#include "logic/base/format.hpp"
#include "logic/narration/steps.hpp"
#include "ui/ui_state.hpp"

namespace convexloc::viewer {

inline ImVec4 im(Rgba c) {
  return {c.r, c.g, c.b, c.a};
}
inline ImU32 u32(Rgba c) {
  return packAbgr(c);
}

// a small disc, square or line sample in the text flow, as in a legend
void swatchDisc(Rgba c, float radius, Rgba rim);
void swatchBox(Rgba fill, Rgba edge);
void swatchLine(Rgba c, bool dashed, float width);
// a "(?)" with a tooltip
void help(const char* text);
// a two-column row of a statistics table
void statRow(const char* key, const std::string& value);
// a mode's checkbox showing `on`, with its tooltip; the new state when clicked
std::optional<bool> modeSwitch(const char* label, bool on, const char* tooltip);
// check boxes in two columns: `labels` separated by '|', each setting its bool in `values`
void toggleGrid(std::string_view labels, std::initializer_list<bool*> values);
// the path box, Open, recent files and assets
void fileOpen(Model& model, UiState& ui, const char* hint);
// the degenerate gallery's buttons for polygons or for polyhedra
void gallery(Model& model, bool solid);
// text wrapped at spaces only (breakAtSpaces), so that a number never splits across lines
// (ImGui's own wrapping breaks after a '.'): to the panel, or to `width` pixels when given
// (tooltips); continued lines start with `indent`
void textAtSpaces(std::string_view text, std::string_view indent = {}, float width = 0.0f);
// a trace, one coloured line per step
void traceLines(const std::vector<TraceLine>& lines, const Palette& pal, Rgba resultColour);
// a legend: its title, the class rows, a swatch and a line of text per mark
void drawLegend(const Legend& legend);
// the class legend rows (disc, name, count) and the counts' visibility check boxes
void classRows(Model& model, const std::array<std::size_t, 3>& counts, std::size_t total,
               bool checkboxes);

// === Points: spray settings and buttons, counts, filters, point size (2D and 3D alike)
template <class Scene>
void pointsPanel(Model& model, UiState& ui, Scene& scene) {
  followSpray(ui, scene.spraySettings());
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::SliderInt("##count", &ui.sprayCount, 1000, 1000000, "%d points",
                   ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp);
  const float quarter =
      0.25f * (ImGui::GetContentRegionAvail().x - 3.0f * ImGui::GetStyle().ItemSpacing.x);
  const int quick[4] = {1000, 10000, 100000, 1000000};
  const char* quickName[4] = {"1e3", "1e4", "1e5", "1e6"};
  for (int i = 0; i < 4; ++i) {
    if (i) ImGui::SameLine();
    if (ImGui::Button(quickName[i], ImVec2(quarter, 0.0f))) {
      ui.sprayCount = quick[i];
      scene.spray({static_cast<std::size_t>(ui.sprayCount), ui.spraySeed, ui.sprayNear});
    }
  }
  if (ImGui::RadioButton("uniform in the box", !ui.sprayNear)) ui.sprayNear = false;
  // side by side when both fit (with the help mark), else one under the other
  const ImGuiStyle& st = ImGui::GetStyle();
  if (ImGui::CalcTextSize("uniform in the box near the boundary (?)").x +
          2.0f * ImGui::GetFrameHeight() + 4.0f * st.ItemSpacing.x <=
      ImGui::GetContentRegionAvail().x)
    ImGui::SameLine();
  if (ImGui::RadioButton("near the boundary", ui.sprayNear)) ui.sprayNear = true;
  help(
      "Uniform: in the bounding box grown by 10% on each side. Near the boundary: core's hard "
      "cases: vertices, points exactly on edges or faces, one ulp off, a hair inside or outside.");
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.45f);
  ImGui::InputScalar("seed##spray", ImGuiDataType_U64, &ui.spraySeed);
  ImGui::SameLine();
  if (ImGui::Button("Spray"))
    scene.spray({static_cast<std::size_t>(ui.sprayCount), ui.spraySeed, ui.sprayNear});
  ImGui::SameLine();
  if (ImGui::Button("Clear")) scene.clearSpray();

  classRows(model, scene.counts(), scene.points().size(), true);
  const float half = 0.5f * (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x);
  if (ImGui::Button("only inside", ImVec2(half, 0.0f)))
    model.settings.visibleMask = classBit(Location::Inside) | classBit(Location::Boundary);
  ImGui::SameLine();
  if (ImGui::Button("only outside", ImVec2(half, 0.0f)))
    model.settings.visibleMask = classBit(Location::Outside) | classBit(Location::Boundary);
  if (ImGui::Button("show all", ImVec2(-1.0f, 0.0f))) model.settings.visibleMask = kAllClasses;

  bool autoSize = model.settings.pointSize <= 0.0f;
  if (ImGui::Checkbox("auto size", &autoSize)) model.settings.pointSize = autoSize ? 0.0f : 3.0f;
  if (!autoSize) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    ImGui::SliderFloat("##size", &model.settings.pointSize, 1.0f, 12.0f, "%.1f px");
  }
  if (!scene.points().empty())
    ImGui::TextDisabled("classified at %s ns/point", nsText(scene.locateNsPerPoint()).c_str());
}

// the width and height of a text in the window's current font
glm::dvec2 measureText(std::string_view text);

}  // namespace convexloc::viewer
