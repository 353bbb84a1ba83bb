// convexloc-viewer — the split view's, the build animation's and Why O(1)'s controls.
#include "ui/panels/views_panel.hpp"

#include <algorithm>
#include <string>

#include <imgui.h>

#include "logic/base/format.hpp"
#include "ui/slide_frame.hpp"
#include "ui/widgets.hpp"

namespace convexloc::viewer {

void splitControls(Model& model) {
  bool on = model.split.enabled();
  if (ImGui::Checkbox("Split view", &on)) {
    model.split.setEnabled(on);
    model.requestFit();
  }
  help(
      "The scene twice: the current method on the left, a second one on the right, with the "
      "same points and one camera. Each half traces the placed point itself.");
  if (!on) return;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1.0f);
  const std::string name(toString(model.split.method()));
  if (ImGui::BeginCombo("##second", ("right: " + name).c_str())) {
    for (const Method2D m : kAllMethods2D)
      if (ImGui::Selectable(std::string(toString(m)).c_str(), m == model.split.method()))
        model.split.setMethod(m);
    ImGui::EndCombo();
  }
}

namespace {

// the build's steps in the scene shown
std::size_t stepsShown(Model& model) {
  return model.dim == Dim::Two ? buildStepCount(model.scene2d) : buildStepCount(model.scene3d());
}

}  // namespace

void buildControls(Model& model) {
  BuildPlayback& b = model.build;
  const std::size_t steps = stepsShown(model);
  if (steps == 0) {
    b.active = false;
    return;
  }
  const char* label = !b.active ? "Build" : b.playing ? "Pause" : "Play";
  if (ImGui::Button(label)) {
    if (!b.active || b.step >= steps) b.show(0, steps);
    b.active = true;
    b.playing = !b.playing;
    ++b.version;
  }
  help(
      "The cells receiving their edges (faces) one at a time, in order: the cells listing the "
      "one just added flash, tints grow with what they hold, crowded cells get a cross.");
  if (!b.active) return;
  ImGui::SameLine();
  int k = static_cast<int>(b.step);
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - ImGui::GetFontSize() * 3.5f);
  const bool plane = model.dim == Dim::Two;
  if (ImGui::SliderInt("##buildstep", &k, 0, static_cast<int>(steps),
                       plane ? "edge %d" : "face %d"))
    b.show(static_cast<std::size_t>(k), steps);
  ImGui::SameLine();
  if (ImGui::Button("Done")) {
    b.active = b.playing = false;
    ++b.version;
  }
  ImGui::TextDisabled("%zu of %zu %s in", b.step, steps, model.dim == Dim::Two ? "edges" : "faces");
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1.0f);
  float speed = static_cast<float>(b.edgesPerSecond);
  if (ImGui::SliderFloat("##buildspeed", &speed, 0.5f, 60.0f,
                         plane ? "%.1f edges/s" : "%.1f faces/s", ImGuiSliderFlags_Logarithmic))
    b.edgesPerSecond = speed;
}

void whyButton(Model& model) {
  if (ImGui::Button("Why O(1)? Cost against N", ImVec2(-1.0f, 0.0f))) {
    model.whyOpen = true;
    model.whySolid = model.dim == Dim::Three;  // it opens on the scene's page
  }
}

void splitHeadings(const Model& model, UiState& ui) {
  ui.splitHeadings[0] = ui.splitHeadings[1] = TextBox{};
  if (!model.split.enabled() || model.dim != Dim::Two || model.lines2d.enabled()) return;
  const SlideMetrics m = windowMetrics();
  const ImVec2 window = ImGui::GetIO().DisplaySize;
  const double scale = splitHeadingScale(model, ui, {window.x, window.y});
  ui.splitHeadings[0] =
      splitHeading(model.split.left(), SecondView::traceCaption(model.scene2d), m, scale);
  ui.splitHeadings[1] =
      splitHeading(model.split.right(), SecondView::traceCaption(model.split.scene()), m, scale);
}

void splitDecorations(const Model& model, const UiState& ui) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const Palette& pal = paletteFor(model.settings.theme);
  const auto [from, to] = model.split.divider();
  dl->AddLine(ImVec2(static_cast<float>(from.x), static_cast<float>(from.y)),
              ImVec2(static_cast<float>(to.x), static_cast<float>(to.y)), packAbgr(pal.textMuted),
              2.0f);
  for (const TextBox& t : ui.splitHeadings) {
    if (t.lines.empty()) continue;
    const float size = ImGui::GetFontSize() * static_cast<float>(t.scale), pad = 0.6f * size;
    const ImVec2 lo(static_cast<float>(t.box.lo.x), static_cast<float>(t.box.lo.y));
    dl->AddRectFilled(lo, ImVec2(static_cast<float>(t.box.hi.x), static_cast<float>(t.box.hi.y)),
                      packAbgr(withAlpha(pal.background, 0.9f)), 4.0f);
    dl->AddText(nullptr, size, ImVec2(lo.x + pad, lo.y + 0.5f * pad), packAbgr(pal.text),
                t.lines[0].c_str());
  }
}

void splitInspector(const Model& model) {
  if (!model.split.enabled() || model.dim != Dim::Two || model.lines2d.enabled()) return;
  const Scene2D& s = model.split.scene();
  if (!s.probe()) return;
  const Palette& pal = paletteFor(model.settings.theme);
  const Trace2D& t = s.probe()->trace;
  const Rgba colour = textColourOf(pal, t.result);
  ImGui::Separator();
  ImGui::TextColored(im(colour), "Right half, %s: %s", std::string(toString(s.method())).c_str(),
                     std::string(toString(t.result)).c_str());
  traceLines(describeTrace(t, s.probe()->point, s.polygon()), pal, colour);
}

void advanceBuild(Model& model, double seconds) {
  model.build.advance(seconds, stepsShown(model));
}

}  // namespace convexloc::viewer
