// convexloc-viewer — the scene on the GPU.
#include "gl/scene_view.hpp"

#include <cmath>

#include "logic/structure2d.hpp"

namespace convexloc::viewer {
namespace {

bool sameOptions(const View2DOptions& a, const View2DOptions& b) {
  return a.showStructure == b.showStructure && a.showTints == b.showTints &&
         a.showBox == b.showBox && a.showOctants == b.showOctants &&
         a.showLabels == b.showLabels && a.showHandles == b.showHandles;
}

// the camera has wandered so far from the origin, in pixels, that floats would blur
constexpr double kRebasePixels = 1e5;

}  // namespace

void SceneView::sync(const Model& model, Renderer& renderer) {
  const Scene2D& scene = model.scene2d;
  const Versions& v = scene.versions();
  const Palette& pal = paletteFor(model.settings.theme);
  const View2DOptions& opt = model.settings.view2d;

  bool rebase = false;
  if (first_ || v.shape != shape_) {
    const Box2 b = scene.polygon().bounds();
    origin_ = {0.5 * b.lo.x + 0.5 * b.hi.x, 0.5 * b.lo.y + 0.5 * b.hi.y, 0.0};
    rebase = true;
  }
  const glm::dvec2 c = model.camera2d.centre();
  const double drift = glm::length(c - glm::dvec2(origin_)) * model.camera2d.scale();
  if (drift > kRebasePixels) {
    origin_ = {c.x, c.y, 0.0};
    rebase = true;
  }

  const bool restyle = first_ || theme_ != model.settings.theme || !sameOptions(options_, opt);
  if (rebase || restyle || v.structure != structureV_ || v.shape != shape_) {
    buildStructure2D(scene, pal, opt, structure_);
    renderer.upload(Layer::Structure, structure_, origin_);
  }
  if (rebase || restyle || v.overlay != overlayV_ || v.structure != structureV_) {
    buildOverlay2D(scene, pal, opt, overlay_);
    renderer.upload(Layer::Overlay, overlay_, origin_);
  }
  if (rebase || v.points != points_) renderer.uploadPoints(scene.points(), scene.classes(), origin_);

  shape_ = v.shape;
  structureV_ = v.structure;
  overlayV_ = v.overlay;
  points_ = v.points;
  theme_ = model.settings.theme;
  options_ = opt;
  first_ = false;
}

void SceneView::draw(const Model& model, Renderer& renderer, glm::vec2 fbSize, float pixelRatio) {
  const Palette& pal = paletteFor(model.settings.theme);
  const Camera2D& cam = model.camera2d;
  FrameParams f;
  f.clipFromLocal = cam.clipFromLocal(glm::dvec2(origin_));
  f.framebuffer = fbSize;
  f.pixelRatio = pixelRatio;
  const glm::dvec2 vp = cam.viewport();
  pointSize_ = model.settings.pointSize > 0.0f
                   ? model.settings.pointSize
                   : autoPointSize(model.scene2d.points().size(), 0.6 * vp.x * vp.y);
  f.pointSize = pointSize_;
  f.visibleMask = model.settings.visibleMask;
  f.classColours[0] = pal.inside;
  f.classColours[1] = pal.boundary;
  f.classColours[2] = pal.outside;
  f.rim = pal.rim;
  f.depth = false;

  renderer.drawFills(Layer::Structure, f);
  renderer.drawSegments(Layer::Structure, f);
  renderer.drawPoints(f);
  renderer.drawMarkers(Layer::Structure, f);
  renderer.drawFills(Layer::Overlay, f);
  renderer.drawSegments(Layer::Overlay, f);
  renderer.drawMarkers(Layer::Overlay, f);
}

}  // namespace convexloc::viewer
