// convexloc-viewer — what the 2D and the 3D scene share: the shape and its label, the
// method and its locator (cells, statistics), the spray and its classes, the placed point
// and its trace, the last error, the version counters, and the timing of every method.
//
// A scene is a SceneState over its dimension's traits (Traits2D in scene2d.hpp, Traits3D
// in scene3d.hpp). Every class and every cell comes from core's locator; the scene keeps
// them and bumps a version counter for each part that changed, so that drawing rebuilds
// only that part. A failed change (a shape core refuses, a locator it cannot build) keeps
// the last good state and leaves the reason in error().
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <new>
#include <optional>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/geometry.hpp"
#include "convexloc/methods.hpp"

namespace convexloc::viewer {

// what a spray asks for
struct SpraySettings {
  std::size_t count = 2000;
  std::uint64_t seed = 1;
  bool nearBoundary = false;  // core's hard cases on and next to the boundary
};

// counters bumped when a part changes, so that drawing rebuilds only that part
struct Versions {
  std::uint64_t shape = 0;      // the shape
  std::uint64_t structure = 0;  // the locator and its cells (bumped with the shape too)
  std::uint64_t points = 0;     // the spray or its classes
  std::uint64_t overlay = 0;    // probe, hover, drag, pinned cell
  std::uint64_t section = 0;    // 3D: the slicing plane's section
};

// above this many cells a subdivision is not drawn (nor hovered): its statistics still are
inline constexpr std::size_t kMaxDrawnCells = std::size_t{1} << 18;

// one method timed by `compare`
template <class Method>
struct MethodTiming {
  Method method{};
  std::size_t points = 0;  // how many of the spray were located in the time budget
  double nsPerPoint = 0.0;
  double buildMs = 0.0;
  std::size_t bytes = 0;
  std::size_t cells = 0;
  std::size_t disagreements = 0;  // answers differing from the current method's (0 expected)
};

// the point placed by a click, and what the locator did with it
template <class Point, class Trace>
struct PlacedPoint {
  Point point{};
  Trace trace;
};

// the file name of a path, for labels
std::string baseName(const std::string& path);

// the types a dimension's scene is made of, for its traits
template <class PointT, class ShapeT, class LocatorT, class CellT, class StatsT, class MethodT,
          class TraceT>
struct SceneTypes {
  using Point = PointT;
  using Shape = ShapeT;
  using Locator = LocatorT;
  using Cell = CellT;
  using Stats = StatsT;
  using Method = MethodT;
  using Trace = TraceT;
};

// The state both scenes keep, over the traits of a dimension: its types (Point, Shape,
// Locator, Cell, Stats, Method, Trace), its methods (kMethods, kDefaultMethod), where a
// method keeps its resolution (kSlots, slot(m), compareResolution), how to spray and read
// a shape (sprayPoints, readShape), and the compare spray's size and chunk.
template <class Traits>
class SceneState {
 public:
  using Point = typename Traits::Point;
  using Shape = typename Traits::Shape;
  using Locator = typename Traits::Locator;
  using Cell = typename Traits::Cell;
  using Stats = typename Traits::Stats;
  using Method = typename Traits::Method;
  using Probe = PlacedPoint<Point, typename Traits::Trace>;
  using Timing = MethodTiming<Method>;
  // every method of the dimension, in order
  static constexpr std::span<const Method> kMethods = Traits::kMethods;

  virtual ~SceneState() = default;

  // === Shape
  // a shape file; false and error() (file and line where known) when it cannot be used
  bool loadFile(const std::string& path);
  // what the shape is, in words ("random, 16 vertices, seed 7", a file name)
  const std::string& label() const { return label_; }

  // === Method
  // switches the locator; on a method core cannot build, keeps the last and sets error()
  void setMethod(Method m);
  Method method() const { return method_; }
  // The method's resolution, 0 = chosen by core. On a value core refuses, keeps the
  // locator, returns false and sets error(). A resolution set here stays for new shapes;
  // the default scene's goes back to core's choice when another shape comes.
  bool setResolution(std::uint32_t r);
  std::uint32_t resolution() const { return resolution_[Traits::slot(method_)]; }
  const Locator& locator() const { return *locator_; }
  // the cells, as core reports them; empty when there are more than kMaxDrawnCells
  const std::vector<Cell>& cells() const { return cells_; }
  // the locator has cells, but too many to draw
  bool cellsOmitted() const { return stats_.cells > cells_.size(); }
  const Stats& stats() const { return stats_; }

