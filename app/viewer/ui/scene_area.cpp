// convexloc-viewer — the scene's area and the camera's fit in it.
#include "ui/scene_area.hpp"

#include <algorithm>
#include <iterator>

#include <imgui.h>

#include "ui/slide_frame.hpp"

namespace convexloc::viewer {

namespace {

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
  const Settings& s = model.settings;
  // the drawer: nearly the window's width, over the scene
  if (s.drawer)
    return s.drawerOpen ? std::min(345.0f * s.uiScale(), static_cast<float>(0.92 * window.x))
                        : 0.0f;
  if (!s.showUi) return 0.0f;
  // as wide as the text needs at its scale, up to 45% of the window (longer lines wrap)
  const float cap = std::max(300.0f, static_cast<float>(0.45 * window.x));
  return std::min(345.0f * model.settings.uiScale(), cap);
}

float rightPanelWidth(const Model& model, glm::dvec2 window) {
  // narrower windows keep the scene wide: legend and inspector float over it instead
  const float fs = model.settings.uiScale();
  if (!model.settings.showUi || window.x < 1280.0 * std::max(1.0f, 0.75f * fs)) return 0.0f;
  return std::min(330.0f * fs, static_cast<float>(0.26 * window.x));
}

ScreenRect fitRoom(const Model& model, const UiState& ui, glm::dvec2 window,
                   const SlideLayout* thisFrame) {
  const bool split = model.dim == Dim::Two && model.split.enabled() && !model.lines2d.enabled();
  if (!split)
    return thisFrame ? thisFrame->shapeRoom() : frameLayout(model, ui, window).shapeRoom();
  // the split view's halves share the whole area (its Steps window stays over it), below
  // the halves' headings (logic/teach/slide_layout's splitHeading: 2.2 body heights high)
  ScreenRect room = frameLayout(model, ui, window, false).scene;
  // (a slide's halves are its figure room, the same room)
  const double top = onSlide(model, ui) ? room.lo.y : sceneArea(model, ui, window).lo.y;
  room.lo.y = std::max(
      room.lo.y, top + splitHeadingBand(windowMetrics(), splitHeadingScale(model, ui, window)));
  return room;
}

void fitScene(Model& model, UiState& ui, glm::dvec2 window, double now) {
  slideDrawOptions(model, ui);
  const ScreenRect room = fitRoom(model, ui, window);
  model.fit(room, onSlide(model, ui));
  ui.fittedScene = room;
  viewNow(model, ui.fittedView);
  ui.refitUntil = now + 1.5;
}

ScreenRect pageArea(const Model& model, const UiState& ui, glm::dvec2 window) {
  const ScreenRect page = pageOf(model, ui, window).page;
  const double left = model.settings.drawer ? 0.0 : leftPanelWidth(model, window);
  return {{std::max(page.lo.x, left), page.lo.y},
          {std::min(page.hi.x, window.x - static_cast<double>(rightPanelWidth(model, window))),
           page.hi.y}};
}

ScreenRect sceneArea(const Model& model, const UiState& ui, glm::dvec2 window) {
  ScreenRect a = pageArea(model, ui, window);
  a.lo.y += static_cast<double>(model.settings.slideCardHeight);
  return a;
}

}  // namespace convexloc::viewer
