// convexloc-viewer — the slide card, the Lecture panel, the slide keys.
#include "ui/panels/lecture_panel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include <imgui.h>

#include "logic/teach/figures.hpp"
#include "ui/widgets.hpp"

namespace convexloc::viewer {
namespace {

// the paper's figure n as the only slide, in the viewer's text size and panels
void showFigure(Model& model, UiState& ui, int n) {
  const std::vector<std::string> words = figureArgs(n);
  const std::vector<std::string_view> args(words.begin(), words.end());
  ui.show.lecture = figureLecture(n, parseOptions(args).options);
  ui.show.lecture.slides[0].keys = {"figure", "theme"};
  goToSlide(model, ui, 0);
}

// the slides, one line each; a click shows it
void slideList(Model& model, UiState& ui) {
  const auto& slides = ui.show.lecture.slides;
  const float rows = static_cast<float>(std::min<std::size_t>(slides.size(), 8));
  ImGui::BeginChild("##slides",
                    ImVec2(0.0f, rows * ImGui::GetTextLineHeightWithSpacing() +
                                     2.0f * ImGui::GetStyle().WindowPadding.y),
                    true);
  for (std::size_t k = 0; k < slides.size(); ++k) {
    char line[160];
    std::snprintf(line, sizeof line, "%2zu  %s", k + 1, slides[k].title.c_str());
    if (ImGui::Selectable(line, k == ui.show.current))
      goToSlide(model, ui, static_cast<std::ptrdiff_t>(k));
  }
  ImGui::EndChild();
}

// previous and next, as PageUp and PageDown
void slideButtons(Model& model, UiState& ui) {
  const float half = 0.5f * (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x);
  const auto at = static_cast<std::ptrdiff_t>(ui.show.current);
  if (ImGui::Button("< previous (PgUp)", ImVec2(half, 0.0f))) goToSlide(model, ui, at - 1);
  ImGui::SameLine();
  if (ImGui::Button("next (PgDn) >", ImVec2(half, 0.0f))) goToSlide(model, ui, at + 1);
}

// the paper's figures: buttons 1..7
void figureGallery(Model& model, UiState& ui) {
  ImGui::TextDisabled("Paper figures (one click each)");
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  const float w = (ImGui::GetContentRegionAvail().x - (kFigureCount - 1) * spacing) / kFigureCount;
  for (int n = 1; n <= kFigureCount; ++n) {
    if (n > 1) ImGui::SameLine();
    const std::string id = std::to_string(n);
    if (ImGui::Button(id.c_str(), ImVec2(w, 0.0f))) showFigure(model, ui, n);
    if (ImGui::IsItemHovered())
      ImGui::SetTooltip("%s\n%s", figure(n).title.data(), figure(n).caption.data());
  }
}

// the card's height becomes the band the scene keeps free; a change refits the scene
void keepBand(Model& model, float height) {
  if (std::abs(model.settings.slideCardHeight - height) < 1.0f) return;
  model.settings.slideCardHeight = height;
  model.requestFit();
}

}  // namespace

bool startLecture(Model& model, UiState& ui, const Options& options, bool headless) {
  if (options.lecture.empty()) {
    if (options.figure) ui.show.lecture = figureLecture(*options.figure, options);
    return true;
  }
  ParsedLecture parsed = loadLecture(options.lecture);
  if (!parsed.error.empty()) {
    if (headless) {
      std::cerr << "convexloc-viewer: " << parsed.error << "\n";
      return false;
    }
    model.fail(parsed.error);
    return true;
  }
  ui.show.lecture = std::move(parsed.lecture);
  const std::string problem = showSlideNow(model, ui, options.slide - 1);
  if (!problem.empty() && headless) {
    std::cerr << "convexloc-viewer: " << options.lecture << ": slide " << ui.show.current + 1
              << ": " << problem << "\n";
    return false;
  }
  return true;
}

std::string showSlideNow(Model& model, UiState& ui, std::ptrdiff_t k) {
  const std::string problem = ui.show.go(model, k);
  ui.compare2d.clear();
  ui.compare3d.clear();
  if (ui.show.active() && ui.show.slide().options.compare) {
    if (model.dim == Dim::Two) ui.compare2d = model.scene2d.compare();
    if (model.dim == Dim::Three) ui.compare3d = model.scene3d().compare();
  }
  return problem;
}

void goToSlide(Model& model, UiState& ui, std::ptrdiff_t k) {
  const std::string problem = showSlideNow(model, ui, k);
  if (!problem.empty()) model.fail("slide " + std::to_string(ui.show.current + 1) + ": " + problem);
}

void moveSlide(ActionKind kind, Model& model, UiState& ui) {
  if (!ui.show.active()) return;
  const auto at = static_cast<std::ptrdiff_t>(ui.show.current);
  const auto last = static_cast<std::ptrdiff_t>(ui.show.lecture.slides.size()) - 1;
  const std::ptrdiff_t to = kind == ActionKind::NextSlide       ? at + 1
                            : kind == ActionKind::PreviousSlide ? at - 1
                            : kind == ActionKind::FirstSlide    ? 0
                                                                : last;
  if (to != at && to >= 0 && to <= last) goToSlide(model, ui, to);
  ui.pointerStill = true;
}

void slideCard(Model& model, UiState& ui, ScreenRect area) {
  if (!ui.show.active()) {
    keepBand(model, 0.0f);
    return;
  }
  const Slide& s = ui.show.slide();
  const std::size_t count = ui.show.lecture.slides.size();
  const float w = std::min(static_cast<float>(area.size().x) * 0.7f, ImGui::GetFontSize() * 44.0f);
  // at the window's top, not the area's: the area starts below the card
  ImGui::SetNextWindowPos(ImVec2(static_cast<float>(area.lo.x) + 12.0f, 12.0f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(0.0f, 0.0f), ImVec2(w, 1e6f));
  ImGui::SetNextWindowBgAlpha(0.88f);
  ImGui::Begin("##slide", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
  ImGui::PushTextWrapPos(w - ImGui::GetStyle().WindowPadding.x);
  ImGui::SetWindowFontScale(1.3f);
  if (count > 1)
    ImGui::Text("%zu / %zu: %s", ui.show.current + 1, count, s.title.c_str());
  else
    ImGui::TextUnformatted(s.title.c_str());
  ImGui::SetWindowFontScale(1.0f);
  // a caption the scene shows in its own box (--caption) is not written twice
  if (!s.caption.empty() && model.settings.caption.empty())
    textAtSpaces(s.caption, {}, w - 2.0f * ImGui::GetStyle().WindowPadding.x);
  ImGui::PopTextWrapPos();
  const float band = ImGui::GetWindowPos().y + ImGui::GetWindowHeight() + 8.0f;
  ImGui::End();
  keepBand(model, band);
}

void lecturePanel(Model& model, UiState& ui) {
  if (!ImGui::CollapsingHeader("Lecture", ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (ui.show.lecture.slides.size() > 1) {
    slideList(model, ui);
    slideButtons(model, ui);
  } else {
    ImGui::TextWrapped("%s", "Open a lecture with --lecture FILE (see docs/viewer.md).");
  }
  figureGallery(model, ui);
}

}  // namespace convexloc::viewer
