// convexloc-viewer — Why O(1), measured: every 2D method on regular N-gons of growing N,
// the mean predicates per query (core's trace: edge and ray tests) and the nanoseconds
// per query (core's batch locate); and the paper's uniform-slab memory against the
// smallest y-gap beside convexloc's bounded memory. The measurement runs in a worker
// thread that owns its own core objects; the UI reads a snapshot under a mutex. GL-free.
#pragma once

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "convexloc/locate2d.hpp"
#include "convexloc/locate3d.hpp"
#include "logic/base/colour.hpp"
#include "logic/teach/log_plot.hpp"
#include "logic/teach/slide_layout.hpp"

namespace convexloc::viewer {

// what a measurement covers
struct ScalingConfig {
  std::vector<std::size_t> sizes;  // N, ascending
  std::size_t tracedPoints = 300;  // random points traced per (method, N)
  std::size_t timedPoints = 1 << 14;
  double minSeconds = 0.02;           // each timing runs at least this long
  std::size_t linearLimit = 1 << 18;  // the O(N) method stops above this N
  std::vector<std::size_t> faces;     // 3D: F of the geodesic spheres, ascending
  std::size_t linearLimit3d = 81920;  // the O(F) method stops above this F
  std::uint64_t seed = 1;
};

// 8, 64, 512, ... (times 8) up to `most`, and `most` itself when it is not such a power
std::vector<std::size_t> scalingSizes(std::size_t most = 1000000);
// the 2D sizes up to `most` and the 3D ones (geodesicSizes) up to the same bound
ScalingConfig scalingConfig(std::size_t most);

// 20, 80, 320, ... (times 4: geodesic spheres) up to `most`, at most 327 680
std::vector<std::size_t> geodesicSizes(std::size_t most = 1000000);

// whether `m` is measured at N = n (the O(N) method stops above config.linearLimit)
bool measured(const ScalingConfig& config, Method2D m, std::size_t n);
// whether `m` is measured at F = f (the O(F) method stops above config.linearLimit3d)
bool measured(const ScalingConfig& config, Method3D m, std::size_t f);

// one method at one N
struct ScalingSample {
  std::size_t n = 0;
  double predicates = 0.0;  // mean edge and ray tests per traced query
  // polar: the mean edges the traced queries' cells list, what the paper's query tests
  // (its cells carry no radii); 0 for the other methods
  double cellEdges = 0.0;
  double nsPerQuery = 0.0;  // batch locate, wall clock
  std::size_t bytes = 0;    // the locator's memory
};

// one method over every N (F) it was measured at
template <class Method>
struct SeriesOf {
  Method method{};
  std::vector<ScalingSample> samples;
};
using ScalingSeries = SeriesOf<Method2D>;
using ScalingSeries3D = SeriesOf<Method3D>;

// the paper's uniform slabs against convexloc's bounded tables for one smallest y-gap
struct MemorySample {
  double gap = 0.0;         // the polygon's smallest positive difference of vertex y
  double paperSlabs = 0.0;  // (ymax - ymin) / gap
  double paperBytes = 0.0;  // paperSlabs * kPaperBytesPerSlab (logic/draw/y_gap.hpp)
  std::size_t uniformBytes = 0, polarBytes = 0;  // convexloc's, at core's resolution
};

struct ScalingResult {
  std::vector<ScalingSeries> series;      // one per 2D method, in kAllMethods2D order
  std::vector<ScalingSeries3D> series3d;  // one per 3D method (none when no F was asked)
  std::vector<MemorySample> memory;       // gaps 1e-1 .. 1e-9
};

// a regular n-gon's (method, N) measurement; `traced` and `timed` are its query points
ScalingSample measureMethod(const ConvexPolygon& polygon, Method2D m, std::span<const Vec2> traced,
                            std::span<const Vec2> timed, double minSeconds);

// a geodesic sphere's (method, F) measurement: plane and walk-edge tests, ns per query
ScalingSample measureMethod3D(const ConvexPolyhedron& polyhedron, Method3D m,
                              std::span<const Vec3> traced, std::span<const Vec3> timed,
                              double minSeconds);

// The memory comparison for one gap: a regular octagon plus a vertex `gap` above vertex 0
// on the same circle.
MemorySample measureMemory(double gap);

// how far a run has come, and what it has found so far
struct ScalingProgress {
  std::size_t done = 0, total = 0;  // measurements
  bool running = false, finished = false, cancelled = false;
  std::string current;  // "polar, N = 4 096"
  std::string error;
  ScalingResult result;
};

// Runs a measurement in its own thread; cancel() and the destructor stop and join it.
// Where no thread can start (the web page has none), step() measures one method at one
// size at a time on the caller's thread instead, a frame each.
// (it owns a thread, and its mutex keeps it from being copied or moved)
class ScalingWorker {
 public:
  ScalingWorker() = default;
  ~ScalingWorker();
  // Starts a run (a running one is cancelled first): in a thread, or, without `threaded` or
  // where no thread can start, by step() on the caller's thread.
  void start(ScalingConfig config, bool threaded = true);
  // a finished run's results, recorded earlier, shown as if just measured
  void show(ScalingConfig config, ScalingResult result);
  // asks the run to stop and waits for it
  void cancel();
  // waits for the run to end (without a thread: measures what is left, here)
  void wait();
  // without a thread: measures the run's next method at its size here; with one, or no
  // run: nothing
  void step();
  // a copy of the progress and the results so far
  ScalingProgress snapshot() const;
  const ScalingConfig& config() const { return config_; }
  // whether a run is under way (without taking the lock)
  bool running() const { return running_; }

