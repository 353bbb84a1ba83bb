// convexloc-viewer — the scene's labels over the window.
#include "ui/label_overlay.hpp"

#include <cmath>
#include <span>

#include <imgui.h>

#include "logic/draw/cube_inset.hpp"
#include "logic/draw/zoom_inset.hpp"
#include "logic/view/scene_labels.hpp"
#include "ui/panels/views_panel.hpp"
#include "ui/scene_area.hpp"
#include "ui/slide_frame.hpp"
#include "ui/widgets.hpp"

namespace convexloc::viewer {

namespace {

// the labels of `lists` over the scene, placed as the SVG places them: no two overlap, none
// sits on a marker
void writeLabels(const Model& model, ImDrawList* dl, const ScreenProjection& project,
                 std::span<const DrawList* const> lists, std::span<const PixelBox> windows,
                 ScreenRect area) {
  const Palette& pal = paletteFor(model.settings.theme);
  const ImU32 shadow = packAbgr(withAlpha(pal.background, 0.85f));
  const float halo = std::max(1.0f, std::round(model.settings.drawScale()));
  for (const PlacedSceneLabel& p :
       layoutSceneLabels(lists, 1, project, {area.lo, area.hi}, measureText,
                         model.settings.drawScale(), 400, windows)) {
    const char* text = p.label->text.c_str();
    const ImVec2 at(std::round(static_cast<float>(p.place.centre.x - 0.5 * p.place.size.x)),
                    std::round(static_cast<float>(p.place.centre.y - 0.5 * p.place.size.y)));
    if (p.place.leader)
      dl->AddLine(
          ImVec2(static_cast<float>(p.anchor.x), static_cast<float>(p.anchor.y)),
          ImVec2(static_cast<float>(p.place.centre.x), static_cast<float>(p.place.centre.y)),
          packAbgr(withAlpha(p.label->colour, 0.6f)), 1.0f);
    // a halo of the background all round, as thick as the lines are scaled
    for (const ImVec2 d : {ImVec2(-1, 0), ImVec2(1, 0), ImVec2(0, -1), ImVec2(0, 1), ImVec2(-1, -1),
                           ImVec2(1, -1), ImVec2(-1, 1), ImVec2(1, 1)})
      dl->AddText(ImVec2(at.x + d.x * halo, at.y + d.y * halo), shadow, text);
    dl->AddText(at, packAbgr(readableOn(p.label->colour, pal.background, pal.text)), text);
  }
}

// a rectangle of the window as ImGui's clip rectangle
void pushClip(ImDrawList* dl, const ScreenRect& r) {
  dl->PushClipRect(ImVec2(static_cast<float>(r.lo.x), static_cast<float>(r.lo.y)),
                   ImVec2(static_cast<float>(r.hi.x), static_cast<float>(r.hi.y)));
}

}  // namespace

std::vector<PixelBox> labelKeepOffs(const UiState& ui) {
  std::vector<PixelBox> boxes;
  for (const float* w : {ui.legendRect, ui.stepsRect})
    if (w[2] > w[0]) boxes.push_back({{w[0], w[1]}, {w[2], w[3]}});
  for (const ScreenRect& r : {ui.layout.title.box, ui.layout.caption.box, ui.layout.note.box,
                              ui.splitHeadings[0].box, ui.splitHeadings[1].box})
    if (r.hi.x > r.lo.x && r.hi.y > r.lo.y) boxes.push_back({r.lo, r.hi});
  return boxes;
}

const std::optional<CubeInset>& cubeInsetFound(const Model& model) {
  static const std::optional<CubeInset> none;
  if (model.dim != Dim::Three || !model.hasScene3d() || model.planes3d.enabled() ||
      !model.settings.view3d.showCube)
    return none;
  const Scene3D& scene = model.scene3d();
  const auto& cells = scene.cells();
  // the patch, found again only when the cells change (a scan of every cell)
  static struct {
    const void* cells = nullptr;
    std::uint64_t structure = ~0ull;
    std::optional<CubeInset> inset;
  } found;
  if (found.cells != &cells || found.structure != scene.versions().structure) {
    found.inset = cubeMapInset(cells);
    found.cells = &cells;
    found.structure = scene.versions().structure;
  }
  return found.inset;
}

std::optional<ZoomInset> zoomInsetFound(const Model& model) {
  if (model.dim != Dim::Two || model.lines2d.enabled() || model.split.enabled()) return {};
  return tinyEdgesInset(model.scene2d.polygon());
}

namespace {

// the cube inset's frame: a slide's corner kept for it, else the free corner found
std::optional<PixelBox> cubeInsetFrame(const Model& model, const UiState& ui,
                                       const CubeInset& inset, const ScreenProjection& project,
                                       double room) {
  if (ui.layout.insetFrame.hi.x > ui.layout.insetFrame.lo.x)
    return PixelBox{ui.layout.insetFrame.lo, ui.layout.insetFrame.hi};
  // the cube on screen: its eight corners
  const Scene3D& scene = model.scene3d();
  const double h = scene.cubeHalfSize();
  std::vector<glm::dvec2> cube;
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 corner =
        toGlm(*scene.centre()) + h * glm::dvec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1);
    if (const auto p = project(corner)) cube.emplace_back(*p);
  }
  if (cube.size() < 8) return std::nullopt;  // a corner behind the eye
  const ScreenRect figure = figureRoomOf(model, ui);
  const ScreenRect area =
      figure.hi.x > figure.lo.x ? figure : sceneArea(model, ui, model.camera3d.viewport());
  const double wide =
      std::max(measureText(cubeInsetTitle(inset)).x, measureText(cubeInsetZoomText(inset)).x);
  return placeCubeInset({area.lo, area.hi}, cube, labelKeepOffs(ui), {wide + 8.0, room});
}

