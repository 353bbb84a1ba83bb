// convexloc-viewer — the Steps window.
#include "ui/panels/steps_panel.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <string>

#include <imgui.h>

#include "logic/view/label_layout.hpp"
#include "ui/scene_area.hpp"
#include "ui/widgets.hpp"

namespace convexloc::viewer {
namespace {

// Previous, Next, Play / Pause, All on the first row; the speed, "step k of n" and the
// pseudo-code's fold on the second
void stepControls(Model& model, UiState& ui, const StepModel& m, int step, double now, bool whole) {
  const std::size_t n = m.steps.size();
  if (ImGui::Button("< Prev")) model.stepBy(false);
  ImGui::SameLine();
  if (ImGui::Button("Next >")) model.stepBy(true);
  ImGui::SameLine();
  StepPlayer& player = model.stepPlayer;
  if (ImGui::Button(player.playing ? "Pause" : "Play")) {
    if (player.playing) {
      player.playing = false;
    } else {
      int k = step;
      player.start(k, n, now);
      model.setStep(k);
    }
  }
  ImGui::SameLine();
  if (ImGui::Button("All")) {
    player.playing = false;
    model.setStep(-1);
  }
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 6.5f);
  ImGui::SliderFloat("##speed", &player.speed, 0.25f, 4.0f, "%.2g steps/s",
                     ImGuiSliderFlags_Logarithmic);
  ImGui::SameLine();
  if (step < 0)
    ImGui::TextDisabled("all %zu steps", n);
  else
    ImGui::Text("step %d of %zu", step + 1, n);
  ImGui::SameLine();
  if (ImGui::SmallButton(whole ? "code -" : "code +")) ui.stepsCode = whole ? 0 : 1;
  if (ImGui::IsItemHovered() && !ui.exporting)
    ImGui::SetTooltip(whole ? "show the current line of pseudo-code alone"
                            : "show the method's whole pseudo-code");
}

// a line of text with its top left at (x, y)
void lineAt(double x, double y, const std::string& text, Rgba colour) {
  ImGui::SetCursorScreenPos(ImVec2(static_cast<float>(x), static_cast<float>(y)));
  ImGui::TextColored(im(colour), "%s", text.c_str());
}

// a separator a spacing above `y`, across the window's inside
void separatorAbove(const StepsLayout& l, double y, const Palette& pal) {
  const float pad = ImGui::GetStyle().WindowPadding.x;
  const float at = static_cast<float>(y) - 0.5f * ImGui::GetStyle().ItemSpacing.y;
  ImGui::GetWindowDrawList()->AddLine(ImVec2(static_cast<float>(l.box.lo.x) + pad, at),
                                      ImVec2(static_cast<float>(l.box.hi.x) - pad, at),
                                      u32(withAlpha(pal.textMuted, 0.5f)), 1.0f);
}

// the steps shown, the current one on a highlighted row and those after it dimmed
void stepList(const StepsLayout& l, const StepModel& m, int step, const Palette& pal, Rgba result) {
  double y = l.listTop;
  const double spacing = ImGui::GetStyle().ItemSpacing.y;
  for (const StepLines& s : l.shown) {
    const int i = static_cast<int>(s.step);
    Rgba c = stepColour(m.steps[s.step], pal, result);
    if (step >= 0 && i > step) c = withAlpha(c, 0.35f);
    if (i == step) {
      const double h = static_cast<double>(s.lines.size()) * l.lineStep - spacing;
      ImGui::GetWindowDrawList()->AddRectFilled(
          ImVec2(static_cast<float>(l.listLeft) - 3.0f, static_cast<float>(y) - 1.0f),
          ImVec2(static_cast<float>(l.listLeft + l.columnWidth), static_cast<float>(y + h) + 1.0f),
          u32(withAlpha(pal.hoverEdge, 0.22f)));
    }
    for (const std::string& line : s.lines) {
      lineAt(l.listLeft, y, line, c);
      y += l.lineStep;
    }
  }
}

// the pseudo-code's lines shown, the current step's marked
void codeList(const StepsLayout& l, const Palette& pal) {
  for (std::size_t i = 0; i < l.code.size(); ++i)
    lineAt(l.codeLeft, l.codeTop + static_cast<double>(i) * l.lineStep, l.code[i],
           l.codeCurrent[i] ? pal.hoverEdge : pal.textMuted);
}

}  // namespace

void tickStepPlayer(Model& model, double now) {
  if (!model.stepPlayer.playing) return;
  const std::optional<StepModel> m = model.steps();
  if (!m || m->steps.empty()) return;
  model.setStep(model.stepPlayer.tick(model.step(), m->steps.size(), now));
}

void stepsWindow(Model& model, UiState& ui, double now) {
  std::fill(std::begin(ui.stepsRect), std::end(ui.stepsRect), 0.0f);
  const std::optional<StepModel> m = model.steps();
  if (!ui.layout.steps || !m) return;
  const StepsLayout& l = *ui.layout.steps;
  const int step = model.step();
  const Palette& pal = paletteFor(model.settings.theme);
  const Rgba result =
      m->steps.back().kind == TraceLine::Result
          ? textColourOf(pal, model.dim == Dim::Two ? model.scene2d.probe()->trace.result
                                                    : model.scene3d().probe()->trace.result)
          : pal.text;
  const glm::dvec2 size = l.box.size();
  ImGui::SetNextWindowPos(ImVec2(static_cast<float>(l.box.lo.x), static_cast<float>(l.box.lo.y)));
  ImGui::SetNextWindowSize(ImVec2(static_cast<float>(size.x), static_cast<float>(size.y)));
  ImGui::SetNextWindowBgAlpha(0.9f);
  // the window's padding as the layout's (a slide's is tighter): nothing clipped at its edges
  const float pad = static_cast<float>(l.listLeft - l.box.lo.x);
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(pad, pad));
  ImGui::Begin("Steps", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav);
  ImGui::SetWindowFontScale(static_cast<float>(l.textScale));  // a slide's column: smaller
  for (std::size_t k = 0; k < l.heading.size(); ++k)
    lineAt(l.listLeft, l.headingTop + static_cast<double>(k) * l.lineStep, l.heading[k],
           pal.textMuted);
  if (l.controls) {
    ImGui::SetCursorScreenPos(
        ImVec2(static_cast<float>(l.listLeft), static_cast<float>(l.controlsTop)));
    stepControls(model, ui, *m, step, now, l.wholeCode);
  }
  separatorAbove(l, l.listTop, pal);
  stepList(l, *m, step, pal, result);
  if (!l.sideBySide && !l.code.empty()) separatorAbove(l, l.codeTop, pal);
  codeList(l, pal);
  ImGui::End();
  ImGui::PopStyleVar();
  ui.stepsRect[0] = static_cast<float>(l.box.lo.x),
  ui.stepsRect[1] = static_cast<float>(l.box.lo.y);
  ui.stepsRect[2] = static_cast<float>(l.box.hi.x),
  ui.stepsRect[3] = static_cast<float>(l.box.hi.y);
}

}  // namespace convexloc::viewer
