// convexloc-viewer — the scene's area and the camera's fit in it.
#include "ui/scene_area.hpp"

#include <algorithm>
#include <iterator>

#include "logic/view/fit_room.hpp"

namespace convexloc::viewer {

namespace {

// the drawn shape's width over its height, about (the 3D scenes as a square)
double shapeAspect(const Model& model) {
  if (model.dim == Dim::Three) return model.planes3d.enabled() ? 2.0 : 1.0;
  if (model.lines2d.enabled()) return 2.0;  // the dual view sits beside
  const Box2 b = model.scene2d.polygon().bounds();
  const double w = b.hi.x - b.lo.x, h = b.hi.y - b.lo.y;
  return w > 0.0 && h > 0.0 ? std::clamp(w / h, 0.2, 5.0) : 1.0;
}

// the Steps window's strip, and the legend's with it (logic/view/fit_room.hpp)
void leaveRoomForSteps(ScreenRect& a, const UiState& ui, ScreenRect full, double aspect) {
  full.hi.y -= ui.captionHeight;
  CornerBoxes boxes;
  boxes.steps = {ui.stepsSize[0], ui.stepsSize[1]};
  if (a.hi.x < full.hi.x || a.hi.y < full.hi.y)  // the fit gave the legend a strip
    boxes.legend = {ui.legendSize[0] + 20.0, ui.legendSize[1] + 20.0};
  a = roomBesideCorners(a, full, boxes, aspect);
}

// the camera's state, to tell whether it moved since the fit
void viewNow(const Model& model, double (&v)[6]) {
  if (model.dim == Dim::Two) {
    const glm::dvec2 c = model.camera2d.centre();
    v[0] = c.x, v[1] = c.y, v[2] = model.camera2d.scale(), v[3] = v[4] = v[5] = 0.0;
    return;
  }
  const Camera3D& cam = model.camera3d;
  v[0] = cam.target().x, v[1] = cam.target().y, v[2] = cam.target().z;
  v[3] = cam.distance(), v[4] = cam.yaw(), v[5] = cam.pitch();
}

}  // namespace

bool viewAsFitted(const Model& model, const UiState& ui) {
  double v[6];
  viewNow(model, v);
  return std::equal(std::begin(v), std::end(v), std::begin(ui.fittedView));
}

float leftPanelWidth(const Model& model, glm::dvec2 window) {
  if (!model.settings.showUi) return 0.0f;
  // as wide as the text needs at its scale, up to 45% of the window (longer lines wrap)
  const float cap = std::max(300.0f, static_cast<float>(0.45 * window.x));
  return std::min(345.0f * model.settings.fontScale, cap);
}

float rightPanelWidth(const Model& model, glm::dvec2 window) {
  // narrower windows keep the scene wide: legend and inspector float over it instead
  const float fs = model.settings.fontScale;
  if (!model.settings.showUi || window.x < 1280.0 * std::max(1.0f, 0.75f * fs)) return 0.0f;
  return std::min(330.0f * fs, static_cast<float>(0.26 * window.x));
}

void fitScene(Model& model, UiState& ui, glm::dvec2 window, double now) {
  ScreenRect a = sceneArea(model, window);
  a.hi.y -= ui.captionHeight;
  const bool floatingLegend = model.settings.showLegend && rightPanelWidth(model, window) == 0.0f;
  if (floatingLegend && !ui.legendMoved && ui.legendSize[0] > 0.0f) {
    // give up the strip, right or bottom, that costs the scene less
    const glm::dvec2 s = a.size();
    const double lw = ui.legendSize[0] + 20.0, lh = ui.legendSize[1] + 20.0;
    if (s.x > lw && s.y > lh) {
      if ((s.x - lw) / s.x >= (s.y - lh) / s.y)
        a.hi.x -= lw;
      else
        a.hi.y -= lh;
    }
  }
  // (the split view's halves share the whole area: its Steps window stays over it)
  if (ui.stepsSize[0] > 0.0f && !(model.dim == Dim::Two && model.split.enabled()))
    leaveRoomForSteps(a, ui, sceneArea(model, window), shapeAspect(model));
  model.fit(a);
  viewNow(model, ui.fittedView);
  ui.refitUntil = now + 1.5;
}

ScreenRect sceneArea(const Model& model, glm::dvec2 window) {
  return {{static_cast<double>(leftPanelWidth(model, window)),
           static_cast<double>(model.settings.slideCardHeight)},
          {window.x - static_cast<double>(rightPanelWidth(model, window)), window.y}};
}

}  // namespace convexloc::viewer
