// convexloc-viewer — the slide card, the Lecture panel, the slide keys.
#include "ui/panels/lecture_panel.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

#include <imgui.h>

#include "logic/teach/figures.hpp"
#include "ui/overlays.hpp"
#include "ui/widgets.hpp"

namespace convexloc::viewer {
namespace {

// the paper's figure n as the only slide, in the viewer's text size and panels
void showFigure(Model& model, UiState& ui, int n) {
  const std::vector<std::string> words = figureArgs(n);
  const std::vector<std::string_view> args(words.begin(), words.end());
  ui.show.lecture = figureLecture(n, parseOptions(args).options);
  ui.show.dismissed.clear();
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
  {
    Model scratch;  // every slide shown once, so that every problem is known now
    checkSlides(parsed, scratch);
  }
  for (const std::string& p : parsed.problems) std::cerr << "convexloc-viewer: " << p << "\n";
  ui.show.lecture = std::move(parsed.lecture);
  ui.show.lookTaken = false;
  ui.show.dismissed.clear();
  // --export writes the good slides; a window shows the first, its problems over it
  const std::size_t first = options.exportDir.empty() ? 0 : ui.show.goodFrom(0);
  if (first >= ui.show.lecture.slides.size()) {
    if (headless) return false;
    if (!parsed.problems.empty()) model.fail(parsed.problems.front());
    return true;
  }
  // --slide K opens the window at slide K (a link to a slide in the web page)
  const std::ptrdiff_t start =
      options.exportDir.empty() ? options.slide - 1 : static_cast<std::ptrdiff_t>(first);
  const std::string problem = showSlideNow(model, ui, start);
  if (!problem.empty() && headless) {
    std::cerr << "convexloc-viewer: " << options.lecture << ": slide " << ui.show.current + 1
              << ": " << problem << "\n";
    return false;
  }
  if (!headless) printNotes(ui.show);
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
  ui.show.blank = false;
  const std::string problem = showSlideNow(model, ui, k);
  if (!problem.empty()) model.fail("slide " + std::to_string(ui.show.current + 1) + ": " + problem);
  printNotes(ui.show);
}

void moveSlide(ActionKind kind, Model& model, UiState& ui) {
  // a blanked screen comes back where it was, as PowerPoint's does
  if (ui.show.blank) {
    ui.show.blank = false;
    return;
  }
  if (!ui.show.active()) return;
  const std::size_t to = ui.show.target(kind);
  if (to != ui.show.current) goToSlide(model, ui, static_cast<std::ptrdiff_t>(to));
  ui.pointerStill = true;
}

void printNotes(const SlideShow& show) {
  if (!show.active() || show.slide().notes.empty()) return;
  std::cout << "--- " << show.current + 1 << " / " << show.lecture.slides.size() << ": "
            << show.slide().title << "\n";
  for (const std::string& line : show.slide().notes) std::cout << "    " << line << "\n";
  std::cout << std::flush;
}

void problemsBox(SlideShow& show, ScreenRect area) {
  const std::vector<std::string> problems = show.shownProblems();
  if (problems.empty()) return;
  const ImGuiIO& io = ImGui::GetIO();
  const float w = std::min(static_cast<float>(area.size().x) * 0.9f, ImGui::GetFontSize() * 50.0f);
  ImGui::SetNextWindowPos(
      ImVec2(static_cast<float>(area.lo.x + area.hi.x) * 0.5f, io.DisplaySize.y * 0.5f),
      ImGuiCond_Always, ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowSizeConstraints(ImVec2(w, 0.0f), ImVec2(w, io.DisplaySize.y * 0.8f));
  ImGui::PushStyleColor(ImGuiCol_Border, ImVec4(0.84f, 0.37f, 0.0f, 1.0f));
  ImGui::PushStyleVar(ImGuiStyleVar_WindowBorderSize, 3.0f);
  ImGui::Begin("##problems", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing);
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextUnformatted(show.active() ? "This slide is not shown as written (the other slides "
                                         "play on):"
                                       : "This lecture has no slide to show:");
  // a bullet, then the problem wrapped at the box's edge (BulletText does not wrap)
  for (const std::string& p : problems) {
    ImGui::Bullet();
    ImGui::TextUnformatted(p.c_str());
  }
  ImGui::PopTextWrapPos();
  if (ImGui::Button("Dismiss (D)")) show.dismiss();
  ImGui::End();
  ImGui::PopStyleVar();
  ImGui::PopStyleColor();
}

void notesWindow(const SlideShow& show, bool& open) {
  if (!open || !show.active()) return;
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowSize(ImVec2(ImGui::GetFontSize() * 30.0f, ImGui::GetFontSize() * 14.0f),
                           ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowPos(
      ImVec2(io.DisplaySize.x - ImGui::GetFontSize() * 31.0f, ImGui::GetFontSize()),
      ImGuiCond_FirstUseEver);
  ImGui::SetNextWindowBgAlpha(1.0f);
  if (!ImGui::Begin("Speaker notes (N)", &open, ImGuiWindowFlags_NoFocusOnAppearing)) {
    ImGui::End();
    return;
  }
  const Slide& s = show.slide();
  const std::size_t count = show.lecture.slides.size();
  ImGui::Text("%zu / %zu: %s", show.current + 1, count, s.title.c_str());
  ImGui::Separator();
  ImGui::PushTextWrapPos(0.0f);
  if (s.notes.empty()) ImGui::TextDisabled("(no notes on this slide)");
  for (const std::string& line : s.notes) ImGui::TextUnformatted(line.c_str());
  ImGui::PopTextWrapPos();
  if (show.current + 1 < count) {
    ImGui::Separator();
    ImGui::TextDisabled("next: %s", show.lecture.slides[show.current + 1].title.c_str());
  }
  ImGui::End();
}

void notesContents(const SlideShow& show) {
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
  ImGui::SetNextWindowSize(io.DisplaySize);
  ImGui::Begin(
      "##notes", nullptr,
      ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings);
  if (!show.active()) {
    ImGui::TextDisabled("no lecture");
    ImGui::End();
    return;
  }
  const Slide& s = show.slide();
  const std::size_t count = show.lecture.slides.size();
  ImGui::PushTextWrapPos(0.0f);
  ImGui::TextDisabled("%zu / %zu%s", show.current + 1, count,
                      show.blank ? "  (screen blanked)" : "");
  ImGui::TextUnformatted(s.title.c_str());
  ImGui::Separator();
  if (s.notes.empty()) ImGui::TextDisabled("(no notes on this slide)");
  for (const std::string& line : s.notes) ImGui::TextUnformatted(line.c_str());
  if (show.current + 1 < count) {
    ImGui::Separator();
    ImGui::TextDisabled("next: %s", show.lecture.slides[show.current + 1].title.c_str());
  }
  ImGui::PopTextWrapPos();
  ImGui::End();
}

void blankIfAsked(const SlideShow& show) {
  if (!show.blank) return;
  const ImGuiIO& io = ImGui::GetIO();
  ImGui::GetForegroundDrawList()->AddRectFilled(ImVec2(0.0f, 0.0f), io.DisplaySize,
                                                IM_COL32(0, 0, 0, 255));
}

void slideCard(Model& model, UiState& ui, ScreenRect area) {
  problemsBox(ui.show, area);
  // the notes inside the main window where they cannot have one of their own
  if (!ui.notesOwnWindow) notesWindow(ui.show, ui.showNotes);
  const SlideLayout& l = ui.layout;
  if (!ui.show.active() || l.title.lines.empty()) {
    keepBand(model, 0.0f);
    return;
  }
  layoutBox("##slide", l.title, l.titleLines, paletteFor(model.settings.theme).text);
  // the band the scene keeps free under the card, from the page's top
  keepBand(model, static_cast<float>(l.title.box.hi.y + 0.625 * ImGui::GetFontSize() -
                                     (area.lo.y - model.settings.slideCardHeight)));
}

void lecturePanel(Model& model, UiState& ui) {
  if (!ImGui::CollapsingHeader("Lecture", ImGuiTreeNodeFlags_DefaultOpen)) return;
  if (ui.show.lecture.slides.size() > 1) {
    slideList(model, ui);
    slideButtons(model, ui);
  } else {
    ImGui::TextWrapped("%s", ui.webPage
                                 ? "Open a lecture: Open files... with the .lecture and "
                                   "its shape files together, or a link "
                                   "?lecture=URL (see docs/viewer.md)."
                                 : "Open a lecture with --lecture FILE (see docs/viewer.md).");
  }
  figureGallery(model, ui);
}

}  // namespace convexloc::viewer
