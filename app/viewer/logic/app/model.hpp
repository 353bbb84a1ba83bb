// convexloc-viewer — everything the app shows, GL-free: which scene (2D now, 3D beside it),
// its camera, the view settings, recent files and the last error. The UI edits it, the
// interaction moves it, the renderer draws it.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "logic/app/options.hpp"
#include "logic/base/colour.hpp"
#include "logic/draw/structure2d.hpp"
#include "logic/draw/structure3d.hpp"
#include "logic/dual/lines2d.hpp"
#include "logic/dual/planes3d.hpp"
#include "logic/narration/steps.hpp"
#include "logic/scene/scene2d.hpp"
#include "logic/scene/scene3d.hpp"
#include "logic/scene/second_view.hpp"
#include "logic/teach/build_anim.hpp"
#include "logic/teach/scaling.hpp"
#include "logic/view/camera2d.hpp"
#include "logic/view/camera3d.hpp"
#include "logic/view/picking.hpp"
#include "logic/view/scene_labels.hpp"

namespace convexloc::viewer {

// which scene is shown
enum class Dim : std::uint8_t { Two, Three };

struct Settings {
  Theme theme = Theme::Dark;
  float fontScale = 1.0f;
  bool showUi = true;
  float pointSize = 0.0f;              // pixels; 0 chooses from the count and the window
  unsigned visibleMask = kAllClasses;  // which classes of sprayed points are drawn
  View2DOptions view2d;
  View3DOptions view3d;
  // the query step by step
  bool stepBoxVisible = true;  // the Steps window, also with the panels hidden
  bool paperMode = false;      // traces without the radius filter (the paper's query)
  // presentation: panels hidden (P, --present), a caption over the scene, the legend shown
  bool present = false;
  bool showLegend = true;
  std::string caption;
  // a slide's page (logic/teach/slide_layout.hpp): the user's text zoom over the slide's own
  // size (--font-scale with --lecture, + and -), and window pixels per page unit, 1 when no
  // slide is shown (the viewer then lays out in window pixels)
  float textZoom = 1.0f;
  // a HiDPI web page's pixel ratio (--ui-scale): in fontScale outside slides, not in a
  // lecture's zoom
  float uiScaleFactor = 1.0f;
  float pageScale = 1.0f;
  // the page's size in units (--page; a lecture's first slide sets it for the lecture)
  glm::dvec2 page{1920.0, 1080.0};
  bool pageGiven = false;  // the lecture (or --page) gave it: no upright page on a phone
  // the text's scale on screen: the slide's size, the zoom and the page's scale together
  float uiScale() const { return fontScale * textZoom * pageScale; }
  // how much line widths, marker sizes and label offsets grow: with the text
  float drawScale() const { return uiScale(); }
  // a lecture's slide card over the scene's top, in window pixels: the scene fits below it
  float slideCardHeight = 0.0f;
  // a narrow window (a phone's page): the panels are a drawer over the scene, shown while
  // `drawerOpen` (its button), and the scene keeps the whole width
  bool drawer = false;
  bool drawerOpen = false;
};

// the point diameter in pixels that keeps `count` points readable over `areaPx` pixels
float autoPointSize(std::size_t count, double areaPx);

// what Model::apply() could not do, and the option (a lecture's key, without "--") it comes from
struct ApplyProblem {
  std::string text;
  std::string key;
};

class Model {
 public:
  Model() = default;

  Dim dim = Dim::Two;
  Scene2D scene2d;
  // the 3D scene, made on first use (building it takes a moment)
  Scene3D& scene3d();
  // the 3D scene, which must have been made (hasScene3d())
  const Scene3D& scene3d() const { return *scene3d_; }
  bool hasScene3d() const { return scene3d_ != nullptr; }
  // shows the 2D or the 3D scene
  void show(Dim d);
  // the 2D scene's Lines mode (the dual problem)
  Lines2D lines2d;
  // turns the Lines mode on or off (the camera is fitted again: the dual view sits beside)
  void setLinesMode(bool on);
  // the 3D scene's Planes mode (the dual problem in 3D)
  Planes3D planes3d;
  // turns the Planes mode on or off (the camera is fitted again: the dual view sits beside)
  void setPlanesMode(bool on);
  Camera2D camera2d;
  Camera3D camera3d;
  Settings settings;
  std::vector<std::string> recent;  // files opened, newest first

