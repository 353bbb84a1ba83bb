// convexloc-viewer — the shared panel pieces that need no template.
#include "ui/panels/method_panels.hpp"

#include <algorithm>

namespace convexloc::viewer {

std::string costText(const MethodInfo& info) {
  std::string text(info.cost);
  if (!info.costNote.empty()) {
    text.push_back(' ');
    text.append(info.costNote);
  }
  if (info.paper) text.append(", the paper's");
  return text;
}

void statsTable(const char* id, const std::vector<StatLine>& rows) {
  if (!ImGui::BeginTable(id, 2, ImGuiTableFlags_SizingStretchProp)) return;
  for (const StatLine& r : rows) statRow(r.key, r.value);
  ImGui::EndTable();
}

void noResolutionRow() {
  ImGui::AlignTextToFramePadding();
  ImGui::TextDisabled("no resolution to set for this method");
}

namespace {

// the bars of a histogram, drawn here (ImGui's own plot adds a tooltip line of its own)
void histogramBars(const char* id, const std::vector<std::size_t>& histogram) {
  const ImVec2 size(ImGui::GetContentRegionAvail().x, ImGui::GetFontSize() * 4.0f);
  const ImVec2 p = ImGui::GetCursorScreenPos();
  ImGui::InvisibleButton(id, size);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  dl->AddRectFilled(p, ImVec2(p.x + size.x, p.y + size.y), ImGui::GetColorU32(ImGuiCol_FrameBg),
                    ImGui::GetStyle().FrameRounding);
  const std::size_t most = *std::max_element(histogram.begin(), histogram.end());
  const float w = size.x / static_cast<float>(histogram.size()), pad = 0.12f * w;
  for (std::size_t k = 0; k < histogram.size() && most > 0; ++k) {
    const float h = (size.y - 4.0f) * static_cast<float>(histogram[k]) / static_cast<float>(most);
    const float x = p.x + w * static_cast<float>(k);
    dl->AddRectFilled(ImVec2(x + pad, p.y + size.y - 2.0f - h),
                      ImVec2(x + w - pad, p.y + size.y - 2.0f),
                      ImGui::GetColorU32(ImGuiCol_PlotHistogram));
  }
}

}  // namespace

void cellHistogram(const char* id, const std::vector<std::size_t>& histogram, const char* noun) {
  if (histogram.empty()) return;
  ImGui::TextDisabled("cells by %s listed: 0, 1, ..., %zu+", noun, histogram.size() - 1);
  histogramBars(id, histogram);
  if (!ImGui::IsItemHovered()) return;
  ImGui::BeginTooltip();
  for (std::size_t k = 0; k < histogram.size(); ++k)
    if (histogram[k])
      ImGui::Text("%s%zu %s: %s cells", k + 1 == histogram.size() ? ">= " : "", k, noun,
                  grouped(histogram[k]).c_str());
  ImGui::EndTooltip();
}

void paperModeCheckbox(Model& model, bool hasRadii) {
  // always shown, greyed for methods without the filter, so that nothing below it moves
  bool on = model.settings.paperMode;
  ImGui::BeginDisabled(!hasRadii);
  if (ImGui::Checkbox("paper-faithful: no radius filter (R)", &on)) model.setPaperMode(on);
  ImGui::EndDisabled();
  help(
      "The radius filter is convexloc's own shortcut: a cell's two radii decide most points "
      "before any predicate. Without it the placed point's query runs exactly as the paper "
      "describes: the cell's edges (faces) decide. Answers are the same either way.");
}

}  // namespace convexloc::viewer
