// convexloc-viewer — the Why O(1) window.
#include "ui/panels/scaling_panel.hpp"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <filesystem>
#include <iostream>

#include <imgui.h>

#include "logic/base/format.hpp"
#include "logic/teach/scaling_record.hpp"
#include "ui/scene_area.hpp"
#include "ui/slide_frame.hpp"
#include "ui/widgets.hpp"

namespace convexloc::viewer {
namespace {

// the largest N the window offers
constexpr std::size_t kMostChoices[] = {4096, 32768, 262144, 1000000};

ImVec2 at(glm::dvec2 p, ImVec2 o) {
  return {o.x + static_cast<float>(p.x), o.y + static_cast<float>(p.y)};
}

// a polyline, dashed 6 px on 4 off when asked
void drawPath(ImDrawList* dl, const PlotPath& p, ImVec2 o) {
  const ImU32 c = packAbgr(p.colour);
  for (std::size_t i = 1; i < p.points.size(); ++i) {
    const glm::dvec2 a = p.points[i - 1], b = p.points[i];
    if (!p.dashed) {
      dl->AddLine(at(a, o), at(b, o), c, p.width);
      continue;
    }
    const double len = glm::length(b - a);
    for (double t = 0.0; t < len; t += 10.0)
      dl->AddLine(at(a + (b - a) * (t / len), o),
                  at(a + (b - a) * (std::min(t + 6.0, len) / len), o), c, p.width);
  }
}

// a laid-out plot on ImGui's draw list, `o` its origin in window pixels, its text
// style.fontPx high; series-coloured text darkened where it would not read on the
// background (the light theme)
void drawPlot(ImDrawList* dl, const PlotDrawing& d, ImVec2 o, const PlotStyle& style) {
  for (const PlotPath& p : d.paths) drawPath(dl, p, o);
  for (const PlotMark& m : d.marks) dl->AddCircleFilled(at(m.p, o), m.radius, packAbgr(m.colour));
  ImFont* font = ImGui::GetFont();
  const auto px = static_cast<float>(style.fontPx);
  for (const PlotText& t : d.texts) {
    const char* text = t.text.c_str();
    const ImVec2 size = font->CalcTextSizeA(px, FLT_MAX, 0.0f, text, text + t.text.size());
    const ImVec2 p = at(t.p, o);
    dl->AddText(
        font, px, ImVec2(std::round(p.x - t.anchor * size.x), std::round(p.y - 0.5f * size.y)),
        packAbgr(readableOn(t.colour, style.background, style.text)), text, text + t.text.size());
  }
}

// Measure, the largest N, Cancel, Export SVG
void controls(Model& model, UiState& ui, const ScalingProgress& p) {
  // the choice starts at the last run's largest N
  static int most = -1;
  if (most < 0) {
    const auto& sizes = model.scaling->config().sizes;
    const std::size_t last = sizes.empty() ? kMostChoices[3] : sizes.back();
    most = 0;
    while (most < 3 && kMostChoices[most] < last) ++most;
  }
  ImGui::SetNextItemWidth(ImGui::GetFontSize() * 11.0f);
  if (ImGui::BeginCombo("##most", ("N up to " + grouped(kMostChoices[most])).c_str())) {
    for (int i = 0; i < static_cast<int>(std::size(kMostChoices)); ++i)
      if (ImGui::Selectable(("N up to " + grouped(kMostChoices[i])).c_str(), i == most)) most = i;
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  if (p.running) {
    if (ImGui::Button("Cancel")) model.scaling->cancel();
  } else if (ImGui::Button("Measure")) {
    model.scaling->start(scalingConfig(kMostChoices[most]));
  }
  ImGui::SameLine();
  if (ImGui::Button("Export SVG")) {
    const std::string path = std::filesystem::absolute("convexloc-why-o1.svg").string();
    std::string error;
    const ScalingConfig& c = model.scaling->config();
    if (writeScalingSvg(path, p.result, c, model.settings.theme, error) &&
        writeScalingSvg(solidSvgPath(path), p.result, c, model.settings.theme, error, true)) {
      ui.notice = "wrote " + path + " and " + solidSvgPath(path) + " (3D)";
      ui.noticeUntil = ImGui::GetTime() + 6.0;
    } else {
      model.fail(error);
    }
  }
  help(
      "Regular N-gons: each method traces a few hundred random points (core's trace: edge and "
      "ray tests) and locates a fixed random set in batches (ns per query). The O(1) methods "
      "stay flat.");
}

// One page of plots filling the rest of the window, as a slide: its text shrinks with the
// window (a page reads at about 60 x 44 em) down to 45% of the panels' text; the window
// scrolls only where the page would be smaller than 40 x 30 em of that text.
void plots(const Model& model, UiState& ui, const ScalingProgress& p, bool solid) {
  const float font = ImGui::GetFontSize();
  const ImVec2 avail = ImGui::GetContentRegionAvail();
  const float fit = std::min(avail.x / (60.0f * font), avail.y / (44.0f * font));
  const float scale = std::clamp(fit, 0.45f, 1.0f);
  const float plotFont = font * scale;
  const ImVec2 size(std::max(avail.x, 40.0f * plotFont), std::max(avail.y, 30.0f * plotFont));
  const ImVec2 o = ImGui::GetCursorScreenPos();
  ImGui::Dummy(size);
  ImDrawList* dl = ImGui::GetWindowDrawList();
  const PlotStyle style = plotStyle(model.settings.theme, plotFont);
  ui.whyPlots = {{{o.x, o.y}, {o.x + size.x, o.y + size.y}}, plotFont, solid};  // for the SVG
  ImGui::SetWindowFontScale(scale);
  for (const PlotDrawing& d :
       scalingDrawings(p.result, model.scaling->config(), style, {size.x, size.y}, solid))
    drawPlot(dl, d, o, style);
  ImGui::SetWindowFontScale(1.0f);
}

}  // namespace

namespace {

// A lecture's Why O(1) slide: the page's plots in the slide's figure room (its layout's
// PlotsLayout), under the slide's boxes, without the window or its widgets; while a
// measurement runs, its progress in place of the line under them.
void scalingSlide(const Model& model, UiState& ui) {
  if (!ui.layout.plots) return;
  const PlotsLayout& l = *ui.layout.plots;
  const ScalingProgress p = model.scaling->snapshot();
  const std::string status = p.running          ? "measuring " + p.current + " ..."
                             : !p.error.empty() ? p.error
                                                : std::string();
  const PlotStyle style = slidePlotStyle(model.settings.theme, l.fontPx);
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  for (const PlotDrawing& d :
       slideDrawings(p.result, model.scaling->config(), style, l, model.whySolid, status))
    drawPlot(dl, d, ImVec2(0.0f, 0.0f), style);
  ui.whyPlots = {ui.layout.scene, l.fontPx, model.whySolid};
}

}  // namespace

void scalingWindow(Model& model, UiState& ui) {
  ui.whyPlots = {};
  ui.whyWindow = {};
  if (!model.whyOpen) return;
  model.scaling->step();  // a measurement without a thread goes on a size a frame
  if (plotsSlide(model, ui)) return scalingSlide(model, ui);
  const ImGuiIO& io = ImGui::GetIO();
  // between a slide's card and its caption, where a lecture shows them (kept there while
  // the panels are hidden), in the page
  const ImGuiCond cond = model.settings.showUi ? ImGuiCond_Appearing : ImGuiCond_Always;
  const ScreenRect area = sceneArea(model, ui, {io.DisplaySize.x, io.DisplaySize.y});
  const float top = static_cast<float>(area.lo.y),
              bottom = static_cast<float>(area.hi.y) - ui.captionHeight;
  const float width = static_cast<float>(area.size().x) * (model.settings.showUi ? 0.8f : 0.96f);
  ImGui::SetNextWindowSize(
      ImVec2(width, std::min(static_cast<float>(area.size().y) * 0.88f, bottom - top - 8.0f)),
      cond);
  ImGui::SetNextWindowPos(ImVec2(static_cast<float>(area.middle().x), 0.5f * (top + bottom)), cond,
                          ImVec2(0.5f, 0.5f));
  ImGui::SetNextWindowBgAlpha(1.0f);
  if (!ImGui::Begin("Why O(1): cost against N", &model.whyOpen,
                    ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_HorizontalScrollbar)) {
    ImGui::End();
    return;
  }
  const ScalingProgress p = model.scaling->snapshot();
  controls(model, ui, p);
  const float share = p.total ? static_cast<float>(p.done) / static_cast<float>(p.total) : 0.0f;
  const std::string what = p.running          ? "measuring " + p.current
                           : p.cancelled      ? "cancelled"
                           : !p.error.empty() ? p.error
                           : p.finished ? (p.current.starts_with("recorded") ? p.current : "done")
                                        : "press Measure";
  // the progress on the controls' row where it has room, so that the plots get the height
  if (ImGui::GetWindowPos().x + ImGui::GetWindowContentRegionMax().x - ImGui::GetItemRectMax().x >
      ImGui::GetFontSize() * 12.0f)
    ImGui::SameLine();
  ImGui::ProgressBar(share, ImVec2(-1.0f, 0.0f), what.c_str());
  // the window opens on the tab of the scene shown
  const bool appearing = ImGui::IsWindowAppearing();
  if (ImGui::BeginTabBar("##dims")) {
    for (const bool solid : {false, true})
      if (ImGui::BeginTabItem(
              solid ? "3D: geodesic spheres" : "2D: regular N-gons", nullptr,
              appearing && solid == model.whySolid ? ImGuiTabItemFlags_SetSelected : 0)) {
        plots(model, ui, p, solid);
        ImGui::EndTabItem();
      }
    ImGui::EndTabBar();
  }
  ui.whyWindow = {{ImGui::GetWindowPos().x, ImGui::GetWindowPos().y},
                  {ImGui::GetWindowPos().x + ImGui::GetWindowSize().x,
                   ImGui::GetWindowPos().y + ImGui::GetWindowSize().y}};
  ImGui::End();
  if (!model.whyOpen) model.scaling->cancel();
}

namespace {

// the measurement --why-svg and --why-record write: --why-from's record, else measured now
bool measureOrRead(const Options& options, ScalingResult& r, ScalingConfig& c, std::string& error) {
  if (!options.whyFrom.empty()) return readScalingRecord(options.whyFrom, r, c, error);
  ScalingWorker worker;
  c = scalingConfig(options.whyMost);
  worker.start(c);
  worker.wait();
  ScalingProgress p = worker.snapshot();
  error = p.error;
  r = std::move(p.result);
  return error.empty();
}

}  // namespace

int measureToSvg(const Options& options) {
  ScalingResult r;
  ScalingConfig c;
  std::string error;
  if (!measureOrRead(options, r, c, error)) {
    std::cerr << "convexloc-viewer: " << error << "\n";
    return 1;
  }
  if (!options.whyRecord.empty()) {
    if (!writeScalingRecord(options.whyRecord, r, c, error)) {
      std::cerr << "convexloc-viewer: " << error << "\n";
      return 1;
    }
    std::cout << "convexloc-viewer: recorded " << options.whyRecord << "\n";
  }
  if (options.whySvg.empty()) return 0;
  const std::string solid = solidSvgPath(options.whySvg);
  if (!writeScalingSvg(options.whySvg, r, c, options.theme, error) ||
      !writeScalingSvg(solid, r, c, options.theme, error, true)) {
    std::cerr << "convexloc-viewer: " << error << "\n";
    return 1;
  }
  std::cout << "convexloc-viewer: wrote " << options.whySvg << " (N = 8 .. "
            << grouped(c.sizes.back()) << ") and " << solid << " (F = 20 .. "
            << grouped(c.faces.empty() ? 0 : c.faces.back()) << ")\n";
  return 0;
}

}  // namespace convexloc::viewer