  // === Why O(1), the split view, the build animation
  bool whyOpen = false;  // the Why O(1) window shows
  // its page: the geodesic spheres (3D) rather than the N-gons (--why-page, else the scene's)
  bool whySolid = false;
  // its measurement, in a worker thread (held apart so that the model stays movable)
  std::unique_ptr<ScalingWorker> scaling = std::make_unique<ScalingWorker>();
  SecondView split;     // 2D: a second method beside the current one
  BuildPlayback build;  // the cells receiving their edges (faces) one at a time
  // something moves without input (a measurement, the build playing): draw every frame
  bool busy() const { return (scaling && scaling->running()) || build.playing; }

  // Opens a shape file, chosen by extension (.txt polygon; .off/.obj/.stl/.ply polyhedron). On
  // failure the scene stays and error() says why (file and line where known).
  bool open(const std::string& path);
  // a degenerate-gallery shape; false and error() for an unknown name
  bool applyPreset(std::string_view name);
  // Applies the command line's scene settings (shape, method, spray, probe, ...). Returns
  // an empty string, or what went wrong (the scene then keeps what could be applied).
  std::string apply(const Options& o);
  // every problem the last apply() met, in order, each with the key it comes from
  const std::vector<ApplyProblem>& applyProblems() const { return problems_; }
  // Puts back the viewer's default scenes and drawing options (not the theme, the text
  // size, the panels or the recent files), so that what one slide set does not leak into
  // the next.
  void reset();

  // the camera is fitted to the shape at the next frame (the UI knows the free area)
  void requestFit() { fitPending_ = true; }
  bool takeFitRequest() {
    const bool f = fitPending_;
    fitPending_ = false;
    return f;
  }
  // fits the current scene's camera into `area`, or applies the asked 2D view; `tight`
  // (a slide's figure room) leaves a narrower margin around the figure
  void fit(ScreenRect area, bool tight = false);
  // what a fit holds in view: 2D the polygon, a placed point near it, a zoom inset's frame
  Box2 figureBox2() const;
  // 3D: turns the camera across a placed point's ray (logic/teach/query_view)
  void lookAcrossQuery();
  // 3D: the polyhedron's vertices and the cube's corners where the cube map is drawn
  std::vector<glm::dvec3> figurePoints3() const;
  // a 2D view to apply at the next fit instead: centre and width in world units
  std::optional<AskedView> pendingView;
  // a 3D view to apply at the next fit (a lecture's `camera`, `look`)
  std::optional<AskedCamera> pendingCamera;

  // === The placed point's query, step by step (the shown scene's)
  // the steps of the shown scene's placed point, none without one
  std::optional<StepModel> steps() const;
  // the step shown, clamped to the steps there are (-1: all)
  int step() const;
  // shows step `k` (clamped; -1: all)
  void setStep(int k);
  // the next or the previous step (from all shown: the first or the last)
  void stepBy(bool forward);
  // paper-faithful mode on or off in both scenes: the placed point traced again
  void setPaperMode(bool on);
  StepPlayer stepPlayer;

  // the last error shown to the user, from the model or a scene; the serial grows with each
  const std::string& error() const { return error_; }
  std::uint64_t errorSerial() const { return errorSerial_; }
  void fail(std::string message);
  // collects a scene's new error, if any (call once per frame)
  void collectErrors();

 private:
  void remember(const std::string& path);
  // the steps of apply(): the shape, then the scene's own options
  void applyShape(const Options& o, bool method3d);
  void applyGenerator(const Options& o, bool method3d);
  template <class Scene, class Method>
  void applyToScene(Scene& scene, const Options& o, std::optional<Method> method);
  void apply2d(const Options& o, bool method3d);
  void apply3d(const Options& o, bool method3d);
  // --y-gap, --slice none, --cell auto or K,L: the paper's figures
  void applyFigureOptions(const Options& o);
  // --why, --split, --build-step
  void applyTeachingViews(const Options& o);
  // a problem apply() reports, with the option (lecture key) it comes from, and a scene's last
  // error as one
  void note(const std::string& problem, std::string_view key);
  void noteSceneError(std::string_view key);
  std::vector<ApplyProblem> problems_;
  std::unique_ptr<Scene3D> scene3d_;
  std::uint64_t seen3d_ = 0;
  bool fitPending_ = true;
  std::string error_;
  std::uint64_t errorSerial_ = 0;
  std::uint64_t seen2d_ = 0;
};

// world to window pixels (and depth, in 3D) by the camera of the scene shown
ScreenProjection sceneProjection(const Model& model);

// 2D: a near-boundary spray's points hug the edges, so all are drawn over the lines (which
// would hide them), not only the boundary ones
inline bool pointsOverLines(const Model& model) {
  return model.dim == Dim::Two && model.scene2d.spraySettings().nearBoundary;
}

}  // namespace convexloc::viewer
