// convexloc-viewer — the View panel.
#include "ui/panels/view_panel.hpp"

#include <imgui.h>

#include "logic/base/format.hpp"
#include "ui/frame.hpp"
#include "ui/key_actions.hpp"
#include "ui/widgets.hpp"

namespace convexloc::viewer {

namespace {

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

// Screenshot and SVG, and the directory they write to (the web page: downloads). A tooltip
// never shows on the frame a picture is taken.
void exportButtons(UiState& ui, float half) {
  const char* where = ui.webPage ? "as a download" : "in the folder below";
  if (ImGui::Button("Screenshot", ImVec2(half, 0.0f))) ui.screenshotRequested = true;
  const bool taking = ui.screenshotRequested || ui.svgRequested;
  if (ImGui::IsItemHovered() && !taking) ImGui::SetTooltip("F12: a PNG of the window, %s", where);
  ImGui::SameLine();
  if (ImGui::Button("SVG", ImVec2(half, 0.0f))) ui.svgRequested = true;
  if (ImGui::IsItemHovered() && !ui.screenshotRequested && !ui.svgRequested)
    ImGui::SetTooltip("V or Shift+F12: the scene as a vector figure, %s", where);
  if (ui.webPage) return;
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::InputTextWithHint("##exportdir", "save to: the working directory", ui.exportDirEdit,
                               sizeof ui.exportDirEdit))
    ui.exportDir = ui.exportDirEdit;
}

}  // namespace

void viewPanel(Model& model, Renderer& renderer, UiState& ui) {
  int theme = static_cast<int>(model.settings.theme);
  if (ImGui::RadioButton("dark", theme == 0)) model.settings.theme = Theme::Dark;
  ImGui::SameLine();
  if (ImGui::RadioButton("light", theme == 1)) model.settings.theme = Theme::Light;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::SliderFloat("##font", &ui.fontScaleEdit, 0.75f, 2.5f, "text %.2fx");
  if (ImGui::IsItemDeactivatedAfterEdit()) ui.pendingFontScale = ui.fontScaleEdit;
  // the slider follows the size a slide sets, except while it is dragged
  if (!ImGui::IsItemActive() && ui.pendingFontScale <= 0.0f)
    ui.fontScaleEdit = model.settings.fontScale;
  // what the text is drawn at: the size, a slide page's scale and the zoom (+ / -)
  const Settings& st = model.settings;
  if (st.uiScale() != st.fontScale)
    ImGui::TextDisabled("drawn at %.2fx: page %.0f%%, zoom %.2fx (+ / -)", st.uiScale(),
                        100.0 * st.pageScale, st.textZoom);

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

}  // namespace convexloc::viewer