// the cube map's inset (logic/draw/cube_inset) in window pixels
std::optional<ScreenInset> cubeInsetOver(const Model& model, const UiState& ui) {
  const std::optional<CubeInset>& inset = cubeInsetFound(model);
  if (!inset || !model.scene3d().centre()) return std::nullopt;
  const auto& cells = model.scene3d().cells();
  const ScreenProjection project = sceneProjection(model);
  const double room = insetTextRoom();
  const auto frame = cubeInsetFrame(model, ui, *inset, project, room);
  if (!frame) return std::nullopt;
  ScreenInset out;
  out.box = {frame->lo - glm::dvec2(0.0, room), frame->hi + glm::dvec2(0.0, room)};
  // a slide's corner: the title in two lines over the frame
  const bool corner = ui.layout.inset.hi.x > ui.layout.inset.lo.x;
  if (corner) out.box = {ui.layout.inset.lo, ui.layout.inset.hi};
  std::optional<glm::dvec2> anchor;
  if (const auto a = project(cubeInsetAnchor(*inset, cells))) anchor = glm::dvec2(*a);
  drawCubeInset(*inset, cells, paletteFor(model.settings.theme), *frame, room, anchor, out.list,
                corner);
  if (anchor) {  // the scene's labels keep off the ring and the name by it
    const Label& name = out.list.labels.back();
    const glm::dvec2 at(name.p), half = 0.5 * measureText(name.text) + glm::dvec2(2.0);
    out.mark = {glm::min(*anchor - 10.0, at - half), glm::max(*anchor + 10.0, at + half)};
  }
  return out;
}

// the tiny edges' inset on a slide, in the corner its layout keeps (off a slide it is drawn
// beside the polygon, in world units)
std::optional<ScreenInset> zoomInsetOver(const Model& model, const UiState& ui) {
  const ScreenRect frame = ui.layout.insetFrame;
  const std::optional<ZoomInset> inset = zoomInsetFound(model);
  if (!inset || !(frame.hi.x > frame.lo.x)) return std::nullopt;
  const double room = insetTextRoom();
  ScreenInset out;
  out.box = {ui.layout.inset.lo, ui.layout.inset.hi};
  const Camera2D& camera = model.camera2d;
  const auto project = [&camera](Vec2 p) -> std::optional<glm::dvec2> {
    return camera.toScreen({p.x, p.y});
  };
  drawZoomInsetOnScreen(model.scene2d.polygon(), *inset, paletteFor(model.settings.theme),
                        {frame.lo, frame.hi}, room, project, out.list);
  if (const auto s = project({0.5 * (inset->source.lo.x + inset->source.hi.x),
                              0.5 * (inset->source.lo.y + inset->source.hi.y)}))
    out.mark = {*s - room, *s + room};
  return out;
}

}  // namespace

std::vector<PixelBox> ScreenInset::keepOff() const {
  std::vector<PixelBox> boxes = leader;
  boxes.push_back(box);
  if (!mark.empty()) boxes.push_back(mark);
  return boxes;
}

double insetTextRoom() {
  return 1.6 * measureText("Ag").y;
}

