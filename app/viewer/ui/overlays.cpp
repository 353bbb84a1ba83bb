// convexloc-viewer — the windows floating over the scene.
#include "ui/overlays.hpp"

#include <algorithm>
#include <cmath>
#include <iostream>

#include <imgui.h>

#include "logic/view/label_layout.hpp"
#include "ui/frame.hpp"
#include "ui/scene_area.hpp"
#include "ui/slide_frame.hpp"
#include "ui/widgets.hpp"

namespace convexloc::viewer {

void legendOverlay(Model& model, UiState& ui, ScreenRect area, glm::dvec2 window, double now) {
  if (ui.legendMoved) {
    const float x = std::clamp(ui.legendPos[0], 0.0f, static_cast<float>(window.x) - 40.0f);
    const float y = std::clamp(ui.legendPos[1], 0.0f, static_cast<float>(window.y) - 30.0f);
    ImGui::SetNextWindowPos(ImVec2(x, y), ImGuiCond_Always);
  } else {
    // the layout's lower right corner (logic/teach/slide_layout), with the padding
    const SlideLayout& l = ui.layout;
    const glm::dvec2 corner = l.legend.hi.x > 0.0
                                  ? l.legend.hi
                                  : glm::dvec2(area.hi.x, area.hi.y - ui.captionHeight) -
                                        glm::dvec2(10.0 * model.settings.uiScale());
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(corner.x), static_cast<float>(corner.y)),
                            ImGuiCond_Always, ImVec2(1.0f, 1.0f));
  }
  ImGui::SetNextWindowBgAlpha(0.82f);
  // a slide's side column may have smaller text (logic/teach/slide_layout): all of it scaled
  const float scale = static_cast<float>(ui.layout.columnScale);
  const ImGuiStyle& style = ImGui::GetStyle();
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding,
                      ImVec2(style.WindowPadding.x * scale, style.WindowPadding.y * scale));
  ImGui::PushStyleVar(ImGuiStyleVar_ItemSpacing,
                      ImVec2(style.ItemSpacing.x * scale, style.ItemSpacing.y * scale));
  // a slide's legend takes the layout's box (sized from its rows), elsewhere its own size
  const bool laidOut =
      onSlide(model, ui) && ui.layout.legend.hi.x > ui.layout.legend.lo.x && !ui.legendMoved;
  if (laidOut)
    ImGui::SetNextWindowSize(ImVec2(static_cast<float>(ui.layout.legend.size().x),
                                    static_cast<float>(ui.layout.legend.size().y)));
  ImGui::Begin("Legend", nullptr,
               ImGuiWindowFlags_NoDecoration |
                   (laidOut ? ImGuiWindowFlags_None : ImGuiWindowFlags_AlwaysAutoResize) |
                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
  ImGui::SetWindowFontScale(scale);
  panelsOf(model).legend(model);
  // dragged by hand (ImGui's own moving would fight the corner placement)
  const ImVec2 pos = ImGui::GetWindowPos(), size = ImGui::GetWindowSize();
  // a drag that began on the legend moves it until the button is let go
  if (ImGui::IsWindowHovered() && ImGui::IsMouseClicked(ImGuiMouseButton_Left))
    ui.legendDragging = true;
  if (!ImGui::IsMouseDown(ImGuiMouseButton_Left)) ui.legendDragging = false;
  const ImVec2 delta = ImGui::GetIO().MouseDelta;
  if (ui.legendDragging && (delta.x != 0.0f || delta.y != 0.0f) && ImGui::IsMousePosValid()) {
    ui.legendMoved = true;
    ui.legendPos[0] = pos.x + delta.x;
    ui.legendPos[1] = pos.y + delta.y;
  } else if (ImGui::IsWindowHovered() && ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left)) {
    ui.legendMoved = false;  // back to the corner, and the scene fitted beside it
    model.requestFit();
  } else if (ImGui::IsWindowHovered() && !ui.exporting) {
    ImGui::SetTooltip("drag to move, double-click: back to the corner; G hides the legend");
  }
  const bool resized = std::abs(size.x / scale - ui.legendSize[0]) > 2.0f ||
                       std::abs(size.y / scale - ui.legendSize[1]) > 2.0f;
  // fitted a moment ago for another size: fit again; and rows added (a cell pinned) over a
  // view left as fitted: fit beside the taller legend, which would cover the scene
  const bool grew = size.y / scale > ui.legendSize[1] + 2.0f && ui.legendSize[1] > 0.0f;
  if (resized && (now < ui.refitUntil || (grew && viewAsFitted(model, ui)))) model.requestFit();
  // at the body text's size, which the layout scales
  ui.legendSize[0] = size.x / scale;
  ui.legendSize[1] = size.y / scale;
  // where it is, for the labels to keep off
  ui.legendRect[0] = pos.x, ui.legendRect[1] = pos.y;
  ui.legendRect[2] = pos.x + size.x, ui.legendRect[3] = pos.y + size.y;
  ImGui::End();
  ImGui::PopStyleVar(2);
}

