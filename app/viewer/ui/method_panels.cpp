// convexloc-viewer — the shared panel pieces that need no template.
#include "ui/method_panels.hpp"

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

void cellHistogram(const char* id, const std::vector<std::size_t>& histogram, const char* noun) {
  std::vector<float> h(histogram.begin(), histogram.end());
  ImGui::TextDisabled("cells by %s listed: 0, 1, ..., %zu+", noun, h.size() - 1);
  ImGui::PlotHistogram(id, h.data(), static_cast<int>(h.size()), 0, nullptr, 0.0f, FLT_MAX,
                       ImVec2(ImGui::GetContentRegionAvail().x, ImGui::GetFontSize() * 4.0f));
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
