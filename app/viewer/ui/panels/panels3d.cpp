// convexloc-viewer — the 3D panels.
#include "ui/panels/panels3d.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include <imgui.h>

#include "logic/dual/dual_view3d.hpp"
#include "logic/view/snap.hpp"
#include "ui/panels/method_panels.hpp"
#include "ui/panels/typed_coords.hpp"
#include "ui/panels/views_panel.hpp"
#include "ui/widgets.hpp"

namespace convexloc::viewer {
namespace {

constexpr GeneratorText kGenerator3D = {"##kind3", "Generate##3", "faces (about)", 16, 256,
                                        4,         "seed##3",     "next##3"};
constexpr MethodPanelText kMethodText3D = {"stats3", "##hist3", "faces", "Compare all methods##3",
                                           "compare3"};
constexpr SliderText kGridSlider = {"auto##g", "##g", 256, "G = %d"};

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
  std::string what = "cell " + std::to_string(c.index) + " on cube face " +
                     std::string(kCubeFaceNames[static_cast<std::size_t>(c.cubeFace)]) + ", (" +
                     std::to_string(c.i) + ", " + std::to_string(c.j) + ")";
  if (c.level > 0) what += ", quadtree level " + std::to_string(c.level);
  textAtSpaces(what);
  textAtSpaces("lists " + std::to_string(c.faces.size()) +
               (c.faces.size() == 1 ? " face: " : " faces: ") + listOf(c.faces, 24));
}

// the statistics of the 3D locator
std::vector<StatLine> statLines(const Scene3D& scene) {
  const Stats3D& s = scene.stats();
  std::vector<StatLine> rows = {{"faces", grouped(s.faces) + " (" + grouped(s.triangles) +
                                              " triangles, " + grouped(s.vertices) + " vertices)"}};
  if (s.cells) {
    rows.push_back({"cells", grouped(s.cells) +
                                 (s.nodes > s.cells ? " (" + grouped(s.nodes) + " nodes)" : "")});
    rows.push_back(
        {"grid", "G = " + std::to_string(s.resolution) +
                     (s.maxLevel > 0 ? ", quadtree to level " + std::to_string(s.maxLevel) : "")});
    rows.push_back({"faces per cell",
                    "max " + std::to_string(s.maxPerCell) + ", mean " + approx(s.meanPerCell, 3)});
    if (s.crowdedCells) rows.push_back({"crowded cells", grouped(s.crowdedCells) + " (walk)"});
  }
  if (!s.centred && scene.method() != Method3D::Halfspace)
    rows.push_back({"centre", "none: every face is tested"});
  if (scene.cellsOmitted()) rows.push_back({"drawing", "too many cells to draw"});
  rows.push_back({"memory", binarySize(s.bytes) + " (" + approx(s.bytesPerFace, 3) + " B/face)"});
  rows.push_back({"build", approx(s.buildSeconds * 1e3, 3) + " ms"});
  return rows;
}

void shapePanel3D(Model& model, UiState& ui) {
  Scene3D& scene = model.scene3d();
  const ConvexPolyhedron& p = scene.polyhedron();
  textAtSpaces(scene.label());
  ImGui::TextDisabled("%s faces (%s triangles), %s vertices", grouped(p.planeCount()).c_str(),
                      grouped(p.faceCount()).c_str(), grouped(p.vertexCount()).c_str());
  std::string notes;
  if (p.inputFaces() != p.faceCount()) notes += grouped(p.inputFaces()) + " input faces; ";
  if (p.mergedVertices()) notes += grouped(p.mergedVertices()) + " vertices merged; ";
  if (p.flippedSlivers()) notes += grouped(p.flippedSlivers()) + " slivers flipped; ";
  if (p.wasInverted()) notes += "given inside out; ";
  if (!notes.empty()) ImGui::TextDisabled("(%s)", notes.substr(0, notes.size() - 2).c_str());

  fileOpen(model, ui, "polyhedron .off/.obj/.stl/.ply, polygon .txt");

  generatorsAndGallery<Scene3D, PolyhedronKind>(model, scene, kAllPolyhedronKinds, ui.generator3d,
                                                kGenerator3D, true);
}

// === The Planes mode (the dual problem in 3D)

constexpr double kDegree = 3.14159265358979323846 / 180.0;

// a slider in degrees over an angle kept in radians; true when moved
bool angleSlider(const char* id, const char* format, double& radians, double lo, double hi) {
  double degrees = radians / kDegree;
  ImGui::SetNextItemWidth(-1.0f);
  if (!ImGui::SliderScalar(id, ImGuiDataType_Double, &degrees, &lo, &hi, format)) return false;
  radians = degrees * kDegree;
  return true;
}

// the plane's sliders, the method and the dual's size
void planesControls(Model& model) {
  Planes3D& planes = model.planes3d;
  PlaneSliders s = planes.sliders();
  bool moved = false;
  const double reach = planes.offsetReach(), lo = -reach, hi = reach;
  ImGui::SetNextItemWidth(-1.0f);
  moved |= ImGui::SliderScalar("##planeOffset", ImGuiDataType_Double, &s.offset, &lo, &hi,
                               "offset %.4g");
  moved |= angleSlider("##planeAzimuth", "azimuth %.1f deg", s.azimuth, -180.0, 180.0);
  moved |= angleSlider("##planeElevation", "elevation %.1f deg", s.elevation, -90.0, 90.0);
  // typed, or stepped exactly on a grid of about a twentieth of the reach
  moved |= steppedField("##planeOffsetTyped", s.offset, niceGridStep(reach / 20.0));
  if (ImGui::SmallButton("Through the centre")) {
    s.offset = 0.0;
    moved = true;
  }
  if (moved) planes.setSliders(s);
  typedPlane3D(model);
  ImGui::TextDisabled("method:");
  for (const PlaneMethod m : kAllPlaneMethods) {
    ImGui::SameLine();
    const std::string name = std::string(toString(m)) + " " + std::string(costOf(m));
    if (ImGui::RadioButton(name.c_str(), planes.method() == m)) planes.setMethod(m);
  }
  if (const PlaneIntersector* pi = planes.dualIntersector()) {
    const PlaneStats st = pi->stats();
    const std::string text = "the dual P*: " + grouped(st.dualVertices) + " vertices, " +
                             grouped(st.dualFaces) + " faces, " + grouped(st.cells) +
                             " cube-map cells";
    ImGui::PushStyleColor(ImGuiCol_Text, ImGui::GetStyle().Colors[ImGuiCol_TextDisabled]);
    textAtSpaces(text);
    ImGui::PopStyleColor();
  }
}

// the Planes mode's switch, and its controls when on; true when on
bool planesPanel(Model& model) {
  if (const auto on = modeSwitch(
          "Planes: the dual problem (L)", model.planes3d.enabled(),
          "Place a plane with the sliders; core's dual method (the cube map of the dual\n"
          "polyhedron) and the O(V) baseline answer it, the dual view shows beside"))
    model.setPlanesMode(*on);
  if (!model.planes3d.enabled()) return false;
  planesControls(model);
  return true;
}

void methodPanel3D(Model& model, UiState& ui) {
  Scene3D& scene = model.scene3d();
  if (planesPanel(model)) return;
  methodChoice(scene);
  paperModeCheckbox(model, scene.method() == Method3D::Cubemap);
  if (scene.method() == Method3D::Cubemap) resolutionSlider(scene, kGridSlider);
  // the row is kept for every method, so that the buttons below never move
  if (scene.method() != Method3D::Cubemap) noResolutionRow();
  methodDetails(model, scene, statLines(scene), ui.compare3d, kMethodText3D);
  buildControls(model);  // the build animation
  whyButton(model);      // Why O(1): the cost against F
}

void slicePanel3D(Model& model) {
  if (model.planes3d.enabled()) {
    ImGui::TextDisabled("hidden in the Planes mode");
    return;
  }
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
  typedSliceOffset(model);
  ImGui::Checkbox("show the plane and its section", &model.settings.view3d.showSlice);
  ImGui::TextDisabled("click on the plane to place a point");
}

void pointsPanel3D(Model& model, UiState& ui) {
  pointsPanel(model, ui, model.scene3d());
}

void viewOptions3D(Model& model) {
  View3DOptions& o = model.settings.view3d;
  toggleGrid("faces|see-through|wireframe|cube grid|tinted cells|labels",
             {&o.showMesh, &o.transparent, &o.wireframe, &o.showCube, &o.showTints, &o.showLabels});
}

bool inspectable3D(Model& model) {
  if (model.planes3d.enabled()) return model.planes3d.plane().has_value();
  const Scene3D& s = model.scene3d();
  return s.hoveredCell() >= 0 || s.pinnedCell() >= 0 || s.secondPinnedCell() >= 0 ||
         s.probe().has_value();
}

constexpr const char* kHints3D[] = {
    "drag: orbit, right drag: pan, wheel: zoom",
    "click the slicing plane: place a point; Shift-click: pin a cell",
    "F fit, H hide panels, 1-3 method, Space spray",
    "L planes mode (sliders in Method; clicks place nothing)", nullptr};

void legend3D(Model& model) {
  drawLegend(legendOf(model));
}

// the plane's answer by both methods and the steps core took
void planeInspector(Model& model) {
  const Planes3D& planes = model.planes3d;
  const Palette& pal = paletteFor(model.settings.theme);
  const auto& plane = planes.plane();
  if (!plane) return;
  const Crossing c = plane->chosen(planes.method()).crossing;
  const Rgba colour = crossingColour(pal, c);
  ImGui::TextColored(im(readableOn(colour, pal.background, pal.text)), "Plane: %s",
                     std::string(toString(c)).c_str());
  const CubemapLocator* cube = planes.dualIntersector()->dualLocator();
  traceLines(
      describePlane(*plane, planes.method(), cube ? cube->vertices() : std::span<const Vec3>{}),
      pal, colour);
}

void inspector3D(Model& model, bool hints) {
  if (model.planes3d.enabled()) return planeInspector(model);
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
  if (scene.secondPinnedCell() >= 0) {
    ImGui::Spacing();
    ImGui::TextColored(im(pal.inside), "Second pinned cell");
    cellText(cells[static_cast<std::size_t>(scene.secondPinnedCell())]);
  }
  placedPoint(scene, pal, hints, "click on the slicing plane to place a point and follow its query",
              [&](const Probe3D& probe) {
                const Bounds3 b = scene.bounds();
                return describeTrace3D(probe.trace, probe.point, glm::length(b.hi - b.lo));
              });
}

}  // namespace

const ScenePanels& panels3D() {
  static constexpr ScenePanels kPanels = {
      shapePanel3D,  methodPanel3D, "Slicing plane", slicePanel3D,  pointsPanel3D, false,
      viewOptions3D, legend3D,      inspector3D,     inspectable3D, kHints3D};
  return kPanels;
}

}  // namespace convexloc::viewer
