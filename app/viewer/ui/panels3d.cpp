// convexloc-viewer — the 3D panels: polyhedron, method (the cube map), slicing plane, view
// options, legend and inspector.
#include <algorithm>
#include <cfloat>
#include <string>

#include <imgui.h>

#include "logic/text.hpp"
#include "ui/widgets.hpp"

namespace convexloc::viewer {
namespace {

const char* complexityOf(Method3D m) {
  switch (m) {
    case Method3D::Halfspace: return "O(F)";
    case Method3D::Walk: return "O(sqrt F) expected";
    case Method3D::Cubemap: return "O(1), the paper's";
  }
  return "";
}

const char* kCubeFaces[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};

// "12, 13, 40" (at most `most`)
std::string listOf(const std::vector<std::uint32_t>& v, std::size_t most) {
  std::string out;
  for (std::size_t i = 0; i < v.size() && i < most; ++i) {
    if (i) out += ", ";
    out += std::to_string(v[i]);
  }
  if (v.size() > most) out += ", ...";
  return out;
}

// what a cell is and lists
void cellText(const Cell3D& c) {
  std::string what = "cell " + std::to_string(c.index) + " on cube face " + kCubeFaces[c.cubeFace] +
                     ", (" + std::to_string(c.i) + ", " + std::to_string(c.j) + ")";
  if (c.level > 0) what += ", quadtree level " + std::to_string(c.level);
  ImGui::TextWrapped("%s", what.c_str());
  ImGui::TextWrapped("lists %zu face%s: %s", c.faces.size(), c.faces.size() == 1 ? "" : "s",
                     listOf(c.faces, 24).c_str());
}

}  // namespace

void shapePanel3(Model& model, UiState& ui) {
  Scene3D& scene = model.scene3d();
  const ConvexPolyhedron& p = scene.polyhedron();
  ImGui::TextWrapped("%s", scene.label().c_str());
  ImGui::TextDisabled("%s triangles, %s vertices", grouped(p.faceCount()).c_str(),
                      grouped(p.vertexCount()).c_str());
  std::string notes;
  if (p.inputFaces() != p.faceCount()) notes += grouped(p.inputFaces()) + " input faces; ";
  if (p.mergedVertices()) notes += grouped(p.mergedVertices()) + " vertices merged; ";
  if (p.flippedSlivers()) notes += grouped(p.flippedSlivers()) + " slivers flipped; ";
  if (p.wasInverted()) notes += "given inside out; ";
  if (!notes.empty()) ImGui::TextDisabled("(%s)", notes.substr(0, notes.size() - 2).c_str());

  fileOpen(model, ui, "polyhedron .off/.obj, polygon .txt");

  ImGui::Spacing();
  const int kinds = static_cast<int>(std::size(kAllPolyhedronKinds));
  ui.generator3Kind = std::clamp(ui.generator3Kind, 0, kinds - 1);
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
  if (ImGui::BeginCombo("##kind3",
                        std::string(toString(kAllPolyhedronKinds[ui.generator3Kind])).c_str())) {
    for (int k = 0; k < kinds; ++k)
      if (ImGui::Selectable(std::string(toString(kAllPolyhedronKinds[k])).c_str(),
                            k == ui.generator3Kind))
        ui.generator3Kind = k;
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  auto generate = [&] {
    if (scene.generate(kAllPolyhedronKinds[ui.generator3Kind],
                       static_cast<std::size_t>(ui.generator3N), ui.generator3Seed))
      model.requestFit();
  };
  if (ImGui::Button("Generate##3", ImVec2(-1.0f, 0.0f))) generate();
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
  ImGui::InputInt("faces (about)", &ui.generator3N, 16, 256);
  ui.generator3N = std::clamp(ui.generator3N, 4, 1 << 22);
  ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x * 0.5f);
  ImGui::InputScalar("seed##3", ImGuiDataType_U64, &ui.generator3Seed);
  ImGui::SameLine();
  if (ImGui::SmallButton("next##3")) {
    ++ui.generator3Seed;
    generate();
  }
  ImGui::Spacing();
  ImGui::TextDisabled("Degenerate gallery");
  gallery(model, true);
}

void methodPanel3(Model& model, UiState& ui) {
  Scene3D& scene = model.scene3d();
  for (Method3D m : kAllMethods3D) {
    if (ImGui::RadioButton(std::string(toString(m)).c_str(), scene.method() == m))
      scene.setMethod(m);
    ImGui::SameLine(ImGui::GetFontSize() * 7.0f);
    ImGui::TextDisabled("%s", complexityOf(m));
  }
  if (scene.method() == Method3D::Cubemap) {
    bool automatic = scene.resolution() == 0;
    int g = static_cast<int>(scene.effectiveResolution());
    if (ImGui::Checkbox("auto##g", &automatic))
      scene.setResolution(automatic ? 0 : static_cast<std::uint32_t>(g));
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::SliderInt("##g", &g, 1, 256, "G = %d",
                         ImGuiSliderFlags_Logarithmic | ImGuiSliderFlags_AlwaysClamp))
      scene.setResolution(static_cast<std::uint32_t>(std::max(g, 1)));
  }
  const Stats3D& s = scene.stats();
  if (ImGui::BeginTable("stats3", 2, ImGuiTableFlags_SizingStretchProp)) {
    statRow("faces", grouped(s.faces) + " (" + grouped(s.vertices) + " vertices)");
    if (s.cells) {
      statRow("cells",
              grouped(s.cells) + (s.nodes > s.cells ? " (" + grouped(s.nodes) + " nodes)" : ""));
      statRow("grid",
              "G = " + std::to_string(s.resolution) +
                  (s.maxLevel > 0 ? ", quadtree to level " + std::to_string(s.maxLevel) : ""));
      statRow("faces per cell",
              "max " + std::to_string(s.maxPerCell) + ", mean " + approx(s.meanPerCell, 3));
      if (s.crowdedCells) statRow("crowded cells", grouped(s.crowdedCells) + " (walk)");
    }
    if (!s.centred && scene.method() != Method3D::Halfspace)
      statRow("centre", "none: every face is tested");
    if (scene.cellsOmitted()) statRow("drawing", "too many cells to draw");
    statRow("memory", bytesText(s.bytes) + " (" + approx(s.bytesPerFace, 3) + " B/face)");
    statRow("build", approx(s.buildSeconds * 1e3, 3) + " ms");
    ImGui::EndTable();
  }
  if (!s.histogram.empty() && s.cells) {
    std::vector<float> h(s.histogram.begin(), s.histogram.end());
    ImGui::TextDisabled("cells by faces listed: 0, 1, ..., %zu+", h.size() - 1);
    ImGui::PlotHistogram("##hist3", h.data(), static_cast<int>(h.size()), 0, nullptr, 0.0f, FLT_MAX,
                         ImVec2(ImGui::GetContentRegionAvail().x, ImGui::GetFontSize() * 4.0f));
    if (ImGui::IsItemHovered()) {
      ImGui::BeginTooltip();
      for (std::size_t k = 0; k < s.histogram.size(); ++k)
        if (s.histogram[k])
          ImGui::Text("%s%zu faces: %s cells", k + 1 == s.histogram.size() ? ">= " : "", k,
                      grouped(s.histogram[k]).c_str());
      ImGui::EndTooltip();
    }
  }
  if (ImGui::Button("Compare all methods##3", ImVec2(-1.0f, 0.0f))) ui.compare3 = scene.compare();
  help(
      "Times every method's batch locate on the current spray (at most ~0.1 s each) and checks "
      "that all answer the same.");
  if (!ui.compare3.empty() &&
      ImGui::BeginTable("compare3", 4, ImGuiTableFlags_RowBg | ImGuiTableFlags_SizingStretchProp)) {
    ImGui::TableSetupColumn("method");
    ImGui::TableSetupColumn("ns/pt");
    ImGui::TableSetupColumn("build");
    ImGui::TableSetupColumn("agree");
    ImGui::TableHeadersRow();
    double best = 1e300;
    for (const CompareRow3D& r : ui.compare3)
      if (r.points) best = std::min(best, r.nsPerPoint);
    const Palette& pal = paletteFor(model.settings.theme);
    for (const CompareRow3D& r : ui.compare3) {
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

void slicePanel3(Model& model) {
  Scene3D& scene = model.scene3d();
  SlicePlane s = scene.slice();
  bool changed = false;
  for (int a = 0; a < 3; ++a) {
    if (a) ImGui::SameLine();
    const char* names[3] = {"x =", "y =", "z ="};
    if (ImGui::RadioButton(names[a], s.axis == a)) {
      s.axis = a;
      s.offset = scene.bounds().middle()[a];
      changed = true;
    }
  }
  const Bounds3 b = scene.bounds();
  const double margin = 0.15 * (b.hi[s.axis] - b.lo[s.axis]);
  double lo = b.lo[s.axis] - margin, hi = b.hi[s.axis] + margin;
  ImGui::SetNextItemWidth(-1.0f);
  if (ImGui::SliderScalar("##offset", ImGuiDataType_Double, &s.offset, &lo, &hi, "%.6g"))
    changed = true;
  if (changed) scene.setSlice(s);
  ImGui::Checkbox("show the plane and its section", &model.settings.view3d.showSlice);
  ImGui::TextDisabled("click on the plane to place a point");
}

void viewOptions3(Model& model) {
  View3DOptions& o = model.settings.view3d;
  const float mid = ImGui::GetContentRegionAvail().x * 0.5f;
  ImGui::Checkbox("faces", &o.showMesh);
  ImGui::SameLine(mid);
  ImGui::Checkbox("see-through", &o.transparent);
  ImGui::Checkbox("wireframe", &o.wireframe);
  ImGui::SameLine(mid);
  ImGui::Checkbox("cube grid", &o.showCube);
  ImGui::Checkbox("tinted cells", &o.showTints);
  ImGui::SameLine(mid);
  ImGui::Checkbox("labels", &o.showLabels);
}

void legendContents3(Model& model) {
  Scene3D& scene = model.scene3d();
  const Palette& pal = paletteFor(model.settings.theme);
  const Stats3D& s = scene.stats();
  ImGui::Text("%s", std::string(toString(scene.method())).c_str());
  ImGui::SameLine();
  if (s.cells)
    ImGui::TextDisabled("%s faces, %s cells", grouped(s.faces).c_str(), grouped(s.cells).c_str());
  else
    ImGui::TextDisabled("%s faces", grouped(s.faces).c_str());
  classRows(model, scene.counts(), scene.points().size(), false);
  if (s.cells && model.settings.view3d.showCube && model.settings.view3d.showTints) {
    swatchBox(cellTint(pal, 2, kBaseFacesPerCell, false), withAlpha(pal.extraEdges, 0.8f));
    ImGui::Text("cell listing 2+ faces");
    if (s.crowdedCells) {
      swatchBox(cellTint(pal, 0, kBaseFacesPerCell, true), withAlpha(pal.crowded, 0.8f));
      ImGui::Text("crowded cell (walk)");
    }
  }
  if (s.cells && model.settings.view3d.showCube) {
    swatchLine(pal.cube, false, 1.0f);
    ImGui::Text("cube-map grid around x_T");
  }
  if (model.settings.view3d.showSlice) {
    swatchBox(withAlpha(pal.inside, 0.45f), withAlpha(pal.inside, 0.8f));
    ImGui::Text("section: inside, per core");
  }
}

void inspectorContents3(Model& model, bool hints) {
  Scene3D& scene = model.scene3d();
  const Palette& pal = paletteFor(model.settings.theme);
  const auto& cells = scene.cells();
  if (scene.hoveredCell() >= 0) {
    ImGui::TextColored(im(pal.hoverEdge), "Under the cursor");
    cellText(cells[static_cast<std::size_t>(scene.hoveredCell())]);
  } else if (hints) {
    ImGui::TextDisabled("Under the cursor");
    ImGui::TextWrapped("%s", cells.empty()
                                 ? "this method has no cells"
                                 : "hover over the cube to see a cell's pyramid and its faces");
  }
  if (scene.pinnedCell() >= 0) {
    ImGui::Spacing();
    ImGui::TextColored(im(pal.crowded), "Pinned cell");
    cellText(cells[static_cast<std::size_t>(scene.pinnedCell())]);
    if (ImGui::SmallButton("Unpin")) scene.pin(-1);
  }
  const auto& probe = scene.probe();
  if (!probe) {
    if (hints) {
      ImGui::Spacing();
      ImGui::TextDisabled("Placed point");
      ImGui::TextWrapped("click on the slicing plane to place a point and follow its query");
    }
    return;
  }
  ImGui::Spacing();
  ImGui::TextColored(im(textColourOf(pal, probe->trace.result)), "Placed point: %s",
                     std::string(toString(probe->trace.result)).c_str());
  traceLines(describeTrace3D(probe->trace, probe->point), pal,
             textColourOf(pal, probe->trace.result));
  if (ImGui::SmallButton("Clear (Esc)")) scene.clearProbe();
  ImGui::SameLine();
  if (ImGui::SmallButton("Copy coordinates")) ImGui::SetClipboardText(exact(probe->point).c_str());
}

}  // namespace convexloc::viewer