std::optional<ScreenInset> sceneInsetOver(const Model& model, const UiState& ui) {
  std::optional<ScreenInset> out =
      model.dim == Dim::Three ? cubeInsetOver(model, ui) : zoomInsetOver(model, ui);
  if (!out) return out;
  const double step = 0.5 * insetTextRoom();
  for (Segment& g : out->list.segments) {
    g.width *= static_cast<float>(model.settings.drawScale());  // as wide as the scene's
    if (g.dash <= 0.0f) continue;
    // the leader (the dashed line): boxes a half line apart along it
    const glm::dvec2 a(g.a), b(g.b);
    const int n = static_cast<int>(glm::length(b - a) / step) + 1;
    for (int k = 0; k <= n; ++k) {
      const glm::dvec2 p = a + (static_cast<double>(k) / n) * (b - a);
      out->leader.push_back({p - 0.5 * step, p + 0.5 * step});
    }
  }
  return out;
}

void paintScreenList(const DrawList& list, ImDrawList* dl, const Palette& pal) {
  const auto v = [](glm::dvec3 p) {
    return ImVec2(static_cast<float>(p.x), static_cast<float>(p.y));
  };
  // the fills without anti-aliasing: a fringe would draw each triangle's diagonal
  const ImDrawListFlags flags = dl->Flags;
  dl->Flags &= ~ImDrawListFlags_AntiAliasedFill;
  for (std::size_t t = 0; t + 2 < list.fills.size(); t += 3)
    dl->AddTriangleFilled(v(list.fills[t].p), v(list.fills[t + 1].p), v(list.fills[t + 2].p),
                          packAbgr(list.fills[t].colour));
  dl->Flags = flags;
  for (const Segment& g : list.segments) {
    const double length = glm::length(g.b - g.a);
    if (g.dash <= 0.0f || !(length > 0.0)) {
      dl->AddLine(v(g.a), v(g.b), packAbgr(g.colour), g.width);
      continue;
    }
    // dashes `dash` long, gaps as long
    for (double d = 0.0; d < length; d += 2.0 * g.dash)
      dl->AddLine(v(g.a + (d / length) * (g.b - g.a)),
                  v(g.a + (std::min(d + g.dash, length) / length) * (g.b - g.a)),
                  packAbgr(g.colour), g.width);
  }
  for (const Label& l : list.labels) {
    const ImVec2 size = ImGui::CalcTextSize(l.text.c_str());
    const ImVec2 at(std::round(static_cast<float>(l.p.x) - 0.5f * size.x),
                    std::round(static_cast<float>(l.p.y) - 0.5f * size.y));
    dl->AddText(at, packAbgr(readableOn(l.colour, pal.background, pal.text)), l.text.c_str());
  }
}

void drawLabels(Model& model, const UiState& ui, const SceneView& view) {
  if (plotsSlide(model, ui)) return;  // its plots are the figure: no scene under them
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  std::vector<PixelBox> windows = labelKeepOffs(ui);
  if (const auto inset = sceneInsetOver(model, ui)) {
    paintScreenList(inset->list, dl, paletteFor(model.settings.theme));
    for (const PixelBox& b : inset->keepOff()) windows.push_back(b);
  }
  const glm::dvec2 vp =
      model.dim == Dim::Two ? model.camera2d.viewport() : model.camera3d.viewport();
  const ScreenRect figure = figureRoomOf(model, ui);
  const ScreenRect area = figure.hi.x > figure.lo.x ? figure : sceneArea(model, ui, vp);
  const DrawList* lists[] = {&view.structure(), &view.overlay()};
  const bool split = model.dim == Dim::Two && model.split.enabled() && !model.lines2d.enabled();
  if (!split) {
    writeLabels(model, dl, sceneProjection(model), lists, windows, area);
    return;
  }
  // each half's labels, clipped to it, the right half's through its own camera
  pushClip(dl, model.split.left());
  writeLabels(model, dl, sceneProjection(model), lists, windows, area);
  dl->PopClipRect();
  pushClip(dl, model.split.right());
  const Camera2D right = model.split.rightCamera(model.camera2d);
  const DrawList* rightLists[] = {&view.splitStructure(), &view.splitOverlay()};
  writeLabels(
      model, dl,
      [right](glm::dvec3 p) -> std::optional<glm::dvec3> {
        return glm::dvec3(right.toScreen({p.x, p.y}), 0.0);
      },
      rightLists, windows, area);
  dl->PopClipRect();
  splitDecorations(model, ui);
}

}  // namespace convexloc::viewer