 private:
  void run();
  // measures step k of the run (a 2D size, a 3D size, then the memory); false after the last
  bool runStep(std::size_t k);
  void runSize(std::size_t n);
  void runSize3D(std::size_t f);
  // measures every method of `methods` allowed at `size` into `series`, under the lock
  template <class Method, class Measure>
  void runMethods(std::span<const Method> methods, std::size_t size,
                  std::vector<SeriesOf<Method>>& series, Measure measure);
  // measures methods[i] at `size` into series[i] when it is measured there
  template <class Method, class Measure>
  void measureOne(std::span<const Method> methods, std::size_t i, std::size_t size,
                  std::vector<SeriesOf<Method>>& series, Measure& measure);
  // without a thread: the next method at the current size, or the memory; false after it
  bool stepOne();
  // the next of `methods` at `size`, its shape and points made by `make` at the first
  template <class Method, class Make>
  bool stepMethod(std::span<const Method> methods, std::size_t size,
                  std::vector<SeriesOf<Method>>& series,
                  std::function<ScalingSample(Method)>& measure, Make make);
  ScalingConfig config_;
  std::thread thread_;
  mutable std::mutex mutex_;
  ScalingProgress progress_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> running_{false};
  // without a thread (step() runs the steps): the size under way (2D, then 3D), the method
  // measured next there, and the size's shape and points
  bool inFrames_ = false;
  std::size_t nextStep_ = 0;
  std::size_t nextMethod_ = 0;
  std::function<ScalingSample(Method2D)> measure2d_;
  std::function<ScalingSample(Method3D)> measure3d_;
};

// === The plots

// the colour each method's curve is drawn in (Okabe and Ito's palette)
Rgba methodColour(Method2D m);
Rgba methodColour(Method3D m);
// predicates per query against N, one series per method
LogPlot predicatesPlot(const ScalingResult& r, const ScalingConfig& c);
// nanoseconds per query against N
LogPlot timePlot(const ScalingResult& r, const ScalingConfig& c);
// bytes against the smallest y-gap: the paper's uniform slabs, convexloc's uniform and polar
LogPlot memoryPlot(const ScalingResult& r);
// the plot style of a theme at `fontPx`
PlotStyle plotStyle(Theme theme, double fontPx);
// planes (and walk edges) tested per query against F, one series per 3D method
LogPlot predicatesPlot3D(const ScalingResult& r, const ScalingConfig& c);
// nanoseconds per query against F
LogPlot timePlot3D(const ScalingResult& r, const ScalingConfig& c);
// bytes of each 3D method's tables against F (the cube map's O(F) memory)
LogPlot memoryPlot3D(const ScalingResult& r, const ScalingConfig& c);
// The 2D page (`solid` false: predicates, time, memory, the summary) or the 3D page
// (predicates, time, memory, the summary) laid out `size` pixels large.
std::vector<PlotDrawing> scalingDrawings(const ScalingResult& r, const ScalingConfig& c,
                                         const PlotStyle& style, glm::dvec2 size,
                                         bool solid = false);
// a page as one standalone SVG document
std::string scalingSvg(const ScalingResult& r, const ScalingConfig& c, Theme theme,
                       bool solid = false);
// writes scalingSvg to `path`; false and `error` when the file cannot be written
bool writeScalingSvg(const std::string& path, const ScalingResult& r, const ScalingConfig& c,
                     Theme theme, std::string& error, bool solid = false);
// where the 3D page goes beside the 2D one: "x.svg" -> "x-3d.svg"
std::string solidSvgPath(const std::string& path);

// === On a slide (logic/teach/scaling_slide)

// the plots a slide's page holds side by side: predicates, time and memory
std::size_t slidePlotCount();
// a slide's plot style at `fontPx`: lines and marks grown with the text, the title not bold
PlotStyle slidePlotStyle(Theme theme, double fontPx);
// The 2D or 3D page as a slide's figure laid out by `l` (logic/teach/slide_layout): its plots
// with short labels and no notes, the measurement in one line under them, or `status` (a
// measurement under way) where not empty.
std::vector<PlotDrawing> slideDrawings(const ScalingResult& r, const ScalingConfig& c,
                                       const PlotStyle& style, const PlotsLayout& l, bool solid,
                                       const std::string& status = {});

}  // namespace convexloc::viewer
