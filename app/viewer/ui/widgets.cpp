// convexloc-viewer — shared ImGui pieces.
#include "ui/widgets.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "logic/app/legend.hpp"
#include "logic/scene/presets.hpp"
#include "logic/view/label_layout.hpp"

namespace convexloc::viewer {

void swatchDisc(Rgba c, float radius, Rgba rim) {
  const ImVec2 p = ImGui::GetCursorScreenPos();
  const float h = ImGui::GetTextLineHeight();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 centre(p.x + radius + 1.0f, p.y + 0.5f * h);
  dl->AddCircleFilled(centre, radius + 1.0f, u32(rim), 20);
  dl->AddCircleFilled(centre, radius, u32(c), 20);
  ImGui::Dummy(ImVec2(2.0f * radius + 4.0f, h));
  ImGui::SameLine();
}

// a small coloured square in the text flow
void swatchBox(Rgba fill, Rgba edge) {
  const ImVec2 p = ImGui::GetCursorScreenPos();
  const float h = ImGui::GetTextLineHeight();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const ImVec2 a(p.x + 1.0f, p.y + 0.15f * h), b(p.x + 0.7f * h + 1.0f, p.y + 0.85f * h);
  dl->AddRectFilled(a, b, u32(fill));
  dl->AddRect(a, b, u32(edge));
  ImGui::Dummy(ImVec2(0.7f * h + 4.0f, h));
  ImGui::SameLine();
}

// a short line sample in the text flow; dashed when `dashed`
void swatchLine(Rgba c, bool dashed, float width) {
  const ImVec2 p = ImGui::GetCursorScreenPos();
  const float h = ImGui::GetTextLineHeight();
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const float y = p.y + 0.5f * h, w = 0.7f * h;
  if (dashed) {
    dl->AddLine(ImVec2(p.x + 1.0f, y), ImVec2(p.x + 0.3f * w, y), u32(c), width);
    dl->AddLine(ImVec2(p.x + 0.6f * w, y), ImVec2(p.x + w + 1.0f, y), u32(c), width);
  } else {
    dl->AddLine(ImVec2(p.x + 1.0f, y), ImVec2(p.x + w + 1.0f, y), u32(c), width);
  }
  ImGui::Dummy(ImVec2(w + 4.0f, h));
  ImGui::SameLine();
}

// the checkbox, then its tooltip while hovered
std::optional<bool> modeSwitch(const char* label, bool on, const char* tooltip) {
  const bool clicked = ImGui::Checkbox(label, &on);
  if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", tooltip);
  if (!clicked) return std::nullopt;
  return on;
}

// a "(?)" with a tooltip
void help(const char* text) {
  ImGui::SameLine();
  ImGui::TextDisabled("(?)");
  if (ImGui::IsItemHovered()) {
    ImGui::BeginTooltip();
    textAtSpaces(text, {}, ImGui::GetFontSize() * 28.0f);
    ImGui::EndTooltip();
  }
}

void statRow(const char* key, const std::string& value) {
  ImGui::TableNextRow();
  ImGui::TableNextColumn();
  ImGui::TextDisabled("%s", key);
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(value.c_str());
}

void toggleGrid(std::string_view labels, std::initializer_list<bool*> values) {
  const float mid = ImGui::GetContentRegionAvail().x * 0.5f;
  bool right = false;
  for (bool* value : values) {
    const std::size_t bar = labels.find('|');
    const std::string label(labels.substr(0, bar));
    labels = bar == std::string_view::npos ? std::string_view() : labels.substr(bar + 1);
    if (right) ImGui::SameLine(mid);
    ImGui::Checkbox(label.c_str(), value);
    right = !right;
  }
}

void fileOpen(Model& model, UiState& ui, const char* hint) {
  ImGui::SetNextItemWidth(-ImGui::CalcTextSize("Open").x - 3.0f * ImGui::GetStyle().FramePadding.x);
  const bool enter = ImGui::InputTextWithHint("##path", hint, ui.path, sizeof ui.path,
                                              ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  if ((ImGui::Button("Open") || enter) && ui.path[0]) model.open(ui.path);
  if (!model.recent.empty() || !ui.assets.empty()) {
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::BeginCombo("##files", "recent files and assets")) {
      for (const std::string& f : model.recent)
        if (ImGui::Selectable(f.c_str())) {
          std::snprintf(ui.path, sizeof ui.path, "%s", f.c_str());
          model.open(f);
        }
      if (!model.recent.empty() && !ui.assets.empty()) ImGui::Separator();
      for (const std::string& f : ui.assets) {
        const std::string name = std::filesystem::path(f).filename().string();
        if (ImGui::Selectable(name.c_str())) {
          std::snprintf(ui.path, sizeof ui.path, "%s", f.c_str());
          model.open(f);
        }
      }
      ImGui::EndCombo();
    }
  }
}

void gallery(Model& model, bool solid) {
  const float half = 0.5f * (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x);
  // two to a row; a title too long for half the width gets a row of its own
  bool rowOpen = false;
  for (const Preset& p : presets()) {
    if (p.solid != solid) continue;
    const std::string title(p.title);
    const bool fits =
        ImGui::CalcTextSize(title.c_str()).x + 2.0f * ImGui::GetStyle().FramePadding.x <= half;
    if (rowOpen && fits) ImGui::SameLine();
    rowOpen = fits && !rowOpen;
    if (ImGui::Button(title.c_str(), ImVec2(fits ? half : -1.0f, 0.0f))) model.applyPreset(p.name);
    if (ImGui::IsItemHovered()) {
      ImGui::BeginTooltip();
      textAtSpaces(p.about, {}, ImGui::GetFontSize() * 24.0f);
      ImGui::EndTooltip();
    }
  }
}

void textAtSpaces(std::string_view text, std::string_view indent, float asked) {
  const float width = asked > 0.0f
                          ? asked
                          : std::max(ImGui::GetContentRegionAvail().x, ImGui::GetFontSize() * 4.0f);
  const auto measure = [](std::string_view t) {
    const ImVec2 v = ImGui::CalcTextSize(t.data(), t.data() + t.size());
    return glm::dvec2(v.x, v.y);
  };
  for (const std::string& line : breakAtSpaces(text, width, measure, indent))
    ImGui::TextUnformatted(line.c_str());
}

void traceLines(const std::vector<TraceLine>& lines, const Palette& pal, Rgba resultColour) {
  constexpr std::size_t kMaxLines = 200;
  for (std::size_t i = 0; i < lines.size() && i < kMaxLines; ++i) {
    const TraceLine& l = lines[i];
    Rgba c = pal.text;
    if (l.kind == TraceLine::Positive)
      c = pal.positive;
    else if (l.kind == TraceLine::Negative)
      c = pal.negative;
    else if (l.kind == TraceLine::Zero)
      c = pal.zero;
    else if (l.kind == TraceLine::Result)
      c = resultColour;
    else if (l.kind == TraceLine::Heading)
      c = pal.textMuted;
    ImGui::PushStyleColor(ImGuiCol_Text, im(readableOn(c, pal.background, pal.text)));
    textAtSpaces(l.text);
    ImGui::PopStyleColor();
  }
  if (lines.size() > kMaxLines) {
    ImGui::TextDisabled("... %zu more steps", lines.size() - kMaxLines);
    ImGui::TextColored(im(resultColour), "%s", lines.back().text.c_str());
  }
}

namespace {

// the swatch of a legend row, in the text flow
void swatch(const LegendRow& r) {
  switch (r.swatch) {
    case Swatch::Disc: swatchDisc(r.colour, 0.27f * ImGui::GetTextLineHeight(), r.edge); break;
    case Swatch::Box: swatchBox(r.colour, r.edge); break;
    case Swatch::Line: swatchLine(r.colour, false, r.width); break;
    case Swatch::DashedLine: swatchLine(r.colour, true, r.width); break;
  }
}

// the width a row's swatch takes in the text flow, its gap after it included
float swatchWidth(const LegendRow& r) {
  const float h = ImGui::GetTextLineHeight();
  const float w = r.swatch == Swatch::Disc ? 0.54f * h : 0.7f * h;
  return w + 4.0f + ImGui::GetStyle().ItemSpacing.x;
}

// The class rows: disc and name, the count right-aligned, the share; with `toggles`, a
// check box before each that shows or hides the class.
void classTable(const std::vector<LegendRow>& rows, Model* toggles) {
  const Location order[3] = {Location::Inside, Location::Boundary, Location::Outside};
  const bool counted = !rows.empty() && !rows[0].count.empty();
  // name, count and share in columns as wide as their text from the first frame on (a
  // table left to fit them learns their widths a frame late)
  float nameWidth = 0.0f, countWidth = 0.0f, shareWidth = 0.0f;
  for (const LegendRow& r : rows) {
    nameWidth = std::max(nameWidth, swatchWidth(r) + ImGui::CalcTextSize(r.text.c_str()).x);
    countWidth = std::max(countWidth, ImGui::CalcTextSize(r.count.c_str()).x);
    shareWidth = std::max(shareWidth, ImGui::CalcTextSize(r.share.c_str()).x);
  }
  if (toggles) nameWidth += ImGui::GetFrameHeight() + ImGui::GetStyle().ItemSpacing.x;
  if (!ImGui::BeginTable("classes", counted ? 3 : 1, ImGuiTableFlags_SizingFixedFit)) return;
  ImGui::TableSetupColumn("name", ImGuiTableColumnFlags_WidthFixed, nameWidth);
  if (counted) {
    ImGui::TableSetupColumn("count", ImGuiTableColumnFlags_WidthFixed, countWidth);
    ImGui::TableSetupColumn("share", ImGuiTableColumnFlags_WidthFixed, shareWidth);
  }
  for (std::size_t i = 0; i < rows.size() && i < 3; ++i) {
    const LegendRow& r = rows[i];
    ImGui::PushID(static_cast<int>(i));
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    if (toggles) {
      unsigned& mask = toggles->settings.visibleMask;
      bool s = (mask & classBit(order[i])) != 0;
      if (ImGui::Checkbox("##show", &s))
        mask = s ? mask | classBit(order[i]) : mask & ~classBit(order[i]);
      ImGui::SameLine();
    }
    swatch(r);
    ImGui::TextUnformatted(r.text.c_str());
    if (counted) {
      ImGui::TableNextColumn();
      // right-aligned counts
      const float w = ImGui::CalcTextSize(r.count.c_str()).x;
      ImGui::SetCursorPosX(ImGui::GetCursorPosX() + countWidth - w);
      ImGui::TextUnformatted(r.count.c_str());
      ImGui::TableNextColumn();
      ImGui::TextDisabled("%s", r.share.c_str());
    }
    ImGui::PopID();
  }
  ImGui::EndTable();
}

}  // namespace

void classRows(Model& model, const std::array<std::size_t, 3>& counts, std::size_t total,
               bool checkboxes) {
  classTable(classLegendRows(model, counts, total), checkboxes ? &model : nullptr);
}

void drawLegend(const Legend& legend) {
  ImGui::TextUnformatted(legend.title.c_str());
  if (!legend.subtitle.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("%s", legend.subtitle.c_str());
  }
  if (!legend.classes.empty()) classTable(legend.classes, nullptr);
  for (const LegendRow& r : legend.rows) {
    swatch(r);
    ImGui::TextUnformatted(r.text.c_str());
  }
}

glm::dvec2 measureText(std::string_view text) {
  const ImVec2 v = ImGui::CalcTextSize(text.data(), text.data() + text.size());
  return {v.x, v.y};
}

}  // namespace convexloc::viewer
