// convexloc-viewer — typed coordinates.
#include "ui/panels/typed_coords.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <unordered_map>

#include <imgui.h>

#include "logic/base/format.hpp"
#include "logic/view/snap.hpp"
#include "ui/widgets.hpp"

namespace convexloc::viewer {
namespace {

// the text typed into each exact field while it is edited or refused, by ImGui id
std::unordered_map<ImGuiID, std::string>& pendingEdits() {
  static std::unordered_map<ImGuiID, std::string> edits;
  return edits;
}

// the width of one of `n` fields side by side in the remaining row
float fieldWidth(int n) {
  const float spacing = ImGui::GetStyle().ItemSpacing.x;
  return std::max(40.0f, (ImGui::GetContentRegionAvail().x - spacing * (n - 1)) / n);
}

// two exact fields on a row: true when either changed
bool pairFields(const char* idX, const char* idY, Vec2& p) {
  const float w = fieldWidth(2);
  bool changed = exactField(idX, p.x, w);
  ImGui::SameLine();
  changed |= exactField(idY, p.y, w);
  return changed;
}

// three exact fields on a row
bool tripleFields(const char* id, Vec3& p) {
  const float w = fieldWidth(3);
  const std::string base(id);
  bool changed = exactField((base + "x").c_str(), p.x, w);
  ImGui::SameLine();
  changed |= exactField((base + "y").c_str(), p.y, w);
  ImGui::SameLine();
  changed |= exactField((base + "z").c_str(), p.z, w);
  return changed;
}

// `index` kept within [0, count) (a vertex chosen for a shape since replaced)
void clampIndex(int& index, std::size_t count) {
  index = std::clamp(index, 0, static_cast<int>(std::max<std::size_t>(count, 1)) - 1);
}

// a vertex number field, kept within [0, count)
void vertexIndexField(const char* id, int& index, std::size_t count, float width) {
  ImGui::SetNextItemWidth(width);
  ImGui::InputInt(id, &index, 1, 1);
  clampIndex(index, count);
}

// what the 2D panel keeps between frames: the point typed and the vertices chosen
struct Typed2D {
  Vec2 point{};
  int vertex = 0, lineFrom = 0, lineTo = 1;
  Vec2 lineP1{}, lineP2{1.0, 0.0};
};

Typed2D& typed2D() {
  static Typed2D t;
  return t;
}

void typedPoint2D(Model& model) {
  Scene2D& scene = model.scene2d;
  Typed2D& t = typed2D();
  if (scene.probe()) t.point = scene.probe()->point;
  ImGui::TextDisabled("point (x, y): Enter places it");
  if (pairFields("##px", "##py", t.point)) scene.place(t.point);
  const auto v = scene.polygon().vertices();
  clampIndex(t.vertex, v.size());
  if (ImGui::SmallButton("on vertex")) scene.place(v[static_cast<std::size_t>(t.vertex)]);
  ImGui::SameLine();
  vertexIndexField("##onVertex", t.vertex, v.size(), fieldWidth(1) * 0.45f);
  if (const auto c = scene.centre()) {
    ImGui::SameLine();
    if (ImGui::SmallButton("at x_T")) scene.place(*c);
  }
}

void typedVertex2D(Model& model) {
  Scene2D& scene = model.scene2d;
  Typed2D& t = typed2D();
  const auto v = scene.polygon().vertices();
  ImGui::TextDisabled("vertex");
  ImGui::SameLine();
  vertexIndexField("##vertex", t.vertex, v.size(), fieldWidth(1) * 0.45f);
  Vec2 p = v[static_cast<std::size_t>(t.vertex)];
  // moved as a drag would: refused (and said why) where the polygon would not stay convex
  if (pairFields("##vx", "##vy", p)) {
    scene.beginDrag(static_cast<std::size_t>(t.vertex));
    scene.dragTo(p);
    scene.endDrag();
  }
}

void typedLine2D(Model& model) {
  Lines2D& lines = model.lines2d;
  Typed2D& t = typed2D();
  if (lines.line()) t.lineP1 = lines.line()->p1, t.lineP2 = lines.line()->p2;
  ImGui::TextDisabled("line through (x, y) and (x, y)");
  bool changed = pairFields("##l1x", "##l1y", t.lineP1);
  changed |= pairFields("##l2x", "##l2y", t.lineP2);
  if (changed && !lines.setLine(t.lineP1, t.lineP2)) model.fail("a line needs two distinct points");
  const auto v = model.scene2d.polygon().vertices();
  clampIndex(t.lineFrom, v.size());
  clampIndex(t.lineTo, v.size());
  if (ImGui::SmallButton("through vertices")) {
    if (t.lineFrom == t.lineTo)
      model.fail("a line needs two distinct vertices");
    else
      lines.setLine(v[static_cast<std::size_t>(t.lineFrom)], v[static_cast<std::size_t>(t.lineTo)]);
  }
  const float w = fieldWidth(2);
  ImGui::SameLine();
  vertexIndexField("##lineFrom", t.lineFrom, v.size(), w * 0.45f);
  ImGui::SameLine();
  vertexIndexField("##lineTo", t.lineTo, v.size(), w * 0.45f);
}

// the plane n.x = d typed: three points of it derived along the normal's largest axis
void typedNormalOffset(Model& model) {
  static Vec3 n{0.0, 0.0, 1.0};
  static double d = 0.0;
  ImGui::TextDisabled("plane a x + b y + c z = d: Enter sets it");
  bool changed = tripleFields("##n", n);
  changed |= exactField("##d", d, fieldWidth(1));
  if (!changed) return;
  const double c[3] = {n.x, n.y, n.z};
  int k = 0;
  for (int a = 1; a < 3; ++a)
    if (std::abs(c[a]) > std::abs(c[k])) k = a;
  if (c[k] == 0.0) return model.fail("a plane needs a normal other than (0, 0, 0)");
  // (0, 0), (1, 0), (0, 1) on the other two axes, the k-th solved (rounded to a double)
  std::array<Vec3, 3> q{};
  const int i = (k + 1) % 3, j = (k + 2) % 3;
  for (int m = 0; m < 3; ++m) {
    double x[3] = {0.0, 0.0, 0.0};
    x[i] = m == 1 ? 1.0 : 0.0;
    x[j] = m == 2 ? 1.0 : 0.0;
    x[k] = (d - c[i] * x[i] - c[j] * x[j]) / c[k];
    q[static_cast<std::size_t>(m)] = {x[0], x[1], x[2]};
  }
  model.planes3d.setPlane(q[0], q[1], q[2]);
}

}  // namespace

bool exactField(const char* id, double& v, float width) {
  auto& edits = pendingEdits();
  const ImGuiID key = ImGui::GetID(id);
  const auto it = edits.find(key);
  const bool refused = it != edits.end() && !parseNumber(it->second);
  std::array<char, 96> buf{};
  std::snprintf(buf.data(), buf.size(), "%s",
                it != edits.end() ? it->second.c_str() : exactText(v).c_str());
  if (refused) ImGui::PushStyleColor(ImGuiCol_FrameBg, ImVec4(0.75f, 0.2f, 0.15f, 0.55f));
  ImGui::SetNextItemWidth(width);
  const bool entered =
      ImGui::InputText(id, buf.data(), buf.size(),
                       ImGuiInputTextFlags_EnterReturnsTrue | ImGuiInputTextFlags_CharsScientific |
                           ImGuiInputTextFlags_AutoSelectAll);
  if (refused) ImGui::PopStyleColor();
  if (ImGui::IsItemActive()) {
    edits[key] = buf.data();
    if (!entered) return false;
  }
  const auto pending = edits.find(key);
  if (pending == edits.end()) return false;
  if (!entered && !ImGui::IsItemDeactivated()) return false;
  const auto typed = parseNumber(entered ? std::string(buf.data()) : pending->second);
  if (!typed) return false;  // kept, red, until mended
  edits.erase(key);
  if (*typed == v) return false;
  v = *typed;
  return true;
}

void typedCoordinates2D(Model& model) {
  if (model.lines2d.enabled()) return typedLine2D(model);
  typedPoint2D(model);
  typedVertex2D(model);
}

void typedPlane3D(Model& model) {
  Planes3D& planes = model.planes3d;
  typedNormalOffset(model);
  static std::array<Vec3, 3> q{{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}};
  static std::array<int, 3> chosen{0, 1, 2};
  if (planes.plane()) q = planes.plane()->q;
  ImGui::TextDisabled("plane through three points: Enter sets it");
  bool changed = false;
  for (int k = 0; k < 3; ++k) changed |= tripleFields(("##q" + std::to_string(k)).c_str(), q[k]);
  if (changed && !planes.setPlane(q[0], q[1], q[2]))
    model.fail("the three points are collinear: they define no plane");
  const ConvexPolyhedron* p = planes.polyhedron();
  if (!p) return;
  const auto v = p->vertices();
  for (int& k : chosen) clampIndex(k, v.size());
  // the three vertex numbers on a row, the button below them
  const float w = fieldWidth(3);
  for (int k = 0; k < 3; ++k) {
    if (k) ImGui::SameLine();
    vertexIndexField(("##pv" + std::to_string(k)).c_str(), chosen[static_cast<std::size_t>(k)],
                     v.size(), w);
  }
  if (ImGui::SmallButton("plane through these vertices") &&
      !planes.setPlane(v[static_cast<std::size_t>(chosen[0])],
                       v[static_cast<std::size_t>(chosen[1])],
                       v[static_cast<std::size_t>(chosen[2])]))
    model.fail("those three vertices are collinear: they define no plane");
}

bool steppedField(const char* id, double& v, double step) {
  const float button = ImGui::GetFrameHeight();
  const std::string name(id);
  double typed = v;
  bool changed = false;
  if (ImGui::Button(("-" + name + "down").c_str(), ImVec2(button, 0.0f)) && step > 0.0)
    typed = (std::ceil(typed / step) - 1.0) * step, changed = true;
  ImGui::SameLine();
  const float field = fieldWidth(1) - button - ImGui::GetStyle().ItemSpacing.x;
  changed |= exactField(id, typed, field);
  ImGui::SameLine();
  if (ImGui::Button(("+" + name + "up").c_str(), ImVec2(button, 0.0f)) && step > 0.0)
    typed = (std::floor(typed / step) + 1.0) * step, changed = true;
  if (changed) v = typed;
  return changed;
}

void typedSliceOffset(Model& model) {
  Scene3D& scene = model.scene3d();
  SlicePlane s = scene.slice();
  const Bounds3 b = scene.bounds();
  // a step of 1, 2 or 5 times a power of ten, about a fiftieth of the box
  if (steppedField("##sliceOffset", s.offset, niceGridStep((b.hi[s.axis] - b.lo[s.axis]) / 50.0)))
    scene.setSlice(s);
}

}  // namespace convexloc::viewer