  // === Spray
  void spray(const SpraySettings& s);
  void clearSpray();
  const SpraySettings& spraySettings() const { return spray_; }
  std::span<const Point> points() const { return points_; }
  std::span<const Location> classes() const { return classes_; }
  // points per class, indexed by Location
  const std::array<std::size_t, 3>& counts() const { return counts_; }
  // nanoseconds per point of the last batch classification
  double locateNsPerPoint() const { return locateNsPerPoint_; }

  // === Probe: a placed point and its trace
  void place(Point p);
  void clearProbe();
  const std::optional<Probe>& probe() const { return probe_; }

  // === Steps: how the placed point is traced, and which of its steps is shown
  // traces without the radius filter (the paper's query) when `radii` is false; retraces
  void setTraceOptions(TraceOptions options);
  // the step of the placed point's query shown, -1 for all (clamped where it is drawn)
  void setStep(int step);
  int step() const { return step_; }

  // === Compare: every method timed on the current spray (a temporary one when empty),
  // at most about `secondsPerMethod` each, and checked against the current method
  std::vector<Timing> compare(double secondsPerMethod = 0.12) const;

  // === Errors: the last problem, for the UI; `errorSerial` grows with each new one
  const std::string& error() const { return error_; }
  std::uint64_t errorSerial() const { return errorSerial_; }
  void setError(std::string message);

  const Versions& versions() const { return versions_; }
  // every part counted as changed since `before`: a fresh scene put in place of another
  void followVersions(const Versions& before) {
    versions_ = {before.shape + 1, before.structure + 1, before.points + 1, before.overlay + 1,
                 before.section + 1};
  }

 protected:
  // Builds the locator of the current shape, method and resolution again, then what
  // depends on it (the scene's own cell choices, the classes, the trace); false and
  // error() when core refuses, the last locator staying.
  bool rebuildLocator();
  // the scene's own state that hangs on the cells, brought up to date with new ones
  virtual void cellsChanged() = 0;
  // makes a validated shape the scene's (a new shape, not an edit)
  virtual bool adoptShape(Shape shape, std::string label) = 0;
  // forgets a cell the user chose, before the cells change
  virtual void dropChosenCell() {}

  // the batch classification of the spray, its counts and its time
  void classify();
  // the placed point traced again by the current locator
  void retrace();
  // Runs `step`; an Error or an allocation failure becomes error(), named after `source`.
  template <class Step>
  bool guarded(const std::string& source, Step&& step) {
    try {
      return step();
    } catch (const Error& e) {
      setError(located(source, e.line(), e.what()));
    } catch (const std::bad_alloc&) {
      setError(source.empty() ? "out of memory" : source + ": out of memory");
    }
    return false;
  }

  // Puts `shape` in place and rebuilds; a `fresh` shape (not an edit) gets core's
  // resolution wherever the user chose none. On failure the previous shape and
  // resolutions stay.
  bool swapShape(Shape shape, std::string label, bool fresh);

  std::optional<Shape> shape_;
  std::string label_;
  Method method_ = Traits::kDefaultMethod;
  std::array<std::uint32_t, Traits::kSlots> resolution_{};
  std::array<bool, Traits::kSlots> chosen_{};  // the resolution was set through setResolution
  std::optional<Locator> locator_;
  std::vector<Cell> cells_;
  Stats stats_;

  SpraySettings spray_;
  std::vector<Point> points_;
  std::vector<Location> classes_;
  std::array<std::size_t, 3> counts_{};
  double locateNsPerPoint_ = 0.0;

  std::optional<Probe> probe_;
  TraceOptions traceOptions_;  // how the placed point is traced
  int step_ = -1;              // its step shown, -1 for all

  std::string error_;
  std::uint64_t errorSerial_ = 0;
  Versions versions_;
};

// the shape files the viewer opens (.txt polygons, .off and .obj polyhedra) in `dir`, points
// files left out, sorted; none when `dir` cannot be read
std::vector<std::string> shapeFilesIn(const std::string& dir);

}  // namespace convexloc::viewer
