// convexloc-viewer — the state transitions both scenes share, instantiated for 2D and 3D.
#include "logic/scene/scene_common.hpp"

#include <algorithm>
#include <filesystem>

#include "convexloc/timing.hpp"
#include "logic/scene/scene2d.hpp"
#include "logic/scene/scene3d.hpp"

namespace convexloc::viewer {

std::string baseName(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

template <class Traits>
void SceneState<Traits>::setError(std::string message) {
  error_ = std::move(message);
  ++errorSerial_;
}

// === Shape

template <class Traits>
bool SceneState<Traits>::loadFile(const std::string& path) {
  return guarded(path, [&] { return adoptShape(Traits::readShape(path), baseName(path)); });
}

template <class Traits>
bool SceneState<Traits>::swapShape(Shape shape, std::string label, bool fresh) {
  std::optional<Shape> previous = std::move(shape_);
  const auto resolutions = resolution_;
  shape_.emplace(std::move(shape));
  if (fresh)
    for (std::size_t k = 0; k < resolution_.size(); ++k)
      if (!chosen_[k]) resolution_[k] = 0;
  if (!rebuildLocator()) {
    shape_ = std::move(previous);
    resolution_ = resolutions;
    return false;
  }
  label_ = std::move(label);
  ++versions_.shape;
  return true;
}

// === Method

template <class Traits>
bool SceneState<Traits>::rebuildLocator() {
  try {
    Locator next(*shape_, method_, resolution_[Traits::slot(method_)]);
    stats_ = next.stats();
    std::vector<Cell> cells;
    if (stats_.cells <= kMaxDrawnCells) cells = next.cells();
    locator_.emplace(std::move(next));
    cells_ = std::move(cells);
  } catch (const Error& e) {
    setError(e.what());
    return false;
  } catch (const std::bad_alloc&) {
    setError("out of memory building the " + std::string(toString(method_)) + " locator");
    return false;
  }
  ++versions_.structure;
  cellsChanged();
  classify();
  retrace();
  ++versions_.overlay;
  return true;
}

template <class Traits>
void SceneState<Traits>::setMethod(Method m) {
  if (m == method_ && locator_) return;
  const Method previous = method_;
  method_ = m;
  dropChosenCell();
  if (!rebuildLocator()) method_ = previous;
}

template <class Traits>
bool SceneState<Traits>::setResolution(std::uint32_t r) {
  const std::size_t k = Traits::slot(method_);
  chosen_[k] = true;
  if (resolution_[k] == r) return true;
  const std::uint32_t previous = resolution_[k];
  resolution_[k] = r;
  dropChosenCell();
  if (rebuildLocator()) return true;
  resolution_[k] = previous;
  return false;
}

// === Spray

template <class Traits>
void SceneState<Traits>::spray(const SpraySettings& s) {
  spray_ = s;
  try {
    points_ = Traits::sprayPoints(*shape_, s.count, s.seed, s.nearBoundary);
  } catch (const std::bad_alloc&) {
    points_.clear();
    setError("out of memory spraying " + std::to_string(s.count) + " points");
  }
  classify();
}

template <class Traits>
void SceneState<Traits>::clearSpray() {
  points_.clear();
  classify();
}

template <class Traits>
void SceneState<Traits>::classify() {
  classes_.resize(points_.size());
  const auto t0 = Clock::now();
  locator_->locate(points_, classes_);
  const double seconds = secondsSince(t0);
  locateNsPerPoint_ = points_.empty() ? 0.0 : 1e9 * seconds / static_cast<double>(points_.size());
  counts_ = {0, 0, 0};
  for (Location l : classes_) ++counts_[static_cast<std::size_t>(l)];
  ++versions_.points;
}

// === Probe

template <class Traits>
void SceneState<Traits>::place(Point p) {
  probe_ = Probe{p, locator_->trace(p, traceOptions_)};
  ++versions_.overlay;
}

template <class Traits>
void SceneState<Traits>::clearProbe() {
  if (!probe_) return;
  probe_.reset();
  ++versions_.overlay;
}

template <class Traits>
void SceneState<Traits>::retrace() {
  if (probe_) probe_->trace = locator_->trace(probe_->point, traceOptions_);
}

// === Steps

template <class Traits>
void SceneState<Traits>::setTraceOptions(TraceOptions options) {
  if (options.radii == traceOptions_.radii) return;
  traceOptions_ = options;
  retrace();
  ++versions_.overlay;
}

template <class Traits>
void SceneState<Traits>::setStep(int step) {
  if (step == step_) return;
  step_ = step;
  ++versions_.overlay;
}

// === Compare

namespace {

// Times one locator on `points` in chunks, after one chunk of warming up, until done or
// out of budget; counts its answers that differ from `reference`.
template <class Locator, class Point, class Row>
void timeLocator(const Locator& loc, std::span<const Point> points,
                 std::span<const Location> reference, std::size_t chunk, double seconds,
                 std::vector<Location>& out, Row& row) {
  const std::size_t warm = std::min(chunk, points.size());
  loc.locate(points.first(warm), std::span<Location>(out).first(warm));
  const auto t1 = Clock::now();
  std::size_t done = 0;
  while (done < points.size()) {
    const std::size_t k = std::min(chunk, points.size() - done);
    loc.locate(points.subspan(done, k), std::span<Location>(out).subspan(done, k));
    done += k;
    if (secondsSince(t1) > seconds) break;
  }
  const double spent = secondsSince(t1);
  row.points = done;
  row.nsPerPoint = done ? 1e9 * spent / static_cast<double>(done) : 0.0;
  for (std::size_t i = 0; i < done; ++i) row.disagreements += out[i] != reference[i];
}

}  // namespace

template <class Traits>
auto SceneState<Traits>::compare(double secondsPerMethod) const -> std::vector<Timing> {
  std::vector<Point> temporary;
  std::span<const Point> pts = points_;
  std::span<const Location> reference = classes_;
  std::vector<Location> referenceTemp;
  if (pts.empty()) {
    temporary = Traits::sprayPoints(*shape_, Traits::kCompareSpray, 1, false);
    referenceTemp.resize(temporary.size());
    locator_->locate(temporary, referenceTemp);
    pts = temporary;
    reference = referenceTemp;
  }
  std::vector<Location> out(pts.size());
  std::vector<Timing> rows;
  for (Method m : Traits::kMethods) {
    Timing row;
    row.method = m;
    try {
      const auto t0 = Clock::now();
      Locator loc(*shape_, m, Traits::compareResolution(m, resolution_[Traits::slot(m)]));
      row.buildMs = 1e3 * secondsSince(t0);
      const Stats st = loc.stats();
      row.bytes = st.bytes;
      row.cells = st.cells;
      timeLocator(loc, pts, reference, Traits::kCompareChunk, secondsPerMethod, out, row);
    } catch (const Error&) {
      row.points = 0;
    }
    rows.push_back(row);
  }
  return rows;
}

template class SceneState<Traits2D>;
template class SceneState<Traits3D>;

std::vector<std::string> shapeFilesIn(const std::string& dir) {
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
    const std::string ext = e.path().extension().string();
    const std::string name = e.path().filename().string();
    if ((ext == ".txt" || ext == ".off" || ext == ".obj" || ext == ".stl" || ext == ".ply") &&
        name.find("points") == std::string::npos)
      files.push_back(e.path().string());
  }
  std::sort(files.begin(), files.end());
  return files;
}

}  // namespace convexloc::viewer
