// convexloc-viewer — the pieces of the Method panel, the inspector and the legend that the
// 2D and the 3D scene show alike, written once over the scene: the method list with each
// method's cost (core's methodInfo), the resolution slider, the statistics table, the
// histogram of edges or faces per cell, Compare all methods and its table, the generator
// controls, the placed point's trace.
#pragma once

#include <algorithm>
#include <cfloat>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include <imgui.h>

#include "convexloc/methods.hpp"
#include "logic/base/format.hpp"
#include "ui/widgets.hpp"

namespace convexloc::viewer {

// "O(1), the paper's", "O(sqrt F) expected": a method's cost as the panels show it
std::string costText(const MethodInfo& info);

// one row of a statistics table
struct StatLine {
  const char* key;
  std::string value;
};

// a two-column table of statistics
void statsTable(const char* id, const std::vector<StatLine>& rows);

// the histogram of cells by the edges (or faces: `noun`) they list, with a tooltip
void cellHistogram(const char* id, const std::vector<std::size_t>& histogram, const char* noun);

// === Method list and resolution

// a radio button per method, its cost beside it
template <class Scene>
void methodChoice(Scene& scene) {
  for (const auto m : Scene::kMethods) {
    if (ImGui::RadioButton(std::string(toString(m)).c_str(), scene.method() == m))
      scene.setMethod(m);
    ImGui::SameLine(ImGui::GetFontSize() * 7.0f);
    ImGui::TextDisabled("%s", costText(methodInfo(m)).c_str());
  }
}

// what a resolution slider is called and how far it goes
struct SliderText {
  const char* autoId;    // the "auto" check box
  const char* sliderId;  // the slider
  int most;              // its largest value
  const char* format;    // "%d slabs", "G = %d"
};

// the "auto" box (core's choice) and a logarithmic slider for the method's resolution
template <class Scene>
void resolutionSlider(Scene& scene, const SliderText& text) {
  bool automatic = scene.resolution() == 0;
  int r = static_cast<int>(scene.effectiveResolution());
  if (ImGui::Checkbox(text.autoId, &automatic))
    scene.setResolution(automatic ? 0 : static_cast<std::uint32_t>(r));
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::SliderInt(text.sliderId, &r, 1, text.most, text.format,
                       ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
    scene.setResolution(static_cast<std::uint32_t>(std::max(r, 1)));
}

// the paper-faithful mode's check box (key R): the placed point traced without the radius
// filter; greyed for the methods that have none (all but polar and cubemap)
void paperModeCheckbox(Model& model, bool hasRadii);
// the resolution slider's row for a method without one, as high as the slider's
void noResolutionRow();

// === Compare all methods

// the table of a comparison: ns per point (the fastest in the positive colour), build
// time, whether every method agreed with the current one
template <class Row>
void compareTable(const char* id, const std::vector<Row>& rows, const Palette& pal) {
  if (rows.empty() ||
      !ImGui::BeginTable(id, 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp))
    return;
  ImGui::TableSetupColumn("method");
  ImGui::TableSetupColumn("ns/pt");
  ImGui::TableSetupColumn("build");
  ImGui::TableSetupColumn("agree");
  ImGui::TableHeadersRow();
  double best = 1e300;
  for (const Row& r : rows)
    if (r.points) best = std::min(best, r.nsPerPoint);
  for (const Row& r : rows) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(std::string(toString(r.method)).c_str());
    ImGui::TableNextColumn();
    if (r.nsPerPoint == best)
      ImGui::TextColored(im(pal.positive), "%s", nsText(r.nsPerPoint).c_str());
    else
      ImGui::Text("%s", nsText(r.nsPerPoint).c_str());
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("%s points located, %s", grouped(r.points).c_str(),
                        binarySize(r.bytes).c_str());
    ImGui::TableNextColumn();
    ImGui::Text("%s ms", approx(r.buildMs, 2).c_str());
    ImGui::TableNextColumn();
    if (r.disagreements == 0)
      ImGui::TextColored(im(pal.positive), "yes");
    else
      ImGui::TextColored(im(pal.negative), "%zu differ", r.disagreements);
  }
  ImGui::EndTable();
}

// the Compare all methods button, its help mark and the last comparison's table
template <class Scene, class Row>
void compareSection(Scene& scene, std::vector<Row>& rows, const char* button, const char* tableId,
                    const Palette& pal) {
  if (ImGui::Button(button, ImVec2(-1.0f, 0.0f))) rows = scene.compare();
  help(
      "Times every method's batch locate on the current spray (at most ~0.1 s each) and checks "
      "that all answer the same.");
  compareTable(tableId, rows, pal);
}

// what a Method panel's widgets are called
struct MethodPanelText {
  const char* statsId;
  const char* histogramId;
  const char* noun;  // what cells list: "edges", "faces"
  const char* compareButton;
  const char* compareId;
};

// below the method list and the resolution: statistics, histogram, Compare all methods
template <class Scene, class Row>
void methodDetails(Model& model, Scene& scene, const std::vector<StatLine>& stats,
                   std::vector<Row>& rows, const MethodPanelText& text) {
  statsTable(text.statsId, stats);
  const auto& histogram = scene.stats().histogram;
  if (!histogram.empty() && scene.stats().cells)
    cellHistogram(text.histogramId, histogram, text.noun);
  compareSection(scene, rows, text.compareButton, text.compareId, paletteFor(model.settings.theme));
}

// === Generators

// what the generator controls are called
struct GeneratorText {
  const char* comboId;  // the kind
  const char* button;   // Generate
  const char* count;    // the size's label
  int step, fastStep;   // the size's +/- steps
  int fewest;           // the smallest size
  const char* seed;     // the seed's label
  const char* next;     // the next-seed button
};

// The kind, Generate, the size and the seed; true when a shape is asked for (Generate,
// or the next seed).
template <class Kind>
bool generatorControls(std::span<const Kind> kinds, GeneratorChoice& choice,
                       const GeneratorText& text) {
  ImGui::Spacing();
  const int count = static_cast<int>(kinds.size());
  choice.kind = std::clamp(choice.kind, 0, count - 1);
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
  if (ImGui::BeginCombo(text.comboId, std::string(toString(kinds[choice.kind])).c_str())) {
    for (int k = 0; k < count; ++k)
      if (ImGui::Selectable(std::string(toString(kinds[k])).c_str(), k == choice.kind))
        choice.kind = k;
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  bool generate = ImGui::Button(text.button, ImVec2(-1.0f, 0.0f));
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
  ImGui::InputInt(text.count, &choice.n, text.step, text.fastStep);
  choice.n = std::clamp(choice.n, text.fewest, 1 << 22);
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
  ImGui::InputScalar(text.seed, ImGuiDataType_U64, &choice.seed);
  ImGui::SameLine();
  if (ImGui::SmallButton(text.next)) {
    ++choice.seed;
    generate = true;
  }
  return generate;
}

// the generator controls, generating the scene's shape when asked, and the degenerate gallery
template <class Scene, class Kind>
void generatorsAndGallery(Model& model, Scene& scene, std::span<const Kind> kinds,
                          GeneratorChoice& choice, const GeneratorText& text, bool solid) {
  if (generatorControls(kinds, choice, text) &&
      scene.generate(kinds[choice.kind], static_cast<std::size_t>(choice.n), choice.seed))
    model.requestFit();
  ImGui::Spacing();
  ImGui::TextDisabled("Degenerate gallery");
  gallery(model, solid);
}

// === Legend and inspector

// The placed point: its class, its trace told line by line (`lines`), Clear and Copy;
// without one, with `hints`, what a click would do (`hint`).
template <class Scene, class Describe>
void placedPoint(Scene& scene, const Palette& pal, bool hints, const char* hint,
                 Describe describe) {
  const auto& probe = scene.probe();
  if (!probe) {
    if (hints) {
      ImGui::Spacing();
      ImGui::TextDisabled("Placed point");
      ImGui::TextWrapped("%s", hint);
    }
    return;
  }
  ImGui::Spacing();
  const Rgba colour = textColourOf(pal, probe->trace.result);
  ImGui::TextColored(im(colour), "Placed point: %s",
                     std::string(toString(probe->trace.result)).c_str());
  traceLines(describe(*probe), pal, colour);
  if (ImGui::SmallButton("Clear (Esc)")) scene.clearProbe();
  ImGui::SameLine();
  if (ImGui::SmallButton("Copy coordinates"))
    ImGui::SetClipboardText(exactText(probe->point).c_str());
}

}  // namespace convexloc::viewer
