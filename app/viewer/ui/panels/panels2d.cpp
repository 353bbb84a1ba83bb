// convexloc-viewer — the 2D panels.
#include "ui/panels/panels2d.hpp"

#include <algorithm>
#include <string>

#include <imgui.h>

#include "logic/dual/lines2d.hpp"
#include "ui/panels/method_panels.hpp"
#include "ui/panels/typed_coords.hpp"
#include "ui/panels/views_panel.hpp"
#include "ui/widgets.hpp"

namespace convexloc::viewer {
namespace {

constexpr GeneratorText kGenerator2D = {"##kind", "Generate", "N", 1, 16, 3, "seed", "next"};
constexpr MethodPanelText kMethodText2D = {"stats", "##hist", "edges", "Compare all methods",
                                           "compare"};
constexpr SliderText kUniformSlider = {"auto", "##res", 1 << 20, "%d slabs"};
constexpr SliderText kPolarSlider = {"auto", "##res", 1 << 16, "%d per octant"};

// the statistics of the 2D locator
std::vector<StatLine> statLines(const Scene2D& scene) {
  const Stats2D& s = scene.stats();
  std::vector<StatLine> rows = {{"edges", grouped(s.edges)}};
  if (s.cells) {
    rows.push_back({"cells", grouped(s.cells)});
    rows.push_back({"edges per cell",
                    "max " + std::to_string(s.maxPerCell) + ", mean " + approx(s.meanPerCell, 3)});
    if (s.crowdedCells) rows.push_back({"crowded cells", grouped(s.crowdedCells) + " (bisection)"});
  }
  if (scene.cellsOmitted()) rows.push_back({"drawing", "too many cells to draw"});
  rows.push_back({"memory", binarySize(s.bytes) + " (" + approx(s.bytesPerEdge, 3) + " B/edge)"});
  rows.push_back({"build", approx(s.buildSeconds * 1e3, 3) + " ms"});
  if (!scene.points().empty())
    rows.push_back({"locate", nsText(scene.locateNsPerPoint()) + " ns/point"});
  return rows;
}

// the cell under the cursor: its index, octant or y range, the edges it lists
void hoveredCellText(const Scene2D& scene, const Cell2D& c) {
  std::string what = "cell " + std::to_string(c.index);
  if (c.octant >= 0) what += ", octant " + std::to_string(c.octant);
  if (scene.method() == Method2D::Slab || scene.method() == Method2D::Uniform)
    what += ", y in [" + approx(c.y0, 6) + ", " + approx(c.y1, 6) + ")";
  textAtSpaces(what);
  std::string edges;
  for (std::size_t i = 0; i < c.edges.size() && i < 24; ++i)
    edges += (i ? ", " : "") + std::to_string(c.edges[i]);
  if (c.edges.size() > 24) edges += ", ...";
  textAtSpaces("lists " + std::to_string(c.edges.size()) +
               (c.edges.size() == 1 ? " edge: " : " edges: ") + edges);
}

void shapePanel2D(Model& model, UiState& ui) {
  Scene2D& scene = model.scene2d;
  const ConvexPolygon& poly = scene.polygon();
  textAtSpaces(scene.label());
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
  fileOpen(model, ui, "polygon .txt, polyhedron .off/.obj/.stl/.ply");
  generatorsAndGallery<Scene2D, PolygonKind>(model, scene, kAllPolygonKinds, ui.generator2d,
                                             kGenerator2D, false);
  ImGui::TextDisabled("Drag a vertex handle to edit the polygon.");
}

// the Lines mode's switch: the dual problem, line against polygon
void linesSwitch(Model& model) {
  if (const auto on =
          modeSwitch("Lines: the dual problem (L)", model.lines2d.enabled(),
                     "Drag in the scene to place a line; core's dual method answers it, and the\n"
                     "dual polygon P* with its polar slabs shows beside the polygon"))
    model.setLinesMode(*on);
}

void methodPanel2D(Model& model, UiState& ui) {
  Scene2D& scene = model.scene2d;
  linesSwitch(model);
  if (model.lines2d.enabled()) {
    if (const LineIntersector* li = model.lines2d.intersector()) {
      const LineStats s = li->stats();
      const std::string text = "the dual P*: " + grouped(s.dualVertices) + " vertices, " +
                               grouped(s.cells) + " polar cells, at most " +
                               std::to_string(s.maxPerCell) + " edges per cell";
      ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
      textAtSpaces(text);
      ImGui::PopStyleColor();
    }
    return;
  }
  methodChoice(scene);
  paperModeCheckbox(model, scene.method() == Method2D::Polar);
  if (scene.method() == Method2D::Uniform) resolutionSlider(scene, kUniformSlider);
  if (scene.method() == Method2D::Polar) resolutionSlider(scene, kPolarSlider);
  // the row is kept for every method, so that the buttons below never move
  if (scene.method() != Method2D::Uniform && scene.method() != Method2D::Polar) noResolutionRow();
  methodDetails(model, scene, statLines(scene), ui.compare2d, kMethodText2D);
  // the teaching views: split, build, Why O(1)
  splitControls(model);
  buildControls(model);
  whyButton(model);
}

void viewOptions2D(Model& model) {
  View2DOptions& o = model.settings.view2d;
  toggleGrid(
      "structure|tinted cells|bounding box|octant lines|labels|vertex handles",
      {&o.showStructure, &o.showTints, &o.showBox, &o.showOctants, &o.showLabels, &o.showHandles});
}

void pointsPanel2D(Model& model, UiState& ui) {
  pointsPanel(model, ui, model.scene2d);
}

bool inspectable2D(Model& model) {
  if (model.lines2d.enabled()) return model.lines2d.line().has_value();
  return model.scene2d.hoveredCell() >= 0 || model.scene2d.probe().has_value();
}

constexpr const char* kHints2D[] = {"drag: pan, wheel: zoom, click: place a point",
                                    "points snap to vertices, edges, x_T, a grid; Alt: free",
                                    "F fit, H hide panels, 1-5 method, Space spray",
                                    "L lines mode: drag to place a line", nullptr};

void legend2D(Model& model) {
  drawLegend(legendOf(model));
}

// the line's answer and the steps core took
void lineInspector(Model& model, bool hints) {
  const Lines2D& lines = model.lines2d;
  const Palette& pal = paletteFor(model.settings.theme);
  const auto& line = lines.line();
  if (!line) {
    if (hints) {
      ImGui::TextDisabled("Line");
      ImGui::TextWrapped("drag in the scene: press at one point, release at another");
    }
    return;
  }
  const Rgba colour = line->hit.crossing == Crossing::Crosses   ? pal.inside
                      : line->hit.crossing == Crossing::Touches ? pal.boundary
                                                                : pal.outside;
  ImGui::TextColored(im(readableOn(colour, pal.background, pal.text)), "Line: %s",
                     std::string(toString(line->hit.crossing)).c_str());
  traceLines(describeLine(*line, lines.dualVertices(), lines.intersector()->dualLocator()), pal,
             colour);
  if (ImGui::SmallButton("Clear (Esc)")) model.lines2d.clearLine();
}

void inspector2D(Model& model, bool hints) {
  if (model.lines2d.enabled()) return lineInspector(model, hints);
  Scene2D& scene = model.scene2d;
  const Palette& pal = paletteFor(model.settings.theme);
  if (scene.hoveredCell() >= 0) {
    ImGui::TextColored(im(pal.hoverEdge), "Under the cursor");
    hoveredCellText(scene, scene.cells()[static_cast<std::size_t>(scene.hoveredCell())]);
  } else if (hints) {
    ImGui::TextDisabled("Under the cursor");
    ImGui::TextWrapped("%s", scene.cells().empty()
                                 ? "this method has no cells: it tests the edges in turn"
                                 : "hover over a cell to see the edges it lists");
  }
  placedPoint(
      scene, pal, hints, "click in the scene to place a point and follow its query step by step",
      [&](const Probe& probe) { return describeTrace(probe.trace, probe.point, scene.polygon()); });
  splitInspector(model);  // the split view's right half
}

// the 2D scene's panels, in the window's order
constexpr ScenePanels kPanels2D = {shapePanel2D,  methodPanel2D, "Coordinates", typedCoordinates2D,
                                   pointsPanel2D, true,          viewOptions2D, legend2D,
                                   inspector2D,   inspectable2D, kHints2D};

}  // namespace

const ScenePanels& panels2D() {
  return kPanels2D;
}

}  // namespace convexloc::viewer
