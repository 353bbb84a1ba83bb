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

// the colour of a step's line: its sign, the result's class, or plain text
Rgba stepColour(const Step& s, const Palette& pal, Rgba result) {
  switch (s.kind) {
    case TraceLine::Positive: return pal.positive;
    case TraceLine::Negative: return pal.negative;
    case TraceLine::Zero: return readableOn(pal.zero, pal.background, pal.text);
    case TraceLine::Result: return result;
    default: return pal.text;
  }
}

// Previous, Next, Play / Pause, All, the speed, "step k of n"
void stepControls(Model& model, const StepModel& m, int step, double now) {
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
  // the speed and the count follow on the same row where they fit, else on the next
  const float speedWidth = ImGui::GetFontSize() * 6.5f;
  const float room =
      ImGui::GetWindowContentRegionMax().x - (ImGui::GetItemRectMax().x - ImGui::GetWindowPos().x);
  if (room > speedWidth + ImGui::GetFontSize() * 8.0f) ImGui::SameLine();
  ImGui::SetNextItemWidth(speedWidth);
  ImGui::SliderFloat("##speed", &player.speed, 0.25f, 4.0f, "%.2g steps/s",
                     ImGuiSliderFlags_Logarithmic);
  ImGui::SameLine();
  if (step < 0)
    ImGui::TextDisabled("all %zu steps", n);
  else
    ImGui::Text("step %d of %zu", step + 1, n);
}

// the steps, the current one on a highlighted row and those after it dimmed
// (`height` 0: all of them, with no scrolling)
void stepList(const StepModel& m, int step, const Palette& pal, Rgba result, float height) {
  const bool scrolled = height > 0.0f;
  if (scrolled)
    ImGui::BeginChild("##steplist", ImVec2(0.0f, height), false);
  else
    ImGui::BeginGroup();
  for (std::size_t i = 0; i < m.steps.size(); ++i) {
    const Step& s = m.steps[i];
    const bool current = static_cast<int>(i) == step;
    const bool later = step >= 0 && static_cast<int>(i) > step;
    Rgba c = stepColour(s, pal, result);
    if (later) c = withAlpha(c, 0.35f);
    ImDrawList* dl = ImGui::GetWindowDrawList();
    if (current) dl->ChannelsSplit(2);  // the text over its highlight, drawn after it
    if (current) dl->ChannelsSetCurrent(1);
    const ImVec2 at = ImGui::GetCursorScreenPos();
    ImGui::BeginGroup();
    ImGui::PushStyleColor(ImGuiCol_Text, im(c));
    textAtSpaces(std::to_string(i + 1) + ". " + s.caption, "    ");
    ImGui::PopStyleColor();
    ImGui::EndGroup();
    if (current) {
      dl->ChannelsSetCurrent(0);
      dl->AddRectFilled(at,
                        ImVec2(at.x + ImGui::GetContentRegionAvail().x, ImGui::GetItemRectMax().y),
                        u32(withAlpha(pal.hoverEdge, 0.22f)));
      dl->ChannelsMerge();
      static int scrolledTo = -2;  // scrolls once per new step, then the list scrolls freely
      if (scrolled && scrolledTo != step) ImGui::SetScrollHereY(0.5f);
      scrolledTo = step;
    }
  }
  if (scrolled)
    ImGui::EndChild();
  else
    ImGui::EndGroup();
}

// the pseudo-code, the current step's line marked (`onlyCurrent`: that line alone)
void codeList(const StepModel& m, int step, const Palette& pal, bool onlyCurrent) {
  const int line = step >= 0 ? m.steps[static_cast<std::size_t>(step)].line : -1;
  for (std::size_t i = 0; i < m.code.size(); ++i) {
    const bool on = static_cast<int>(i) == line;
    if (onlyCurrent && !on) continue;
    ImGui::PushStyleColor(ImGuiCol_Text, im(on ? pal.hoverEdge : pal.textMuted));
    textAtSpaces((on ? "> " : "  ") + m.code[i], "    ");
    ImGui::PopStyleColor();
  }
}

}  // namespace

namespace {

// the heading: the method and point, the note, and the pseudo-code's fold (`whole`: the
// code is shown whole now)
void stepsHeading(UiState& ui, const StepModel& m, const Palette& pal, bool whole) {
  ImGui::TextColored(im(pal.textMuted), "%s", m.title.c_str());
  if (!m.note.empty()) {
    ImGui::SameLine();
    ImGui::TextColored(im(pal.hoverEdge), "(%s)", m.note.c_str());
  }
  ImGui::SameLine();
  if (ImGui::SmallButton(whole ? "code -" : "code +")) ui.stepsCode = whole ? 0 : 1;
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(whole ? "show the current line of pseudo-code alone"
                            : "show the method's whole pseudo-code");
}

// the Steps window's width: at most half the scene, clear of its middle where the split
// view divides it (and 46 em), at least 16 em where the scene has them
float stepsWidth(ScreenRect area, float font) {
  const float half = static_cast<float>(area.size().x) * 0.5f - 20.0f;
  return std::max(std::min(half, font * 46.0f), std::min(font * 16.0f, half * 1.6f));
}

// the width the window's longest lines need unbroken (the steps, and the code beside them
// when `withCode`), at least the controls' row
float neededWidth(const StepModel& m, bool withCode, float font) {
  float steps = 0.0f, code = 0.0f;
  for (std::size_t i = 0; i < m.steps.size(); ++i)
    steps = std::max(
        steps, ImGui::CalcTextSize((std::to_string(i + 1) + ". " + m.steps[i].caption).c_str()).x);
  for (const std::string& c : m.code) code = std::max(code, ImGui::CalcTextSize(c.c_str()).x);
  const float pad = 2.0f * ImGui::GetStyle().WindowPadding.x + font * 2.0f;
  return std::max(font * 24.0f, (withCode ? steps + code + font * 2.0f : steps) + pad);
}

// the height the step list takes at `width` pixels, its captions broken as stepList breaks
// them
float stepListHeight(const StepModel& m, float width) {
  const auto measure = [](std::string_view t) {
    const ImVec2 v = ImGui::CalcTextSize(t.data(), t.data() + t.size());
    return glm::dvec2(v.x, v.y);
  };
  std::size_t lines = 0;
  for (std::size_t i = 0; i < m.steps.size(); ++i)
    lines +=
        breakAtSpaces(std::to_string(i + 1) + ". " + m.steps[i].caption, width, measure, "    ")
            .size();
  return static_cast<float>(lines) * ImGui::GetTextLineHeightWithSpacing();
}

}  // namespace

