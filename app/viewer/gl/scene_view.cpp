// convexloc-viewer — the scene on the GPU.
#include "gl/scene_view.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>

#include "logic/draw/snap_indicator.hpp"
#include "logic/draw/structure2d.hpp"
#include "logic/draw/structure3d.hpp"
#include "logic/dual/dual_view2d.hpp"
#include "logic/dual/dual_view3d.hpp"
#include "logic/teach/build_anim.hpp"

namespace convexloc::viewer {
namespace {

bool same(const View2DOptions& a, const View2DOptions& b) {
  return a.showStructure == b.showStructure && a.showTints == b.showTints &&
         a.showBox == b.showBox && a.showOctants == b.showOctants && a.showLabels == b.showLabels &&
         a.showHandles == b.showHandles && a.zoomInset == b.zoomInset;
}

bool same(const View3DOptions& a, const View3DOptions& b) {
  return a.showMesh == b.showMesh && a.transparent == b.transparent && a.wireframe == b.wireframe &&
         a.showCube == b.showCube && a.showTints == b.showTints && a.showSlice == b.showSlice &&
         a.showLabels == b.showLabels && a.faceNames == b.faceNames;
}

// the camera has wandered so far from the origin, in pixels, that floats would blur
constexpr double kRebasePixels = 1e5;

// `from`'s fills, segments, markers and labels after `to`'s
void append(DrawList& to, const DrawList& from) {
  to.fills.insert(to.fills.end(), from.fills.begin(), from.fills.end());
  to.segments.insert(to.segments.end(), from.segments.begin(), from.segments.end());
  to.markers.insert(to.markers.end(), from.markers.begin(), from.markers.end());
  to.labels.insert(to.labels.end(), from.labels.begin(), from.labels.end());
}

void classColours(const Palette& pal, FrameParams& f) {
  f.classColours[0] = pal.inside;
  f.classColours[1] = pal.boundary;
  f.classColours[2] = pal.outside;
  f.rim = pal.rim;
}

}  // namespace

void SceneView::sync(Model& model, Renderer& renderer) {
  const bool dimChanged = first_ || model.dim != dim_;
  const bool restyle =
      dimChanged || theme_ != model.settings.theme || !same(options2_, model.settings.view2d) ||
      !same(options3_, model.settings.view3d) || linesShown_ != model.lines2d.enabled() ||
      planesShown_ != model.planes3d.enabled();
  if (dimChanged) {
    seen_ = {~0ull, ~0ull, ~0ull, ~0ull, ~0ull};
    mesh_.clear();
    section_.clear();
    renderer.upload(Layer::Mesh, mesh_, origin_);
    renderer.upload(Layer::Section, section_, origin_);
    ++uploads_;
  }
  if (restyle) ++uploads_;
  if (model.dim == Dim::Two)
    sync2d(model, renderer, restyle);
  else
    sync3d(model, renderer, restyle);
  dim_ = model.dim;
  theme_ = model.settings.theme;
  options2_ = model.settings.view2d;
  options3_ = model.settings.view3d;
  linesShown_ = model.lines2d.enabled();
  planesShown_ = model.planes3d.enabled();
  first_ = false;
}

void SceneView::sync2d(const Model& model, Renderer& renderer, bool restyle) {
  const Scene2D& scene = model.scene2d;
  const Versions& v = scene.versions();
  const Palette& pal = paletteFor(model.settings.theme);
  const Lines2D& lines = model.lines2d;
  View2DOptions opt = model.settings.view2d;
  if (lines.enabled()) {
    // the Lines mode shows the dual's cells instead of the method's, and no handles
    opt.showStructure = opt.showTints = opt.showOctants = opt.showHandles = opt.showBox = false;
    opt.showCentre = false;
  }

  bool rebase = false;
  if (v.shape != seen_.shape || scene_ != &scene) {
    const Box2 b = scene.polygon().bounds();
    origin_ = {0.5 * b.lo.x + 0.5 * b.hi.x, 0.5 * b.lo.y + 0.5 * b.hi.y, 0.0};
    rebase = true;
  }
  const glm::dvec2 c = model.camera2d.centre();
  if (glm::length(c - glm::dvec2(origin_)) * model.camera2d.scale() > kRebasePixels) {
    origin_ = {c.x, c.y, 0.0};
    rebase = true;
  }
  const std::uint64_t build = model.build.active ? model.build.version : ~0ull;
  if (rebase || restyle || v.structure != seen_.structure || v.shape != seen_.shape ||
      build != buildSeen_) {
    buildStructure(model, opt);
    renderer.upload(Layer::Structure, structure_, origin_);
    ++uploads_;
    buildSeen_ = build;
  }
  syncSplit(model, renderer, opt, rebase || restyle);
  const bool linesStale = lines.version() != linesSeen_;
  linesSeen_ = lines.version();
  syncOverlayAndPoints(scene, renderer, rebase, restyle, linesStale, [&](DrawList& out) {
    if (!lines.enabled()) return buildOverlay2D(scene, pal, opt, out);
    out.clear();
    buildLines2D(lines, pal, opt.showLabels, out);
    snapIndicator(scene, pal, out);
  });
}

// === The split view and the build animation

bool SceneView::splitShown(const Model& model) {
  return model.dim == Dim::Two && model.split.enabled() && !model.lines2d.enabled();
}

glm::mat4 SceneView::splitClip(const Model& model) const {
  return model.split.rightCamera(model.camera2d).clipFromLocal(glm::dvec2(origin_));
}

// the split view: `draw` with the `left` layer over the left half, then with the `right`
// layer over the right half through the second camera
template <class Draw>
void SceneView::drawHalves(const Model& model, Renderer& renderer, const FrameParams& f, Layer left,
                           Layer right, Draw draw) const {
  renderer.clipTo(model.split.left(), f);
  draw(left, f);
  FrameParams g = f;
  g.clipFromLocal = splitClip(model);
  renderer.clipTo(model.split.right(), g);
  draw(right, g);
  renderer.clearClip();
}

void SceneView::buildStructure(const Model& model, const View2DOptions& opt) {
  const Palette& pal = paletteFor(model.settings.theme);
  if (!model.build.active) return buildStructure2D(model.scene2d, pal, opt, structure_);
  View2DOptions untinted = opt;
  untinted.showTints = false;
  buildStructure2D(model.scene2d, pal, untinted, structure_);
  DrawList step;
  buildAnimation2D(model.scene2d, model.build.step, pal, step);
  appendBuildStep(structure_, step);
}

void SceneView::syncSplit(const Model& model, Renderer& renderer, const View2DOptions& opt,
                          bool force) {
  if (!splitShown(model)) {
    if (splitDrawn_) {
      splitStructure_.clear();
      splitOverlay_.clear();
      renderer.upload(Layer::SplitStructure, splitStructure_, origin_);
      renderer.upload(Layer::SplitOverlay, splitOverlay_, origin_);
      ++uploads_;
    }
    splitDrawn_ = false;
    return;
  }
  const Scene2D& s = model.split.scene();
  const Versions& v = s.versions();
  const Palette& pal = paletteFor(model.settings.theme);
  const bool fresh = !splitDrawn_ || force || v.structure != splitSeen_.structure;
  if (fresh) {
    buildStructure2D(s, pal, opt, splitStructure_);
    renderer.upload(Layer::SplitStructure, splitStructure_, origin_);
    ++uploads_;
  }
  if (fresh || v.overlay != splitSeen_.overlay) {
    buildOverlay2D(s, pal, opt, splitOverlay_);
    renderer.upload(Layer::SplitOverlay, splitOverlay_, origin_);
  }
  splitSeen_ = v;
  splitDrawn_ = true;
}

void SceneView::sync3d(Model& model, Renderer& renderer, bool restyle) {
  Scene3D& scene = model.scene3d();
  const Versions& v = scene.versions();
  const Palette& pal = paletteFor(model.settings.theme);
  View3DOptions opt = model.settings.view3d;
  Planes3D& planes = model.planes3d;
  planes.sync(scene);
  if (planes.enabled()) {
    // the Planes mode shows the dual's cube map instead of the method's, its plane instead
    // of the slicing plane
    opt.showCube = opt.showTints = opt.showSlice = false;
  }
  const bool planesStale = planes.version() != planesSeen_;
  planesSeen_ = planes.version();

  const bool reshape = v.shape != seen_.shape || scene_ != &scene;
  if (reshape) origin_ = scene.bounds().middle();
  if (reshape || restyle) {
    buildMesh3D(scene, pal, opt, mesh_);
    renderer.upload(Layer::Mesh, mesh_, origin_);
    ++uploads_;
  }
  // the cube faces seen from inside change only when the eye crosses one's plane
  const unsigned far = farCubeFaces(scene, model.camera3d.eye());
  const std::uint64_t build = model.build.active ? model.build.version : ~0ull;
  if (reshape || restyle || v.structure != seen_.structure || far != farFaces_ ||
      build != buildSeen_) {
    View3DOptions noSlice = opt;
    noSlice.showSlice = false;                                 // the section has its own layer
    noSlice.showTints = opt.showTints && !model.build.active;  // the build tints instead
    buildStructure3D(scene, pal, noSlice, far, structure_);
    if (model.build.active) {
      DrawList step;
      buildAnimation3D(scene, model.build.step, far, pal, step);
      appendBuildStep(structure_, step);
    }
    buildSeen_ = build;
    farFaces_ = far;
    ++uploads_;
    renderer.upload(Layer::Structure, structure_, origin_);
  }
  if (reshape || restyle || v.section != seen_.section || v.structure != seen_.structure ||
      planesStale) {
    section_.clear();
    planesOverlay_.clear();
    if (planes.enabled()) {
      buildPlanes3D(planes, pal, opt.showLabels, section_, planesOverlay_);
    } else if (opt.showSlice) {
      // the section alone, so that moving the plane rebuilds only it
      DrawList all;
      View3DOptions only;
      only.wireframe = only.showCube = only.showLabels = false;
      buildStructure3D(scene, pal, only, 0, all);
      section_.fills = std::move(all.fills);
      section_.segments = std::move(all.segments);
    }
    renderer.upload(Layer::Section, section_, origin_);
    ++uploads_;
  }
  syncOverlayAndPoints(scene, renderer, reshape, restyle, planesStale, [&](DrawList& out) {
    // the Planes mode draws its own marks instead of the method's cells and placed point
    if (!planes.enabled()) return buildOverlay3D(scene, pal, opt, out);
    out.clear();
    append(out, planesOverlay_);
  });
}

template <class Scene, class BuildOverlay>
void SceneView::syncOverlayAndPoints(const Scene& scene, Renderer& renderer, bool moved,
                                     bool restyle, bool overlayStale, BuildOverlay buildOverlay) {
  const Versions& v = scene.versions();
  if (moved || restyle || overlayStale || v.overlay != seen_.overlay ||
      v.structure != seen_.structure) {
    buildOverlay(overlay_);
    renderer.upload(Layer::Overlay, overlay_, origin_);
  }
  if (moved || v.points != seen_.points) {
    renderer.uploadPoints(scene.points(), scene.classes(), origin_);
    ++uploads_;
  }
  seen_ = v;
  scene_ = &scene;
}

FrameParams SceneView::frameParams(Model& model, glm::vec2 fbSize, float pixelRatio) {
  const Palette& pal = paletteFor(model.settings.theme);
  FrameParams f;
  f.framebuffer = fbSize;
  f.pixelRatio = pixelRatio;
  f.lineScale = model.settings.drawScale();
  // the Lines mode hides the spray: the line and the dual are the subject
  f.visibleMask =
      model.dim == Dim::Two && model.lines2d.enabled() ? 0u : model.settings.visibleMask;
  // so does the Planes mode: the plane and the dual are the subject
  if (model.dim == Dim::Three && model.planes3d.enabled()) f.visibleMask = 0u;
  classColours(pal, f);
  // on a slide the points are sized for its page, then scaled with it (k = 1 off a slide)
  const double k = model.settings.pageScale;
  const auto sized = [k](float given, std::size_t count, glm::dvec2 vp) {
    return static_cast<float>(k) *
           (given > 0.0f ? given : autoPointSize(count, 0.6 * vp.x * vp.y / (k * k)));
  };
  if (model.dim == Dim::Two) {
    const Camera2D& cam = model.camera2d;
    f.clipFromLocal = cam.clipFromLocal(glm::dvec2(origin_));
    const glm::dvec2 vp = cam.viewport();
    pointSize_ = sized(model.settings.pointSize, model.scene2d.points().size(), vp);
  } else {
    const Camera3D& cam = model.camera3d;
    f.clipFromLocal = cam.clipFromLocal(origin_);
    f.eyeLocal = glm::vec3(cam.eye() - origin_);
    const glm::dvec2 vp = cam.viewport();
    pointSize_ = (model.settings.pointSize > 0.0f ? 1.0f : 0.8f) *
                 sized(model.settings.pointSize, model.scene3d().points().size(), vp);
  }
  f.pointSize = pointSize_;
  return f;
}

void SceneView::drawBase(Model& model, Renderer& renderer, glm::vec2 fbSize, float pixelRatio,
                         double frameBudgetMs) {
  FrameParams f = frameParams(model, fbSize, pixelRatio);
  const Rgba bg = paletteFor(model.settings.theme).background;
  const glm::mat4 right = splitShown(model) ? splitClip(model) : glm::mat4(0.0f);
  const BaseKey key{f.clipFromLocal, right,       fbSize,     uploads_,
                    f.visibleMask,   f.pointSize, f.lineScale};
  const std::size_t n = renderer.pointCount();
  if (!renderer.hasTarget()) {
    // no cache: the whole base, every frame
    drawBaseLayers(model, renderer, f);
    pointsDrawn_ = n;
    return;
  }
  if (!(cached_ && key == lastKey_ && !partial_)) {
    // moving: the camera changed since the last picture
    const bool moving = cached_ && key.clip != lastKey_.clip;
    f.maxPoints = moving && n > budget_ ? budget_ : n;
    renderer.bindTarget();
    glClearColor(bg.r, bg.g, bg.b, 1.0f);
    glDepthMask(GL_TRUE);
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    const auto t0 = std::chrono::steady_clock::now();
    drawBaseLayers(model, renderer, f);
    if (n > 100000) {
      // a heavy spray: learn how many points fit the frame budget
      glFinish();
      const double ms =
          std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
      const double perPoint = ms / static_cast<double>(std::max<std::size_t>(f.maxPoints, 1));
      budget_ = static_cast<std::size_t>(
          std::clamp(frameBudgetMs / std::max(perPoint, 1e-9), 20000.0, 1e9));
    }
    renderer.finishTarget();
    pointsDrawn_ = std::min(n, f.maxPoints);
    partial_ = pointsDrawn_ < n;
    lastKey_ = key;
    cached_ = true;
  }
  glViewport(0, 0, static_cast<GLsizei>(fbSize.x), static_cast<GLsizei>(fbSize.y));
  renderer.compositeTarget();
}

void SceneView::drawBaseLayers(Model& model, Renderer& renderer, const FrameParams& base) {
  FrameParams f = base;
  if (model.dim == Dim::Two) {
    // points over the cells' tints, under the lines and edges; boundary points over those
    // (all of them where they hug the edges)
    const bool over = pointsOverLines(model);
    const auto flat = [&](Layer layer, const FrameParams& g) {
      renderer.drawFills(layer, g);
      if (!over) renderer.drawPoints(g, PointRange::AllButBoundary);
      renderer.drawSegments(layer, g);
      renderer.drawPoints(g, over ? PointRange::All : PointRange::Boundary);
      renderer.drawMarkers(layer, g);
    };
    if (!splitShown(model)) return flat(Layer::Structure, f);
    return drawHalves(model, renderer, f, Layer::Structure, Layer::SplitStructure, flat);
  }
  const bool transparent = model.settings.view3d.transparent;
  // opaque faces first, pushed back a little so their edges draw over them
  f.depth = true;
  if (!transparent) {
    f.depthWrite = true;
    f.offset = true;
    renderer.drawFills(Layer::Mesh, f);
    f.offset = false;
  }
  // see-through things test depth but do not write it
  f.depthWrite = false;
  renderer.drawFills(Layer::Structure, f);
  renderer.drawFills(Layer::Section, f);
  renderer.drawSegments(Layer::Structure, f);
  renderer.drawSegments(Layer::Section, f);
  f.depthWrite = true;
  renderer.drawPoints(f);
  if (transparent) {
    // a convex shell: its far side, then its near side, is back to front
    f.depthWrite = false;
    renderer.drawFills(Layer::Mesh, f, Cull::Front);
    renderer.drawFills(Layer::Mesh, f, Cull::Back);
  }
  f.depth = false;
  f.depthWrite = false;
  renderer.drawMarkers(Layer::Structure, f);
}

void SceneView::drawOverlay(Model& model, Renderer& renderer, glm::vec2 fbSize, float pixelRatio) {
  // the overlay shows through everything
  FrameParams f = frameParams(model, fbSize, pixelRatio);
  f.depth = false;
  f.depthWrite = false;
  const auto overlay = [&](Layer layer, const FrameParams& g) {
    renderer.drawFills(layer, g);
    renderer.drawSegments(layer, g);
    renderer.drawMarkers(layer, g);
  };
  if (!splitShown(model)) return overlay(Layer::Overlay, f);
  drawHalves(model, renderer, f, Layer::Overlay, Layer::SplitOverlay, overlay);
}

}  // namespace convexloc::viewer
