// convexloc-viewer — Why O(1): the measurement and its worker thread.
#include "logic/teach/scaling.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>
#include <system_error>

#include "convexloc/error.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/timing.hpp"
#include "logic/base/format.hpp"
#include "logic/draw/y_gap.hpp"

namespace convexloc::viewer {
namespace {

// A method's measurement on `shape`, for runMethods: `measure` on the points `generate`
// makes of it, those traced (seed + 1) and those timed (seed + 2), made once for every method.
// It holds the shape, so that a measurement without a thread keeps it from step to step.
template <class Shape, class Generate, class Measure>
auto measurerOn(const ScalingConfig& c, std::shared_ptr<const Shape> shape, Generate generate,
                Measure measure) {
  auto traced = generate(*shape, c.tracedPoints, c.seed + 1, false);
  auto timed = generate(*shape, c.timedPoints, c.seed + 2, false);
  return [&c, shape, measure, traced = std::move(traced), timed = std::move(timed)](auto m) {
    return measure(*shape, m, traced, timed, c.minSeconds);
  };
}

// the measurer of every 2D method on core's regular n-gon
std::function<ScalingSample(Method2D)> measurer2D(const ScalingConfig& c, std::size_t n) {
  return measurerOn(c, std::make_shared<const ConvexPolygon>(
                           generatePolygon(PolygonKind::Regular, n, c.seed)),
                    generatePoints, measureMethod);
}

// the measurer of every 3D method on core's geodesic sphere of about f faces
std::function<ScalingSample(Method3D)> measurer3D(const ScalingConfig& c, std::size_t f) {
  return measurerOn(c, std::make_shared<const ConvexPolyhedron>(
                           generatePolyhedron(PolyhedronKind::Geodesic, f, c.seed)),
                    generatePoints3D, measureMethod3D);
}

// the batch locate's time per point over `timed`, in chunks until minSeconds have passed
template <class Locator, class Point>
double nsPerQuery(const Locator& locator, std::span<const Point> timed, double minSeconds) {
  constexpr std::size_t kChunk = 1024;
  std::vector<Location> out(std::min(kChunk, timed.size()));
  std::size_t located = 0, at = 0;
  const Clock::time_point t0 = Clock::now();
  double seconds = 0.0;
  do {
    const std::size_t k = std::min(kChunk, timed.size() - at);
    locator.locate(timed.subspan(at, k), std::span<Location>(out).first(k));
    located += k;
    at = at + k == timed.size() ? 0 : at + k;
    seconds = secondsSince(t0);
  } while (seconds < minSeconds);
  return seconds * 1e9 / static_cast<double>(std::max<std::size_t>(located, 1));
}

// the predicates one traced query evaluated
std::size_t testsOf(const Trace2D& t) {
  return t.edges.size() + t.rays.size();
}
std::size_t testsOf(const Trace3D& t) {
  return t.faces.size() + t.steps.size();
}

// a locator's mean tests per traced point, time per batch point and memory
template <class Locator, class Point>
ScalingSample measureWith(const Locator& locator, std::span<const Point> traced,
                          std::span<const Point> timed, double minSeconds) {
  ScalingSample s;
  std::size_t tests = 0;
  for (const Point p : traced) tests += testsOf(locator.trace(p));
  s.predicates =
      static_cast<double>(tests) / static_cast<double>(std::max<std::size_t>(traced.size(), 1));
  if (!timed.empty()) s.nsPerQuery = nsPerQuery(locator, timed, minSeconds);
  s.bytes = locator.stats().bytes;
  return s;
}

// The edges the paper's polar query tests for `points`, on average: those the point's cell
// lists (a crowded cell's bisection counted as its probes), none outside the box.
double meanCellEdges(const PolarLocator& polar, std::span<const Vec2> points) {
  const Box2 b = polar.box();
  double sum = 0.0;
  for (const Vec2 p : points) {
    const std::int64_t cell = polar.cellIndex(p);
    if (cell < 0 || p.x < b.lo.x || p.x > b.hi.x || p.y < b.lo.y || p.y > b.hi.y) continue;
    const auto k = static_cast<double>(polar.cellEdges(cell).size());
    sum += k > kCrowdedCell ? std::ceil(std::log2(k)) + 1.0 : k;
  }
  return sum / static_cast<double>(std::max<std::size_t>(points.size(), 1));
}

// the smallest positive difference of two vertex y, and the y range
struct YGaps {
  double gap = 0.0, span = 0.0;
};

YGaps yGaps(const ConvexPolygon& polygon) {
  std::vector<double> ys;
  for (const Vec2 v : polygon.vertices()) ys.push_back(v.y);
  std::sort(ys.begin(), ys.end());
  YGaps g{1e300, ys.back() - ys.front()};
  for (std::size_t i = 1; i < ys.size(); ++i)
    if (ys[i] > ys[i - 1]) g.gap = std::min(g.gap, ys[i] - ys[i - 1]);
  return g;
}

}  // namespace

std::vector<std::size_t> scalingSizes(std::size_t most) {
  std::vector<std::size_t> sizes;
  for (std::size_t n = 8; n <= most; n *= 8) sizes.push_back(n);
  if (sizes.empty() || sizes.back() != most) sizes.push_back(std::max<std::size_t>(most, 3));
  return sizes;
}

ScalingConfig scalingConfig(std::size_t most) {
  ScalingConfig c;
  c.sizes = scalingSizes(most);
  c.faces = geodesicSizes(most);
  return c;
}

std::vector<std::size_t> geodesicSizes(std::size_t most) {
  std::vector<std::size_t> sizes;
  for (std::size_t f = 20; f <= std::min<std::size_t>(most, 327680); f *= 4) sizes.push_back(f);
  return sizes;
}

bool measured(const ScalingConfig& config, Method2D m, std::size_t n) {
  return m != Method2D::Halfplane || n <= config.linearLimit;
}

bool measured(const ScalingConfig& config, Method3D m, std::size_t f) {
  return m != Method3D::Halfspace || f <= config.linearLimit3d;
}

ScalingSample measureMethod(const ConvexPolygon& polygon, Method2D m, std::span<const Vec2> traced,
                            std::span<const Vec2> timed, double minSeconds) {
  const Locator2D locator(polygon, m);
  ScalingSample s = measureWith(locator, traced, timed, minSeconds);
  s.n = polygon.size();
  if (const PolarLocator* polar = locator.get<PolarLocator>())
    s.cellEdges = meanCellEdges(*polar, traced);
  return s;
}

ScalingSample measureMethod3D(const ConvexPolyhedron& polyhedron, Method3D m,
                              std::span<const Vec3> traced, std::span<const Vec3> timed,
                              double minSeconds) {
  ScalingSample s = measureWith(Locator3D(polyhedron, m), traced, timed, minSeconds);
  s.n = polyhedron.faceCount();
  return s;
}

MemorySample measureMemory(double gap) {
  // the octagon's y are exactly -1, -s, 0, s, 1: the extra vertex sets the smallest gap
  const double h = std::sqrt(0.5);
  const std::vector<Vec2> v = {{1.0, 0.0}, {std::sqrt(1.0 - gap * gap), gap},
                               {h, h},     {0.0, 1.0},
                               {-h, h},    {-1.0, 0.0},
                               {-h, -h},   {0.0, -1.0},
                               {h, -h}};
  const ConvexPolygon polygon(v);
  const YGaps g = yGaps(polygon);
  MemorySample s;
  s.gap = g.gap;
  s.paperSlabs = std::ceil(g.span / g.gap);
  s.paperBytes = s.paperSlabs * kPaperBytesPerSlab;
  s.uniformBytes = Locator2D(polygon, Method2D::Uniform).stats().bytes;
  s.polarBytes = Locator2D(polygon, Method2D::Polar).stats().bytes;
  return s;
}

// === The worker

ScalingWorker::~ScalingWorker() {
  cancel();
}

void ScalingWorker::start(ScalingConfig config, bool threaded) {
  cancel();
  config_ = std::move(config);
  stop_ = false;
  {
    const std::lock_guard lock(mutex_);
    progress_ = {};
    progress_.running = true;
    for (const std::size_t n : config_.sizes)
      for (const Method2D m : kAllMethods2D) progress_.total += measured(config_, m, n) ? 1 : 0;
    for (const std::size_t f : config_.faces)
      for (const Method3D m : kAllMethods3D) progress_.total += measured(config_, m, f) ? 1 : 0;
    progress_.total += 1;  // the memory comparison
    for (const Method2D m : kAllMethods2D) progress_.result.series.push_back({m, {}});
    if (!config_.faces.empty())
      for (const Method3D m : kAllMethods3D) progress_.result.series3d.push_back({m, {}});
  }
  running_ = true;
  inFrames_ = false;
  nextStep_ = 0;
  nextMethod_ = 0;
  measure2d_ = nullptr;
  measure3d_ = nullptr;
  try {
    if (threaded)
      thread_ = std::thread([this] {
        run();
        running_ = false;
      });
  } catch (const std::system_error&) {
    threaded = false;  // no threads here (the web page)
  }
  inFrames_ = !threaded;  // step() measures, a method at one size a frame
}

void ScalingWorker::show(ScalingConfig config, ScalingResult result) {
  cancel();
  config_ = std::move(config);
  const std::lock_guard lock(mutex_);
  progress_ = {};
  progress_.result = std::move(result);
  progress_.finished = true;
  progress_.done = progress_.total = 1;
  progress_.current = "recorded timings, not measured here";
}

void ScalingWorker::cancel() {
  stop_ = true;
  wait();
  const std::lock_guard lock(mutex_);
  if (progress_.running) progress_.cancelled = true;
  progress_.running = false;
}

void ScalingWorker::wait() {
  if (thread_.joinable()) thread_.join();
  while (inFrames_ && running_) step();
}

void ScalingWorker::step() {
  if (!inFrames_ || !running_) return;
  try {
    if (stop_ || !stepOne()) running_ = false;
  } catch (const std::exception& e) {
    const std::lock_guard lock(mutex_);
    progress_.error = e.what();
    progress_.running = false;
    running_ = false;
  }
  if (!running_) {  // the shapes go
    measure2d_ = nullptr;
    measure3d_ = nullptr;
  }
}

bool ScalingWorker::stepOne() {
  const std::size_t sizes = config_.sizes.size(), faces = config_.faces.size();
  if (nextStep_ < sizes)
    return stepMethod<Method2D>(kAllMethods2D, config_.sizes[nextStep_], progress_.result.series,
                                measure2d_, measurer2D);
  if (nextStep_ < sizes + faces)
    return stepMethod<Method3D>(kAllMethods3D, config_.faces[nextStep_ - sizes],
                                progress_.result.series3d, measure3d_, measurer3D);
  return runStep(nextStep_);  // the memory comparison, the last step
}

template <class Method, class Make>
bool ScalingWorker::stepMethod(std::span<const Method> methods, std::size_t size,
                               std::vector<SeriesOf<Method>>& series,
                               std::function<ScalingSample(Method)>& measure, Make make) {
  if (!measure) measure = make(config_, size);
  measureOne(methods, nextMethod_, size, series, measure);
  if (++nextMethod_ == methods.size()) {
    nextMethod_ = 0;
    ++nextStep_;
    measure = nullptr;
  }
  return true;
}

ScalingProgress ScalingWorker::snapshot() const {
  const std::lock_guard lock(mutex_);
  return progress_;
}

void ScalingWorker::run() {
  try {
    for (std::size_t k = 0; !stop_ && runStep(k); ++k) {
    }
  } catch (const std::exception& e) {
    const std::lock_guard lock(mutex_);
    progress_.error = e.what();
    progress_.running = false;
  }
}

bool ScalingWorker::runStep(std::size_t k) {
  const std::size_t sizes = config_.sizes.size(), faces = config_.faces.size();
  if (k < sizes) {
    runSize(config_.sizes[k]);
    return true;
  }
  if (k < sizes + faces) {
    runSize3D(config_.faces[k - sizes]);
    return true;
  }
  std::vector<MemorySample> memory;
  for (int e = 1; e <= 9 && !stop_; ++e) memory.push_back(measureMemory(std::pow(10.0, -e)));
  const std::lock_guard lock(mutex_);
  progress_.result.memory = std::move(memory);
  progress_.done += 1;
  progress_.running = false;
  progress_.finished = !stop_;
  return false;
}

template <class Method, class Measure>
void ScalingWorker::measureOne(std::span<const Method> methods, std::size_t i, std::size_t size,
                               std::vector<SeriesOf<Method>>& series, Measure& measure) {
  const Method m = methods[i];
  if (!measured(config_, m, size)) return;
  {
    const std::lock_guard lock(mutex_);
    progress_.current = std::string(toString(m)) + ", " + grouped(size);
  }
  const ScalingSample s = measure(m);
  const std::lock_guard lock(mutex_);
  series[i].samples.push_back(s);
  progress_.done += 1;
}

template <class Method, class Measure>
void ScalingWorker::runMethods(std::span<const Method> methods, std::size_t size,
                               std::vector<SeriesOf<Method>>& series, Measure measure) {
  for (std::size_t i = 0; i < methods.size() && !stop_; ++i)
    measureOne(methods, i, size, series, measure);
}

void ScalingWorker::runSize(std::size_t n) {
  runMethods<Method2D>(kAllMethods2D, n, progress_.result.series, measurer2D(config_, n));
}

void ScalingWorker::runSize3D(std::size_t f) {
  runMethods<Method3D>(kAllMethods3D, f, progress_.result.series3d, measurer3D(config_, f));
}

}  // namespace convexloc::viewer