void layoutBox(const char* id, const TextBox& t, std::size_t large, Rgba rest) {
  if (t.lines.empty()) return;
  const glm::dvec2 size = t.box.size();
  ImGui::SetNextWindowPos(ImVec2(static_cast<float>(t.box.lo.x), static_cast<float>(t.box.lo.y)));
  ImGui::SetNextWindowSize(ImVec2(static_cast<float>(size.x), static_cast<float>(size.y)));
  ImGui::SetNextWindowBgAlpha(0.9f);
  // the window's own padding as the layout's: its clip rectangle lets the lines show whole
  const float boxPad =
      t.padding >= 0.0 ? static_cast<float>(t.padding) : ImGui::GetStyle().WindowPadding.x;
  ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(boxPad, boxPad));
  ImGui::Begin(id, nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove |
                   ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoFocusOnAppearing |
                   ImGuiWindowFlags_NoNav | ImGuiWindowFlags_NoInputs);
  const ImGuiStyle& style = ImGui::GetStyle();
  const float font = ImGui::GetFontSize();  // the body size, before any scaling
  const float pad = t.padding >= 0.0 ? static_cast<float>(t.padding) : style.WindowPadding.x;
  // the line gap scales with the text where the layout scaled it (a slide's smaller text)
  const float gap = style.ItemSpacing.y * static_cast<float>(t.restScale);
  // each line where the layout puts it: the padding, then line after line
  float y = static_cast<float>(t.box.lo.y) + pad;
  for (std::size_t k = 0; k < t.lines.size(); ++k) {
    const float scale = static_cast<float>(k < large ? t.scale : t.restScale);
    ImGui::SetWindowFontScale(scale);
    ImGui::SetCursorScreenPos(ImVec2(static_cast<float>(t.box.lo.x) + pad, y));
    if (k < large)
      ImGui::TextUnformatted(t.lines[k].c_str());
    else
      ImGui::TextColored(im(rest), "%s", t.lines[k].c_str());
    y += scale * font + gap;
  }
  ImGui::SetWindowFontScale(1.0f);
  ImGui::End();
  ImGui::PopStyleVar();
}

void captionBox(Model& model, UiState& ui, ScreenRect area) {
  const TextBox& t = ui.layout.caption;
  const float before = ui.captionHeight;
  ui.captionHeight = t.lines.empty() ? 0.0f : static_cast<float>(area.hi.y - t.box.lo.y);
  // a caption of another height (a new slide's) leaves the scene other room: refit
  if (std::abs(ui.captionHeight - before) > 1.0f) model.requestFit();
  layoutBox("##caption", t, t.lines.size(), paletteFor(model.settings.theme).text);
  const TextBox& note = ui.layout.note;  // a slide's note on its figure
  if (!note.lines.empty())
    layoutBox("##note", note, note.lines.size(), paletteFor(model.settings.theme).text);
}

void toast(Model& model, UiState& ui, ScreenRect area, double now) {
  if (model.errorSerial() != ui.toastSerial) {
    ui.toastSerial = model.errorSerial();
    ui.toast = model.error();
    ui.toastUntil = now + 9.0;
    if (!ui.toast.empty()) std::cerr << "convexloc-viewer: " << ui.toast << "\n";
  }
  const Palette& pal = paletteFor(model.settings.theme);
  // below a slide's card: a message never hides the slide's title
  float y = 10.0f + model.settings.slideCardHeight;
  auto banner = [&](const char* id, const std::string& text, Rgba colour, bool closable,
                    double& until) {
    if (text.empty() || now > until) return;
    const float w =
        std::min(static_cast<float>(area.size().x) - 40.0f, ImGui::GetFontSize() * 36.0f);
    ImGui::SetNextWindowPos(ImVec2(static_cast<float>(area.middle().x), y), ImGuiCond_Always,
                            ImVec2(0.5f, 0.0f));
    ImGui::SetNextWindowSizeConstraints(ImVec2(w, 0.0f), ImVec2(w, 400.0f));
    ImGui::SetNextWindowBgAlpha(0.95f);
    ImGui::PushStyleColor(ImGuiCol_Border, im(colour));
    ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 1.5f);
    ImGui::Begin(id, nullptr,
                 ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                     ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
    ImGui::PushStyleColor(ImGuiCol_Text, im(colour));
    // broken at spaces only: a number never splits across lines
    for (const std::string& line :
         breakAtSpaces(text, w - 2.0f * ImGui::GetStyle().WindowPadding.x, measureText))
      ImGui::TextUnformatted(line.c_str());
    ImGui::PopStyleColor();
    if (closable && ImGui::SmallButton("dismiss")) until = 0.0;
    y += ImGui::GetWindowHeight() + 6.0f;
    ImGui::End();
    ImGui::PopStyleVar();
    ImGui::PopStyleColor();
  };
  banner("##error", ui.toast, pal.negative, true, ui.toastUntil);
  banner("##notice", ui.notice, pal.positive, false, ui.noticeUntil);
}

}  // namespace convexloc::viewer
