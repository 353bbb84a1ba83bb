// convexloc-viewer — the scene's labels over the window.
#include "ui/label_overlay.hpp"

#include <cmath>
#include <span>

#include <imgui.h>

#include "logic/view/scene_labels.hpp"
#include "ui/panels/views_panel.hpp"
#include "ui/scene_area.hpp"
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
  for (const ScreenRect& r : {ui.layout.title.box, ui.layout.caption.box, ui.splitHeadings[0].box,
                              ui.splitHeadings[1].box})
    if (r.hi.x > r.lo.x && r.hi.y > r.lo.y) boxes.push_back({r.lo, r.hi});
  return boxes;
}

void drawLabels(Model& model, const UiState& ui, const SceneView& view) {
  ImDrawList* dl = ImGui::GetBackgroundDrawList();
  const std::vector<PixelBox> windows = labelKeepOffs(ui);
  const glm::dvec2 vp =
      model.dim == Dim::Two ? model.camera2d.viewport() : model.camera3d.viewport();
  const ScreenRect area = sceneArea(model, ui, vp);
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
