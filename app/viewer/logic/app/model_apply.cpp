// convexloc-viewer — the command line's (a slide's) options applied to the app's state, each
// problem kept with the option it comes from.
#include <cmath>

#include "convexloc/generate2d.hpp"
#include "convexloc/generate3d.hpp"
#include "logic/app/model.hpp"
#include "logic/teach/scaling_record.hpp"

namespace convexloc::viewer {
namespace {

// the classes of sprayed points --show asks to draw (boundary points with inside or outside)
unsigned visibleMaskFor(const std::string& show) {
  if (show == "inside") return classBit(Location::Inside) | classBit(Location::Boundary);
  if (show == "outside") return classBit(Location::Outside) | classBit(Location::Boundary);
  if (show == "boundary") return classBit(Location::Boundary);
  return kAllClasses;
}

// a pinned cell's number out of range, with the range
std::string cellProblem(std::size_t k, std::size_t cells) {
  std::string text =
      "cell " + std::to_string(k) + ": the scene has " + std::to_string(cells) + " cells";
  if (cells > 0) text += " (0 .. " + std::to_string(cells - 1) + ")";
  return text;
}

}  // namespace

void Model::note(const std::string& problem, std::string_view key) {
  problems_.push_back({problem, std::string(key)});
  fail(problem);
}

void Model::noteSceneError(std::string_view key) {
  collectErrors();
  note(error_, key);
}

std::string Model::apply(const Options& o) {
  problems_.clear();
  settings.theme = o.theme;
  settings.fontScale = o.fontScale;
  // the page stays until another is given (reset() keeps it): a lecture's is its first slide's
  if (o.page) {
    settings.page = {o.page->first, o.page->second};
    settings.pageGiven = true;
  }
  settings.showUi = !o.hideUi;
  // presentation
  settings.present = o.present;
  settings.showUi = settings.showUi && !o.present;
  settings.showLegend = !o.noLegend;
  settings.caption = o.caption;
  // a slide whose drawing tells the steps (the split view's captions) without the window
  settings.stepBoxVisible = !o.noSteps;
  // a 3D method, --3d or a polyhedron kind ask for the 3D scene
  const bool method3d = o.method && parseMethod3D(*o.method).has_value();
  if (o.method && !method3d && !parseMethod2D(*o.method))
    note("unknown method '" + *o.method +
             "' (halfplane, wedge, slab, uniform, polar; halfspace, walk, cubemap)",
         "method");
  applyShape(o, method3d);
  if (dim == Dim::Two)
    apply2d(o, method3d);
  else
    apply3d(o, method3d);
  if (o.show) settings.visibleMask = visibleMaskFor(*o.show);
  // the query step by step: the mode first (it traces again), then the step
  setPaperMode(o.paper);
  setStep(o.step >= 1 ? o.step - 1 : -1);
  applyFigureOptions(o);
  applyTeachingViews(o);
  collectErrors();
  requestFit();
  return problems_.empty() ? std::string() : problems_.front().text;
}

void Model::applyShape(const Options& o, bool method3d) {
  Traits3D::hullOfFiles = o.hull;
  if (!o.shape.empty()) {
    if (!open(o.shape)) note(error_, "shape");
  } else if (o.preset) {
    if (!applyPreset(*o.preset)) note(error_, "preset");
  } else if (o.generate) {
    applyGenerator(o, method3d);
  } else if (o.solid || method3d || o.plane) {
    scene3d();
    dim = Dim::Three;
  }
}

void Model::applyGenerator(const Options& o, bool method3d) {
  const std::uint64_t seed = o.seed.value_or(1);
  const auto k2 = parsePolygonKind(*o.generate);
  const auto k3 = parsePolyhedronKind(*o.generate);
  if (k3 && (!k2 || method3d || o.solid)) {
    if (!scene3d().generate(*k3, o.n.value_or(320), seed))
      noteSceneError("generate");
    else
      dim = Dim::Three;
  } else if (k2) {
    if (!scene2d.generate(*k2, o.n.value_or(16), seed)) noteSceneError("generate");
  } else {
    note("unknown generator kind '" + *o.generate + "'", "generate");
  }
}

template <class Scene, class Method>
void Model::applyToScene(Scene& scene, const Options& o, std::optional<Method> method) {
  if (method) scene.setMethod(*method);
  if (o.resolution && !scene.setResolution(*o.resolution)) noteSceneError("resolution");
  if (o.spray || o.seed || o.nearBoundary) {
    SpraySettings s = scene.spraySettings();
    if (o.spray) s.count = *o.spray;
    if (o.seed) s.seed = *o.seed;
    s.nearBoundary = o.nearBoundary;
    scene.spray(s);
  }
}

void Model::apply2d(const Options& o, bool method3d) {
  if (method3d) note("'" + *o.method + "' is a 3D method; the scene is a polygon", "method");
  applyToScene(scene2d, o, o.method ? parseMethod2D(*o.method) : std::nullopt);
  if (o.probe) scene2d.place(*o.probe);
  if (o.hover) scene2d.hover(*o.hover);
  if (o.view) pendingView = *o.view;
  if (o.line) {
    setLinesMode(true);
    lines2d.setLine(o.line->first, o.line->second);
    lines2d.frameLine();
    lines2d.sync(scene2d);
  }
  if (o.probe3) note("probe X,Y,Z is for a 3D scene; the scene is a polygon (give X,Y)", "probe");
  if (o.slice) note("slice is for a 3D scene; the scene is a polygon", "slice");
  if (o.cell) note("cell is for a 3D scene; the scene is a polygon", "cell");
  if (o.plane) note("plane is for a 3D scene; the scene is a polygon", "plane");
}

void Model::apply3d(const Options& o, bool method3d) {
  Scene3D& s3 = scene3d();
  if (o.method && !method3d)
    note("'" + *o.method + "' is a 2D method; the scene is a polyhedron", "method");
  applyToScene(s3, o, o.method ? parseMethod3D(*o.method) : std::nullopt);
  if (o.slice) s3.setSlice(*o.slice);
  if (o.probe3) s3.place(*o.probe3);
  if (o.camera.angles || o.camera.distance || o.camera.look) pendingCamera = o.camera;
  if (o.cell) {
    if (*o.cell < s3.cells().size())
      s3.pin(static_cast<std::ptrdiff_t>(*o.cell));
    else
      note(cellProblem(*o.cell, s3.cells().size()), "cell");
  }
  if (o.probe) note("probe X,Y is for a 2D scene; the scene is a polyhedron (give X,Y,Z)", "probe");
  if (o.hover) note("hover is for a 2D scene; the scene is a polyhedron", "hover");
  if (o.line) note("line is for a 2D scene; the scene is a polyhedron (see plane)", "line");
  // the Planes mode with the plane asked
  if (o.plane) {
    setPlanesMode(true);
    const auto& q = *o.plane;
    planes3d.setPlane(q[0], q[1], q[2]);
  }
}

void Model::applyFigureOptions(const Options& o) {
  if (o.yGap) settings.view2d.showGap = true;
  if (o.hideSlice) settings.view3d.showSlice = false;
  if (dim != Dim::Three || (!o.cellAuto && !o.cellSecond)) return;
  Scene3D& s3 = scene3d();
  if (o.cellAuto) {
    const auto [one, many] = s3.typicalCells();
    s3.pin(one);
    s3.pinSecond(many);
  } else if (*o.cellSecond < s3.cells().size()) {
    s3.pinSecond(static_cast<std::ptrdiff_t>(*o.cellSecond));
  } else {
    note(cellProblem(*o.cellSecond, s3.cells().size()), "cell");
  }
}

void Model::applyTeachingViews(const Options& o) {
  whySolid = o.whyPage.empty() ? dim == Dim::Three : o.whyPage == "3d";
  if (!o.whyFrom.empty()) {
    std::string problem;
    whyOpen = showScalingRecord(o.whyFrom, *scaling, problem);
    if (!whyOpen) note("why-from: " + problem, "why-from");
  } else if (o.why) {
    whyOpen = true;
    scaling->start(scalingConfig(o.whyMost));
    // a screenshot shows the finished plots
    if (!o.screenshot.empty()) scaling->wait();
  }
  if (o.split) {
    if (const auto m = parseMethod2D(*o.split)) {
      split.setEnabled(dim == Dim::Two);
      split.setMethod(*m);
      split.sync(scene2d);
    } else {
      note("split needs a 2D method (halfplane, wedge, slab, uniform, polar)", "split");
    }
  }
  if (o.buildStep) {
    const std::size_t steps = dim == Dim::Two ? buildStepCount(scene2d) : buildStepCount(scene3d());
    build.active = steps > 0;
    build.show(*o.buildStep, steps);
  }
}

}  // namespace convexloc::viewer
