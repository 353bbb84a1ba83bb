// convexloc-viewer — writing every slide.
#include "writers/slide_export.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <limits>

#include <imgui.h>

#include "logic/teach/query_view.hpp"
#include "ui/label_overlay.hpp"
#include "ui/panels/lecture_panel.hpp"
#include "ui/slide_frame.hpp"
#include "writers/screenshot.hpp"
#include "writers/svg_export.hpp"
#include "writers/svg_writer.hpp"

namespace convexloc::viewer {
namespace {

// grows `box` to hold the window point `p`
void grow(ScreenRect& box, glm::dvec2 p) {
  box.lo = glm::min(box.lo, p);
  box.hi = glm::max(box.hi, p);
}

// the split view: two halves
bool splitShown(const Model& model) {
  return model.dim == Dim::Two && model.split.enabled() && !model.lines2d.enabled();
}

// the drawn bounding box of the figure: the polygon (with a placed point near it and a zoom
// inset's frame) or the polyhedron (with the cube map's cube), as the fit holds them
ScreenRect shapeBox(const Model& model) {
  const ScreenProjection project = sceneProjection(model);
  ScreenRect box{glm::dvec2(std::numeric_limits<double>::infinity()),
                 glm::dvec2(-std::numeric_limits<double>::infinity())};
  const auto add = [&](glm::dvec3 p) {
    if (const std::optional<glm::dvec3> s = project(p)) grow(box, {s->x, s->y});
  };
  if (model.dim == Dim::Two) {
    const Box2 b = model.figureBox2();
    add({b.lo.x, b.lo.y, 0.0});
    add({b.hi.x, b.hi.y, 0.0});
    if (splitShown(model)) {  // the right half's polygon through its own camera
      const Camera2D right = model.split.rightCamera(model.camera2d);
      grow(box, right.toScreen({b.lo.x, b.lo.y}));
      grow(box, right.toScreen({b.hi.x, b.hi.y}));
    }
  } else {
    for (const glm::dvec3& p : model.figurePoints3()) add(p);
  }
  return box;
}

// a world point on the page
glm::dvec2 onPage(const ScreenProjection& project, glm::dvec3 p, glm::dvec2 pageLo) {
  const std::optional<glm::dvec3> s = project(p);
  return s ? glm::dvec2(s->x, s->y) - pageLo : glm::dvec2(-1.0);
}

// the 3D query's centre, point and the face its ray leaves by, on the page
std::optional<Query3DOnPage> query3dOf(const Model& model, glm::dvec2 pageLo) {
  if (model.dim != Dim::Three || !model.hasScene3d() || model.planes3d.enabled()) return {};
  const auto& probe = model.scene3d().probe();
  if (!probe || !probe->trace.centre) return {};
  const Vec3 c = *probe->trace.centre, x = probe->point;
  const glm::dvec3 centre{c.x, c.y, c.z}, point{x.x, x.y, x.z};
  const std::optional<RayExit> exit = rayExitFace(model.scene3d().polyhedron(), centre, point);
  if (!exit) return {};
  const ScreenProjection project = sceneProjection(model);
  return Query3DOnPage{onPage(project, centre, pageLo), onPage(project, point, pageLo),
                       onPage(project, exit->faceMiddle, pageLo)};
}

// the smallest text in a slide's title card and caption box, `font` the body's height
double boxTextPx(const SlideLayout& l, double font) {
  double least = std::numeric_limits<double>::infinity();
  if (!l.title.lines.empty()) least = font * l.title.scale;
  if (l.title.lines.size() > l.titleLines) least = std::min(least, font * l.title.restScale);
  if (!l.caption.lines.empty()) least = std::min(least, font * l.caption.scale);
  return least;
}

ScreenRect rectOf(const float (&r)[4]) {
  return {{r[0], r[1]}, {r[2], r[3]}};
}

}  // namespace

SlideRecord recordSlide(const Model& model, const UiState& ui, glm::dvec2 window) {
  SlideRecord r;
  r.slide = ui.show.current + 1;
  const ScreenRect page = pageOf(model, ui, window).page;
  r.page = page.size();
  const SlideLayout& l = ui.layout;
  const bool whyWindow = model.whyOpen && ui.whyWindow.hi.x > ui.whyWindow.lo.x;
  const bool plots = plotsSlide(model, ui) || whyWindow;
  r.kind = plots ? SlideKind::Plots
                 : (model.dim == Dim::Two ? SlideKind::Figure2D : SlideKind::Figure3D);
  if (!l.title.lines.empty()) r.add("title", l.title.box, page.lo);
  if (!l.caption.lines.empty()) r.add("caption", l.caption.box, page.lo);
  r.add("steps", rectOf(ui.stepsRect), page.lo);
  r.add("legend", rectOf(ui.legendRect), page.lo);
  // the room the scene is drawn in (the split view: both halves, their headings at the top)
  r.add("figure", whyWindow ? ui.whyWindow : l.scene, page.lo);
  if (!plots) r.add("shape", shapeBox(model), page.lo);
  if (const std::optional<ScreenInset> inset = sceneInsetOver(model, ui))
    r.add("inset", {inset->box.lo, inset->box.hi}, page.lo);
  else if (!l.note.lines.empty())
    r.add("inset", l.note.box, page.lo);  // a note on the figure, in the inset's corner
  // the body text (the labels') or a slide's smaller text in its boxes; a plots slide has
  // no labels: its card's, caption's and plots' text
  r.minTextPx = plotsSlide(model, ui) ? boxTextPx(l, ImGui::GetFontSize())
                                      : ImGui::GetFontSize() * std::min(1.0, l.columnScale);
  // the plots' text (a plots slide's tick labels, legends and line under them)
  if (plots && ui.whyPlots.fontPx > 0.0) r.minTextPx = std::min(r.minTextPx, ui.whyPlots.fontPx);
  r.query3d = query3dOf(model, page.lo);
  return r;
}

bool SlideExporter::afterFrame(Model& model, const SceneView& view, UiState& ui, int width,
                               int height) {
  if (!active() || finished_ || next_) return true;
  // a slide measuring Why O(1) is written with its plots finished
  if (model.whyOpen && model.scaling->running()) return true;
  std::error_code ec;
  std::filesystem::create_directories(dir_, ec);
  char name[32];
  std::snprintf(name, sizeof name, "slide-%02zu", ui.show.current + 1);
  const std::string path = (std::filesystem::path(dir_) / name).string();
  std::string problem;
  if (++frames_ == 1 && first_) problem = saveScreenshot(path + "-first.png", width, height);
  if (problem.empty() && frames_ < kFramesPerSlide) return true;
  if (problem.empty()) problem = saveScreenshot(path + ".png", width, height);
  if (problem.empty()) writeSceneSvg(model, view, ui, path + ".svg", problem);
  records_.push_back(recordSlide(model, ui, {width, height}));
  // the next slide that can be shown as written (the others were reported at the start)
  const std::size_t next = ui.show.goodFrom(ui.show.current + 1);
  if (problem.empty() && next >= ui.show.lecture.slides.size())
    writeTextFile((std::filesystem::path(dir_) / "layout.json").string(), layoutJson(records_),
                  problem);
  if (!problem.empty()) {
    std::cerr << "convexloc-viewer: " << problem << "\n";
    return false;
  }
  ++written_;
  frames_ = 0;
  if (next >= ui.show.lecture.slides.size())
    finished_ = true;
  else
    next_ = next;
  return true;
}

bool SlideExporter::turnPage(Model& model, UiState& ui) {
  if (!next_) return true;
  const std::size_t next = *next_;
  next_.reset();
  const std::string problem = showSlideNow(model, ui, static_cast<std::ptrdiff_t>(next));
  if (problem.empty()) return true;
  std::cerr << "convexloc-viewer: slide " << next + 1 << ": " << problem << "\n";
  return false;
}

}  // namespace convexloc::viewer
