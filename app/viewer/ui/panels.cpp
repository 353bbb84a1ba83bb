// convexloc-viewer — the panels.
#include "ui/panels.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>

#include <GLFW/glfw3.h>
#include <imgui.h>

#include "logic/presets.hpp"
#include "logic/text.hpp"
#include "ui/screenshot.hpp"
#include "ui/widgets.hpp"

namespace convexloc::viewer {
namespace {

// "O(1)" and friends, per method
const char* complexityOf(Method2D m) {
  switch (m) {
    case Method2D::Halfplane: return "O(N)";
    case Method2D::Wedge: return "O(log N)";
    case Method2D::Slab: return "O(log N)";
    case Method2D::Uniform: return "O(1)";
    case Method2D::Polar: return "O(1), the paper's";
  }
  return "";
}

// === Shape

void shapePanel(Model& model, UiState& ui) {
  Scene2D& scene = model.scene2d;
  const ConvexPolygon& poly = scene.polygon();
  ImGui::TextWrapped("%s", scene.label().c_str());
  ImGui::TextDisabled("%s vertices", grouped(poly.size()).c_str());
  if (poly.droppedCount() > 0) {
    ImGui::SameLine();
    ImGui::TextDisabled("(%s dropped: repeated or collinear)",
                        grouped(poly.droppedCount()).c_str());
  }
  if (poly.wasClockwise()) {
    ImGui::SameLine();
    ImGui::TextDisabled("(given clockwise)");
  }

  fileOpen(model, ui, "polygon .txt, polyhedron .off/.obj");

  // generate one
  ImGui::Spacing();
  const int kinds = static_cast<int>(std::size(kAllPolygonKinds));
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
  if (ImGui::BeginCombo("##kind",
                        std::string(toString(kAllPolygonKinds[ui.generatorKind])).c_str())) {
    for (int k = 0; k < kinds; ++k)
      if (ImGui::Selectable(std::string(toString(kAllPolygonKinds[k])).c_str(),
                            k == ui.generatorKind))
        ui.generatorKind = k;
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  if (ImGui::Button("Generate", ImVec2(-1.0f, 0.0f)))
    if (scene.generate(kAllPolygonKinds[ui.generatorKind], static_cast<std::size_t>(ui.generatorN),
                       ui.generatorSeed))
      model.requestFit();
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
  ImGui::InputInt("N", &ui.generatorN, 1, 16);
  ui.generatorN = std::clamp(ui.generatorN, 3, 1 << 22);
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
  ImGui::InputScalar("seed", ImGuiDataType_U64, &ui.generatorSeed);
  ImGui::SameLine();
  if (ImGui::SmallButton("next")) {
    ++ui.generatorSeed;
    if (scene.generate(kAllPolygonKinds[ui.generatorKind], static_cast<std::size_t>(ui.generatorN),
                       ui.generatorSeed))
      model.requestFit();
  }

  ImGui::Spacing();
  ImGui::TextDisabled("Degenerate gallery");
  gallery(model, false);
  ImGui::TextDisabled("Drag a vertex handle to edit the polygon.");
}

// === Method

void methodPanel(Model& model, UiState& ui) {
  Scene2D& scene = model.scene2d;
  for (Method2D m : kAllMethods2D) {
    const std::string name = std::string(toString(m));
    if (ImGui::RadioButton(name.c_str(), scene.method() == m)) scene.setMethod(m);
    ImGui::SameLine(ImGui::GetFontSize() * 7.0f);
    ImGui::TextDisabled("%s", complexityOf(m));
  }
  const Method2D m = scene.method();
  if (m == Method2D::Uniform || m == Method2D::Polar) {
    bool automatic = scene.resolution() == 0;
    int r = static_cast<int>(scene.effectiveResolution());
    if (ImGui::Checkbox("auto", &automatic))
      scene.setResolution(automatic ? 0 : static_cast<std::uint32_t>(r));
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    const int most = m == Method2D::Uniform ? 1 << 20 : 1 << 16;
    if (ImGui::SliderInt("##res", &r, 1, most,
                         m == Method2D::Uniform ? "%d slabs" : "%d per octant",
                         ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
      scene.setResolution(static_cast<std::uint32_t>(std::max(r, 1)));
  }

  const Stats2D& s = scene.stats();
  if (ImGui::BeginTable("stats", 2, ImGuiTableFlags_SizingStretchProp)) {
    auto row = [](const char* k, const std::string& v) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextDisabled("%s", k);
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(v.c_str());
    };
    row("edges", grouped(s.edges));
    if (s.cells) {
      row("cells", grouped(s.cells));
      row("edges per cell",
          "max " + std::to_string(s.maxPerCell) + ", mean " + approx(s.meanPerCell, 3));
      if (s.crowdedCells) row("crowded cells", grouped(s.crowdedCells) + " (bisection)");
    }
    if (scene.cellsOmitted()) row("drawing", "too many cells to draw");
    row("memory", bytesText(s.bytes) + " (" + approx(s.bytesPerEdge, 3) + " B/edge)");
    row("build", approx(s.buildSeconds * 1e3, 3) + " ms");
    if (!scene.points().empty()) row("locate", nsText(scene.locateNsPerPoint()) + " ns/point");
    ImGui::EndTable();
  }
  if (!s.histogram.empty() && s.cells) {
    std::vector<float> h(s.histogram.begin(), s.histogram.end());
    ImGui::TextDisabled("cells by edges listed: 0, 1, ..., %zu+", h.size() - 1);
    ImGui::PlotHistogram("##hist", h.data(), static_cast<int>(h.size()), 0, nullptr, 0.0f, FLT_MAX,
                         ImVec2(ImGui::GetContentRegionAvail().x, ImGui::GetFontSize() * 4.0f));
    if (ImGui::IsItemHovered()) {
      ImGui::BeginTooltip();
      for (std::size_t k = 0; k < s.histogram.size(); ++k)
        if (s.histogram[k])
          ImGui::Text("%s%zu edges: %s cells", k + 1 == s.histogram.size() ? ">= " : "", k,
                      grouped(s.histogram[k]).c_str());
      ImGui::EndTooltip();
    }
  }

  if (ImGui::Button("Compare all methods", ImVec2(-1.0f, 0.0f))) ui.compare = scene.compare();
  help(
      "Times every method's batch locate on the current spray (at most ~0.1 s each) and checks "
      "that all answer the same.");
  if (!ui.compare.empty() &&
      ImGui::BeginTable("compare", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
    ImGui::TableSetupColumn("method");
    ImGui::TableSetupColumn("ns/pt");
    ImGui::TableSetupColumn("build");
    ImGui::TableSetupColumn("agree");
    ImGui::TableHeadersRow();
    double best = 1e300;
    for (const CompareRow& r : ui.compare)
      if (r.points) best = std::min(best, r.nsPerPoint);
    const Palette& pal = paletteFor(model.settings.theme);
    for (const CompareRow& r : ui.compare) {
      ImGui::TableNextRow();
      ImGui::TableNextColumn();
      ImGui::TextUnformatted(std::string(toString(r.method)).c_str());
      ImGui::TableNextColumn();
      if (r.nsPerPoint == best)
        ImGui::TextColored(im(pal.positive), "%s", nsText(r.nsPerPoint).c_str());
      else
        ImGui::Text("%s", nsText(r.nsPerPoint).c_str());
      if (ImGui::IsItemHovered())
        ImGui::SetTooltip("%s points located, %s", grouped(r.points).c_str(),
                          bytesText(r.bytes).c_str());
      ImGui::TableNextColumn();
      ImGui::Text("%s ms", approx(r.buildMs, 2).c_str());
      ImGui::TableNextColumn();
      if (r.disagreements == 0)
        ImGui::TextColored(im(pal.positive), "yes");
      else
        ImGui::TextColored(im(pal.negative), "%zu differ", r.disagreements);
    }
    ImGui::EndTable();
  }
}

// === View

void viewPanel(Model& model, Renderer& renderer, UiState& ui) {
  int theme = static_cast<int>(model.settings.theme);
  if (ImGui::RadioButton("dark", theme == 0)) model.settings.theme = Theme::Dark;
  ImGui::SameLine();
  if (ImGui::RadioButton("light", theme == 1)) model.settings.theme = Theme::Light;
  ImGui::SameLine();
  ImGui::SetNextItemWidth(-1.0f);
  ImGui::SliderFloat("##font", &ui.fontScaleEdit, 0.75f, 2.5f, "text %.2fx");
  if (ImGui::IsItemDeactivatedAfterEdit()) ui.pendingFontScale = ui.fontScaleEdit;

  if (model.dim == Dim::Two) {
    View2DOptions& o = model.settings.view2d;
    const float mid = ImGui::GetContentRegionAvail().x * 0.5f;
    ImGui::Checkbox("structure", &o.showStructure);
    ImGui::SameLine(mid);
    ImGui::Checkbox("tinted cells", &o.showTints);
    ImGui::Checkbox("bounding box", &o.showBox);
    ImGui::SameLine(mid);
    ImGui::Checkbox("octant lines", &o.showOctants);
    ImGui::Checkbox("labels", &o.showLabels);
    ImGui::SameLine(mid);
    ImGui::Checkbox("vertex handles", &o.showHandles);
  } else {
    viewOptions3(model);
  }

  const float third =
      (ImGui::GetContentRegionAvail().x - 2.0f * ImGui::GetStyle().ItemSpacing.x) / 3.0f;
  if (ImGui::Button("Fit (F)", ImVec2(third, 0.0f))) model.requestFit();
  ImGui::SameLine();
  if (ImGui::Button("Screenshot", ImVec2(third, 0.0f))) ui.screenshotRequested = true;
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip("F12: a PNG of the window in the working directory");
  ImGui::SameLine();
  if (ImGui::Button("Shaders", ImVec2(third, 0.0f))) ui.reloadShaders = true;
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
  if (!ui.glInfo.empty()) ImGui::TextDisabled("%s", ui.glInfo.c_str());
}

// === Inspector: the hovered cell and the placed point's trace

void inspectorContents(Model& model, bool hints) {
  Scene2D& scene = model.scene2d;
  const Palette& pal = paletteFor(model.settings.theme);
  const auto& probe = scene.probe();
  if (scene.hoveredCell() >= 0) {
    const Cell2D& c = scene.cells()[static_cast<std::size_t>(scene.hoveredCell())];
    ImGui::TextColored(im(pal.hoverEdge), "Under the cursor");
    std::string what = "cell " + std::to_string(c.index);
    if (c.octant >= 0) what += ", octant " + std::to_string(c.octant);
    if (scene.method() == Method2D::Slab || scene.method() == Method2D::Uniform)
      what += ", y in [" + approx(c.y0, 6) + ", " + approx(c.y1, 6) + ")";
    ImGui::TextWrapped("%s", what.c_str());
    std::string edges;
    for (std::size_t i = 0; i < c.edges.size() && i < 24; ++i)
      edges += (i ? ", " : "") + std::to_string(c.edges[i]);
    if (c.edges.size() > 24) edges += ", ...";
    ImGui::TextWrapped("lists %zu edge%s: %s", c.edges.size(), c.edges.size() == 1 ? "" : "s",
                       edges.c_str());
  } else if (hints) {
    ImGui::TextDisabled("Under the cursor");
    ImGui::TextWrapped("%s", scene.cells().empty()
                                 ? "this method has no cells: it tests the edges in turn"
                                 : "hover over a cell to see the edges it lists");
  }
  if (!probe) {
    if (hints) {
      ImGui::Spacing();
      ImGui::TextDisabled("Placed point");
      ImGui::TextWrapped("click in the scene to place a point and follow its query step by step");
    }
    return;
  }
  ImGui::Spacing();
  ImGui::TextColored(im(textColourOf(pal, probe->trace.result)), "Placed point: %s",
                     std::string(toString(probe->trace.result)).c_str());
  const auto lines =
      describeTrace(probe->trace, probe->point, scene.polygon(),
                    scene.method() == Method2D::Polar ? scene.effectiveResolution() : 0);
  traceLines(lines, pal, textColourOf(pal, probe->trace.result));
  if (ImGui::SmallButton("Clear (Esc)")) scene.clearProbe();
  ImGui::SameLine();
  if (ImGui::SmallButton("Copy coordinates")) ImGui::SetClipboardText(exact(probe->point).c_str());
}

// === Legend: what each colour and line means, with the counts

void legendContents(Model& model) {
  const Scene2D& scene = model.scene2d;
  const Palette& pal = paletteFor(model.settings.theme);
  const Stats2D& s = scene.stats();
  ImGui::Text("%s", std::string(toString(scene.method())).c_str());
  ImGui::SameLine();
  if (s.cells)
    ImGui::TextDisabled("%s edges, %s cells", grouped(s.edges).c_str(), grouped(s.cells).c_str());
  else
    ImGui::TextDisabled("%s edges", grouped(s.edges).c_str());
  classRows(model, scene.counts(), scene.points().size(), false);
  const Method2D m = scene.method();
  const std::size_t base = baseEdgesPerCell(m);
  if (s.cells && model.settings.view2d.showTints) {
    swatchBox(cellTint(pal, base + 1, base, false), withAlpha(pal.extraEdges, 0.8f));
    ImGui::Text("cell listing %zu+ edges", base + 1);
    if (s.crowdedCells) {
      swatchBox(cellTint(pal, 0, base, true), withAlpha(pal.crowded, 0.8f));
      ImGui::Text("crowded cell (bisection)");
    }
  }
  if (m == Method2D::Polar && scene.centre()) {
    if (model.settings.view2d.showOctants) {
      swatchLine(pal.octant, true, 1.6f);
      ImGui::Text("octant lines through x_T");
    }
    swatchLine(pal.structure, false, 1.0f);
    ImGui::Text("polar slab boundaries");
  }
  if (model.settings.view2d.showBox) {
    swatchLine(pal.box, true, 1.2f);
    ImGui::Text("bounding box");
  }
}

// the legend alone, over the scene's lower right corner (panels hidden)
void legendOverlay(Model& model, ScreenRect area) {
  ImGui::SetNextWindowPos(
      ImVec2(static_cast<float>(area.hi.x) - 10.0f, static_cast<float>(area.hi.y) - 10.0f),
      ImGuiCond_Always, ImVec2(1.0f, 1.0f));
  ImGui::SetNextWindowBgAlpha(0.82f);
  ImGui::Begin("Legend", nullptr,
               ImGuiWindowFlags_NoDecoration | ImGuiWindowFlags_AlwaysAutoResize |
                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoSavedSettings |
                   ImGuiWindowFlags_NoFocusOnAppearing | ImGuiWindowFlags_NoNav);
  if (model.dim == Dim::Two)
    legendContents(model);
  else
    legendContents3(model);
  ImGui::End();
}

// === Toast

void toast(Model& model, UiState& ui, ScreenRect area, double now) {
  if (model.errorSerial() != ui.toastSerial) {
    ui.toastSerial = model.errorSerial();
    ui.toast = model.error();
    ui.toastUntil = now + 9.0;
    if (!ui.toast.empty()) std::cerr << "convexloc-viewer: " << ui.toast << "\n";
  }
  const Palette& pal = paletteFor(model.settings.theme);
  float y = 10.0f;
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
    ImGui::TextWrapped("%s", text.c_str());
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

}  // namespace

float leftPanelWidth(const Model& model, glm::dvec2 window) {
  if (!model.settings.showUi) return 0.0f;
  return std::min(345.0f * model.settings.fontScale,
                  std::max(300.0f, static_cast<float>(0.32 * window.x)));
}

float rightPanelWidth(const Model& model, glm::dvec2 window) {
  // narrower windows keep the scene wide: legend and inspector float over it instead
  if (!model.settings.showUi || window.x < 1280.0) return 0.0f;
  return std::min(330.0f * model.settings.fontScale, static_cast<float>(0.26 * window.x));
}

ScreenRect sceneArea(const Model& model, glm::dvec2 window) {
  return {{static_cast<double>(leftPanelWidth(model, window)), 0.0},
          {window.x - static_cast<double>(rightPanelWidth(model, window)), window.y}};
}

void scanAssets(UiState& ui) {
  ui.assets.clear();
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(ui.assetDir, ec)) {
    const std::string ext = e.path().extension().string();
    const std::string name = e.path().filename().string();
    if ((ext == ".txt" || ext == ".off" || ext == ".obj") &&
        name.find("points") == std::string::npos)
      ui.assets.push_back(e.path().string());
  }
  std::sort(ui.assets.begin(), ui.assets.end());
}

void handleKeys(Model& model, UiState& ui) {
  if (ImGui::IsKeyPressed(GLFW_KEY_F12, false)) ui.screenshotRequested = true;
  if (ImGui::GetIO().WantCaptureKeyboard) return;
  if (ImGui::IsKeyPressed(GLFW_KEY_F, false)) model.requestFit();
  if (ImGui::IsKeyPressed(GLFW_KEY_H, false)) {
    model.settings.showUi = !model.settings.showUi;
    model.requestFit();  // the scene's area changed
  }
  if (ImGui::IsKeyPressed(GLFW_KEY_T, false))
    model.settings.theme = model.settings.theme == Theme::Dark ? Theme::Light : Theme::Dark;
  const bool space = ImGui::IsKeyPressed(GLFW_KEY_SPACE, false);
  if (space) ++ui.spraySeed;
  const SpraySettings spray{static_cast<std::size_t>(ui.sprayCount), ui.spraySeed, ui.sprayNear};
  if (model.dim == Dim::Two) {
    Scene2D& scene = model.scene2d;
    if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) scene.clearProbe();
    if (space) scene.spray(spray);
    for (int k = 0; k < 5; ++k)
      if (ImGui::IsKeyPressed(GLFW_KEY_1 + k, false)) scene.setMethod(kAllMethods2D[k]);
  } else {
    Scene3D& scene = model.scene3d();
    if (ImGui::IsKeyPressed(GLFW_KEY_ESCAPE, false)) {
      scene.clearProbe();
      scene.pin(-1);
    }
    if (space) scene.spray(spray);
    for (int k = 0; k < 3; ++k)
      if (ImGui::IsKeyPressed(GLFW_KEY_1 + k, false)) scene.setMethod(kAllMethods3D[k]);
  }
}

void drawUi(Model& model, Renderer& renderer, const SceneView& view, UiState& ui, double now) {
  (void)view;
  const ImGuiIO& io = ImGui::GetIO();
  const glm::dvec2 window{io.DisplaySize.x, io.DisplaySize.y};
  const ScreenRect area = sceneArea(model, window);

  if (model.settings.showUi) {
    const float w = leftPanelWidth(model, window);
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(w, io.DisplaySize.y));
    ImGui::Begin("convexloc", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoBringToFrontOnFocus);
    ImGui::Text("convexloc-viewer");
    ImGui::SameLine();
    ImGui::TextDisabled("point in convex %s", model.dim == Dim::Two ? "polygon" : "polyhedron");
    const float half = 0.5f * (ImGui::GetContentRegionAvail().x - ImGui::GetStyle().ItemSpacing.x);
    for (Dim d : {Dim::Two, Dim::Three}) {
      const bool on = model.dim == d;
      if (d == Dim::Three) ImGui::SameLine();
      if (on)
        ImGui::PushStyleColor(ImGuiCol_Button, ImGui::GetStyleColorVec4(ImGuiCol_ButtonActive));
      if (ImGui::Button(d == Dim::Two ? "2D: polygon" : "3D: polyhedron", ImVec2(half, 0.0f)))
        model.show(d);
      if (on) ImGui::PopStyleColor();
    }
    ImGui::Separator();
    if (model.dim == Dim::Two) {
      if (ImGui::CollapsingHeader("Shape", ImGuiTreeNodeFlags_DefaultOpen)) shapePanel(model, ui);
      if (ImGui::CollapsingHeader("Method", ImGuiTreeNodeFlags_DefaultOpen)) methodPanel(model, ui);
      if (ImGui::CollapsingHeader("Points", ImGuiTreeNodeFlags_DefaultOpen))
        pointsPanel(model, ui, model.scene2d);
    } else {
      if (ImGui::CollapsingHeader("Shape", ImGuiTreeNodeFlags_DefaultOpen)) shapePanel3(model, ui);
      if (ImGui::CollapsingHeader("Method", ImGuiTreeNodeFlags_DefaultOpen))
        methodPanel3(model, ui);
      if (ImGui::CollapsingHeader("Slicing plane", ImGuiTreeNodeFlags_DefaultOpen))
        slicePanel3(model);
      if (ImGui::CollapsingHeader("Points")) pointsPanel(model, ui, model.scene3d());
    }
    if (ImGui::CollapsingHeader("View")) viewPanel(model, renderer, ui);
    ImGui::Spacing();
    if (model.dim == Dim::Two) {
      ImGui::TextDisabled("drag: pan, wheel: zoom, click: place a point");
      ImGui::TextDisabled("F fit, H hide panels, 1-5 method, Space spray");
    } else {
      ImGui::TextDisabled("drag: orbit, right drag: pan, wheel: zoom");
      ImGui::TextDisabled("click the plane: place a point; Shift-click: pin a cell");
      ImGui::TextDisabled("F fit, H hide panels, 1-3 method, Space spray");
    }
    ImGui::End();
  }
  const float rw = rightPanelWidth(model, window);
  if (rw > 0.0f) {
    ImGui::SetNextWindowPos(ImVec2(io.DisplaySize.x - rw, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(rw, io.DisplaySize.y));
    ImGui::Begin("What you see", nullptr,
                 ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                     ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoSavedSettings |
                     ImGuiWindowFlags_NoBringToFrontOnFocus);
    if (model.dim == Dim::Two)
      legendContents(model);
    else
      legendContents3(model);
    ImGui::Separator();
    if (model.dim == Dim::Two)
      inspectorContents(model, true);
    else
      inspectorContents3(model, true);
    ImGui::End();
  } else {
    legendOverlay(model, area);
    const bool something =
        model.dim == Dim::Two
            ? model.scene2d.hoveredCell() >= 0 || model.scene2d.probe().has_value()
            : model.scene3d().hoveredCell() >= 0 || model.scene3d().pinnedCell() >= 0 ||
                  model.scene3d().probe().has_value();
    if (model.settings.showUi && something) {
      const float iw =
          std::min(360.0f * model.settings.fontScale, static_cast<float>(area.size().x) * 0.6f);
      ImGui::SetNextWindowPos(ImVec2(static_cast<float>(area.hi.x) - iw - 8.0f, 8.0f));
      ImGui::SetNextWindowSizeConstraints(ImVec2(iw, 0.0f), ImVec2(iw, io.DisplaySize.y * 0.6f));
      ImGui::SetNextWindowBgAlpha(0.9f);
      ImGui::Begin("Inspector", nullptr,
                   ImGuiWindowFlags_NoMove | ImGuiWindowFlags_NoResize |
                       ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings |
                       ImGuiWindowFlags_NoCollapse | ImGuiWindowFlags_NoFocusOnAppearing);
      if (model.dim == Dim::Two)
        inspectorContents(model, false);
      else
        inspectorContents3(model, false);
      ImGui::End();
    }
  }
  toast(model, ui, area, now);
}

void drawLabels(Model& model, const SceneView& view) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const Camera2D& cam = model.camera2d;
  const Camera3D& cam3 = model.camera3d;
  const glm::dvec2 vp = cam.viewport();
  const Palette& pal = paletteFor(model.settings.theme);
  const ImU32 shadow = packAbgr(withAlpha(pal.background, 0.85f));
  int budget = 400;
  for (const DrawList* list : {&view.structure(), &view.overlay()})
    for (const Label& l : list->labels) {
      if (--budget < 0) return;
      glm::dvec2 s;
      if (model.dim == Dim::Two) {
        s = cam.toScreen({l.p.x, l.p.y}) + glm::dvec2(l.offset);
      } else {
        const Projected pr = cam3.toScreen(l.p);
        if (!pr.visible()) continue;
        s = pr.screen + glm::dvec2(l.offset);
      }
      if (s.x < -200.0 || s.y < -50.0 || s.x > vp.x + 200.0 || s.y > vp.y + 50.0) continue;
      const ImVec2 size = ImGui::CalcTextSize(l.text.c_str());
      const ImVec2 at(std::round(static_cast<float>(s.x) - 0.5f * size.x),
                      std::round(static_cast<float>(s.y) - 0.5f * size.y));
      for (const ImVec2 d : {ImVec2(-1, 0), ImVec2(1, 0), ImVec2(0, -1), ImVec2(0, 1)})
        dl->AddText(ImVec2(at.x + d.x, at.y + d.y), shadow, l.text.c_str());
      dl->AddText(at, packAbgr(l.colour), l.text.c_str());
    }
}

}  // namespace convexloc::viewer
