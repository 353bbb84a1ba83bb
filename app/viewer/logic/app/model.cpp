// convexloc-viewer — the app's state.
#include "logic/app/model.hpp"

#include <algorithm>
#include <cmath>

#include "convexloc/generate2d.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/mesh_reader.hpp"
#include "logic/draw/zoom_inset.hpp"
#include "logic/scene/presets.hpp"
#include "logic/teach/query_view.hpp"
#include "logic/teach/scaling_record.hpp"

namespace convexloc::viewer {
namespace {

// the extension of a path, lower case, with its dot ("" when none)
std::string extensionOf(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return "";
  std::string ext = path.substr(dot);
  for (char& c : ext) c = static_cast<char>(c >= 'A' && c <= 'Z' ? c - 'A' + 'a' : c);
  return ext;
}

constexpr std::size_t kMaxRecent = 8;

}  // namespace

float autoPointSize(std::size_t count, double areaPx) {
  if (count == 0) return 5.0f;
  const double spacing = std::sqrt(std::max(areaPx, 1.0) / static_cast<double>(count));
  return static_cast<float>(std::clamp(0.32 * spacing, 1.5, 5.5));
}

void Model::fail(std::string message) {
  error_ = std::move(message);
  ++errorSerial_;
}

void Model::collectErrors() {
  if (scene2d.errorSerial() != seen2d_) {
    seen2d_ = scene2d.errorSerial();
    if (!scene2d.error().empty()) fail(scene2d.error());
  }
  if (scene3d_ && scene3d_->errorSerial() != seen3d_) {
    seen3d_ = scene3d_->errorSerial();
    if (!scene3d_->error().empty()) fail(scene3d_->error());
  }
}

Scene3D& Model::scene3d() {
  if (!scene3d_) {
    scene3d_ = std::make_unique<Scene3D>();
    seen3d_ = scene3d_->errorSerial();
    scene3d_->setTraceOptions({.radii = !settings.paperMode});
  }
  return *scene3d_;
}

void Model::show(Dim d) {
  if (d == dim) return;
  if (d == Dim::Three) scene3d();
  dim = d;
  requestFit();
}

void Model::remember(const std::string& path) {
  recent.erase(std::remove(recent.begin(), recent.end(), path), recent.end());
  recent.insert(recent.begin(), path);
  if (recent.size() > kMaxRecent) recent.resize(kMaxRecent);
}

bool Model::open(const std::string& path) {
  const std::string ext = extensionOf(path);
  const Dim d = meshFormatOf(ext).has_value() ? Dim::Three : Dim::Two;
  if (!(d == Dim::Three ? scene3d().loadFile(path) : scene2d.loadFile(path))) {
    collectErrors();
    return false;
  }
  dim = d;
  remember(path);
  requestFit();
  return true;
}

bool Model::applyPreset(std::string_view name) {
  const Preset* p = findPreset(name);
  if (!p) {
    fail("no preset named '" + std::string(name) + "'");
    return false;
  }
  if (p->solid) {
    const PolyhedronKind kind =
        name == "tiny-faces" ? PolyhedronKind::TinyFaces : PolyhedronKind::Coplanar;
    if (!scene3d().generate(kind, 200, 1)) {
      collectErrors();
      return false;
    }
    dim = Dim::Three;
    requestFit();
    return true;
  }
  const std::vector<Vec2> v = presetPolygon(name);
  if (!scene2d.setShape(
          v, std::string(p->title) + " (" + std::to_string(v.size()) + " input points)")) {
    collectErrors();
    return false;
  }
  if (p->method) scene2d.setMethod(*p->method);
  dim = Dim::Two;
  requestFit();
  return true;
}

// === Step by step

std::optional<StepModel> Model::steps() const {
  if (dim == Dim::Two) {
    if (!scene2d.probe()) return std::nullopt;
    return buildSteps(scene2d.probe()->trace, scene2d.probe()->point, scene2d.polygon());
  }
  if (!scene3d_ || !scene3d_->probe()) return std::nullopt;
  const Bounds3 b = scene3d_->bounds();
  return buildSteps3D(scene3d_->probe()->trace, scene3d_->probe()->point, glm::length(b.hi - b.lo));
}

int Model::step() const {
  const std::optional<StepModel> m = steps();
  if (!m) return -1;
  const int k = dim == Dim::Two ? scene2d.step() : scene3d_->step();
  return clampStep(k, m->steps.size());
}

void Model::setStep(int k) {
  const std::optional<StepModel> m = steps();
  const int shown = m ? clampStep(k, m->steps.size()) : k;
  if (dim == Dim::Two)
    scene2d.setStep(shown);
  else
    scene3d().setStep(shown);
}

void Model::stepBy(bool forward) {
  const std::optional<StepModel> m = steps();
  if (!m) return;
  stepPlayer.playing = false;
  setStep(nextStep(step(), m->steps.size(), forward));
}

void Model::setPaperMode(bool on) {
  settings.paperMode = on;
  scene2d.setTraceOptions({.radii = !on});
  if (scene3d_) scene3d_->setTraceOptions({.radii = !on});
}

void Model::reset() {
  const Versions seen2 = scene2d.versions();
  scene2d = Scene2D();
  scene2d.followVersions(seen2);
  seen2d_ = scene2d.errorSerial();
  if (scene3d_) {
    const Versions seen3 = scene3d_->versions();
    scene3d_ = std::make_unique<Scene3D>();
    scene3d_->followVersions(seen3);
    seen3d_ = scene3d_->errorSerial();
  }
  lines2d.clearLine();
  lines2d.setEnabled(false);
  dim = Dim::Two;
  settings.pointSize = 0.0f;
  settings.visibleMask = kAllClasses;
  settings.view2d = View2DOptions{};
  settings.view3d = View3DOptions{};
  settings.paperMode = false;  // the new scenes trace with the radius filter
  settings.caption.clear();
  pendingView.reset();
  pendingCamera.reset();
  // the teaching views a slide opened: the split, the build, Why O(1), the Planes mode
  split.setEnabled(false);
  build.active = build.playing = false;
  ++build.version;
  if (whyOpen) scaling->cancel();
  whyOpen = whySolid = false;
  planes3d.setEnabled(false);
  requestFit();
}

// === The Lines and Planes modes, the figure fit

void Model::setLinesMode(bool on) {
  lines2d.setEnabled(on);
  lines2d.sync(scene2d);
  requestFit();
}

void Model::setPlanesMode(bool on) {
  planes3d.setEnabled(on);
  if (on) planes3d.sync(scene3d());
  requestFit();
}

Box2 Model::figureBox2() const {
  if (lines2d.enabled()) return lines2d.inset().both();  // the polygon and its dual beside
  // a placed point up to one polygon size off it (a slide's probe) is fitted in view too
  Box2 box = scene2d.polygon().bounds();
  if (const auto& p = scene2d.probe(); p && !lines2d.enabled()) {
    const double w = box.hi.x - box.lo.x, h = box.hi.y - box.lo.y;
    const Vec2 q = p->point;
    if (q.x >= box.lo.x - w && q.x <= box.hi.x + w && q.y >= box.lo.y - h && q.y <= box.hi.y + h)
      box = {{std::min(box.lo.x, q.x), std::min(box.lo.y, q.y)},
             {std::max(box.hi.x, q.x), std::max(box.hi.y, q.y)}};
  }
  // a zoom inset beside the polygon (tiny edges) is fitted in view too
  if (const auto inset = tinyEdgesInset(scene2d.polygon());
      inset && !lines2d.enabled() && settings.view2d.zoomInset)
    box = {{std::min(box.lo.x, inset->frame.lo.x), std::min(box.lo.y, inset->frame.lo.y)},
           {std::max(box.hi.x, inset->frame.hi.x), std::max(box.hi.y, inset->frame.hi.y)}};
  return box;
}

std::vector<glm::dvec3> Model::figurePoints3() const {
  std::vector<glm::dvec3> points;
  if (!hasScene3d()) return points;
  const Scene3D& s = scene3d();
  for (const Vec3 v : s.polyhedron().vertices()) points.push_back({v.x, v.y, v.z});
  if (planes3d.enabled()) {  // the dual beside (on the unit sphere there), no cube
    const DualPlace3D& at = planes3d.place();
    for (int k = 0; k < 26; ++k) {
      const glm::dvec3 d(k % 3 - 1, k / 3 % 3 - 1, k / 9 - 1);
      if (k != 13) points.push_back(at.middle + at.scale * glm::normalize(d));
    }
    return points;
  }
  if (const double h = s.cubeHalfSize(); h > 0.0 && s.centre() && settings.view3d.showCube)
    for (int k = 0; k < 8; ++k)
      points.push_back(toGlm(*s.centre()) +
                       h * glm::dvec3(k & 1 ? 1 : -1, k & 2 ? 1 : -1, k & 4 ? 1 : -1));
  return points;
}

void Model::lookAcrossQuery() {
  const auto& probe = scene3d().probe();
  if (!probe || !probe->trace.centre || planes3d.enabled()) return;
  const glm::dvec3 c = toGlm(*probe->trace.centre), x = toGlm(probe->point);
  if (const auto exit = rayExitFace(scene3d().polyhedron(), c, x))
    camera3d.lookAlong(viewAcrossRay(c, x, exit->normal));
}

void Model::fit(ScreenRect area, bool tight) {
  if (dim == Dim::Two && split.enabled() && !lines2d.enabled()) {
    // the split view: the camera is fitted to the left half; the right one follows it
    split.setArea(area);
    area = split.left();
  }
  if (dim == Dim::Two) {
    lines2d.sync(scene2d);
    // a slide's halves: a narrower margin (the headings take a band over them)
    const bool halves = split.enabled() && !lines2d.enabled();
    camera2d.fit(figureBox2(), area, tight ? (halves ? (split.stacked() ? 0.08 : 0.05) : 0.09) : 0.13);
    if (pendingView) {
      // the asked centre at the area's middle, the asked width across it
      const double scale = area.size().x / pendingView->width;
      camera2d.set({pendingView->centre.x, pendingView->centre.y}, scale);
      camera2d.pan(area.middle() - 0.5 * camera2d.viewport());
      pendingView.reset();
    }
    return;
  }
  // the polyhedron and the cube the cells are drawn on
  Scene3D& s = scene3d();
  Bounds3 b = s.bounds();
  if (const double h = s.cubeHalfSize(); h > 0.0 && s.centre()) {
    const glm::dvec3 c = toGlm(*s.centre());
    b.lo = glm::min(b.lo, c - h);
    b.hi = glm::max(b.hi, c + h);
  }
  // the Planes mode: the dual view beside, along the camera's right
  if (planes3d.enabled()) {
    planes3d.sync(s);
    planes3d.placeDual(camera3d.right());
    // the polyhedron and its dual side by side: fitted by their corners, filling the area
    const DualPlace3D& at = planes3d.place();
    const Bounds3 boxes[] = {planes3d.box(),
                             {at.middle - glm::dvec3(at.scale), at.middle + glm::dvec3(at.scale)}};
    camera3d.fitCorners(boxes, area);
    if (tight) camera3d.fitPoints(figurePoints3(), area, 0.88);
    return;
  }
  // the asked angles, else on a slide a query seen across its ray, its exit face in front
  if (pendingCamera && pendingCamera->angles) {
    const glm::dvec2 a = glm::radians(*pendingCamera->angles);
    camera3d.lookAlong(
        -glm::dvec3(std::cos(a.y) * std::cos(a.x), std::cos(a.y) * std::sin(a.x), std::sin(a.y)));
  } else if (tight) {
    lookAcrossQuery();
  }
  camera3d.fit(b, area);
  // a slide: the figure as drawn, not its bounding sphere, fills the room
  if (tight) camera3d.fitPoints(figurePoints3(), area, 0.88);
  if (pendingCamera) camera3d.applyAsked(*pendingCamera);
}

ScreenProjection sceneProjection(const Model& model) {
  if (model.dim == Dim::Two)
    return [cam = model.camera2d](glm::dvec3 p) -> std::optional<glm::dvec3> {
      return glm::dvec3(cam.toScreen({p.x, p.y}), 0.0);
    };
  return [cam = model.camera3d](glm::dvec3 p) -> std::optional<glm::dvec3> {
    const Projected q = cam.toScreen(p);
    if (!q.visible()) return std::nullopt;
    return glm::dvec3(q.screen, q.w);
  };
}

}  // namespace convexloc::viewer