void stepsWindow(Model& model, UiState& ui, ScreenRect area, double now) {
  const std::optional<StepModel> m = model.steps();
  const float before[2] = {ui.stepsSize[0], ui.stepsSize[1]};
  ui.stepsSize[0] = ui.stepsSize[1] = 0.0f;
  std::fill(std::begin(ui.stepsRect), std::end(ui.stepsRect), 0.0f);
  // the Lines and Planes modes draw no placed point: no steps of it either
  const bool dualMode = model.dim == Dim::Two ? model.lines2d.enabled() : model.planes3d.enabled();
  if (!model.settings.stepBoxVisible || !m || m->steps.empty() || dualMode) return;
  int step = model.step();
  if (model.stepPlayer.playing) {
    step = model.stepPlayer.tick(step, m->steps.size(), now);
    model.setStep(step);
  }
  const Palette& pal = paletteFor(model.settings.theme);
  const Rgba result =
      m->steps.back().kind == TraceLine::Result
          ? textColourOf(pal, model.dim == Dim::Two ? model.scene2d.probe()->trace.result
                                                    : model.scene3d().probe()->trace.result)
          : pal.text;
  const float font = ImGui::GetFontSize();
  const float room = stepsWidth(area, font);
  const bool wide = room > font * 40.0f;
  const bool whole = ui.stepsCode < 0 ? wide : ui.stepsCode == 1;
  const bool sideBySide = whole && wide;
  // the list alone reads in 34 em, its longer steps wrapped
  const float w =
      std::min({room, neededWidth(*m, sideBySide, font), sideBySide ? room : font * 34.0f});
  ImGui::SetNextWindowPos(ImVec2(static_cast<float>(area.lo.x) + 10.0f,
                                 static_cast<float>(area.hi.y) - ui.captionHeight - 10.0f),
                          ImGuiCond_Always, ImVec2(0.0f, 1.0f));
  // exactly `w` wide (auto-resizing would grow it to its widest row), as high as it needs
  ImGui::SetNextWindowSizeConstraints(ImVec2(w, 0.0f),
                                      ImVec2(w, static_cast<float>(area.size().y)));
  ImGui::SetNextWindowBgAlpha(0.9f);
  ImGui::Begin("Steps", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
  stepsHeading(ui, *m, pal, whole);
  stepControls(model, *m, step, now);
  ImGui::Separator();
  // at most about a quarter of the scene's height (3 to 9 lines) for the list; a longer one
  // scrolls
  const float line = ImGui::GetTextLineHeightWithSpacing();
  const float most =
      line * std::clamp(std::floor(static_cast<float>(area.size().y) * 0.25f / line), 3.0f, 9.0f);
  const float avail = ImGui::GetContentRegionAvail().x;
  const float listWidth =
      sideBySide ? 0.5f * (avail - ImGui::GetStyle().CellPadding.x * 4.0f) : avail;
  const float listHeight =
      stepListHeight(*m, listWidth) <= most ? 0.0f : most + ImGui::GetStyle().WindowPadding.y;
  if (sideBySide && ImGui::BeginTable("##steps", 2, ImGuiTableFlags_SizingStretchProp)) {
    ImGui::TableSetupColumn("steps", ImGuiTableColumnFlags_WidthStretch, 1.0f);
    ImGui::TableSetupColumn("code", ImGuiTableColumnFlags_WidthStretch, 1.0f);
    ImGui::TableNextColumn();
    stepList(*m, step, pal, result, listHeight);
    ImGui::TableNextColumn();
    codeList(*m, step, pal, false);
    ImGui::EndTable();
  } else {
    // narrow, or the code folded: the current step's pseudo-code line alone, or all below
    stepList(*m, step, pal, result, listHeight);
    ImGui::Separator();
    codeList(*m, step, pal, !whole);
  }
  const ImVec2 size = ImGui::GetWindowSize(), pos = ImGui::GetWindowPos();
  ImGui::End();
  ui.stepsSize[0] = size.x;
  ui.stepsSize[1] = size.y;
  ui.stepsRect[0] = pos.x, ui.stepsRect[1] = pos.y;
  ui.stepsRect[2] = pos.x + size.x, ui.stepsRect[3] = pos.y + size.y;
  // fitted a moment ago for another size (or none): fit again; and a window appearing (a
  // point just clicked) over a view left as fitted: fit beside it, the shape in the free room
  const bool appeared = before[0] <= 0.0f && viewAsFitted(model, ui);
  if ((std::abs(size.x - before[0]) > 2.0f || std::abs(size.y - before[1]) > 2.0f) &&
      (now < ui.refitUntil || appeared))
    model.requestFit();
}

}  // namespace convexloc::viewer
