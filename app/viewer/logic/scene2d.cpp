// convexloc-viewer — the 2D scene's state transitions.
#include "logic/scene2d.hpp"

#include <algorithm>
#include <chrono>
#include <exception>
#include <string>
#include <utility>

#include "convexloc/error.hpp"
#include "convexloc/timing.hpp"
#include "convexloc/text_reader.hpp"
#include "logic/picking.hpp"

namespace convexloc::viewer {
namespace {

// "file:line: message", "file: message" or "message", as the GUIDE's contract says
std::string located(const std::string& source, const Error& e) {
  if (source.empty()) return e.what();
  if (e.line() == 0) return source + ": " + e.what();
  return source + ":" + std::to_string(e.line()) + ": " + e.what();
}

// the file name of a path, for labels
std::string baseName(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

constexpr std::size_t kDefaultVertices = 16;
constexpr std::uint64_t kDefaultSeed = 7;
constexpr std::size_t kDefaultSpray = 3000;
constexpr std::uint32_t kDefaultPolarSlabs = 8;

}  // namespace

std::size_t baseEdgesPerCell(Method2D m) {
  return (m == Method2D::Slab || m == Method2D::Uniform) ? 2 : 1;
}

Scene2D::Scene2D() {
  generate(PolygonKind::Random, kDefaultVertices, kDefaultSeed);
  // eight polar slabs per octant: most cells then list one edge, and the cells where a
  // vertex falls stand out, as in the paper's figure
  resolution_[static_cast<std::size_t>(Method2D::Polar)] = kDefaultPolarSlabs;
  rebuildLocator();
  spray({kDefaultSpray, 1, false});
}

void Scene2D::setError(std::string message) {
  error_ = std::move(message);
  ++errorSerial_;
}

// === Shape

bool Scene2D::adopt(ConvexPolygon polygon, std::string label, bool respray) {
  std::optional<ConvexPolygon> previous = std::move(polygon_);
  const auto resolutions = resolution_;
  polygon_.emplace(std::move(polygon));
  // a new shape (not an edit) gets core's choice where the user chose nothing
  if (respray)
    for (std::size_t m = 0; m < resolution_.size(); ++m)
      if (!chosen_[m]) resolution_[m] = 0;
  if (!rebuildLocator()) {
    polygon_ = std::move(previous);
    resolution_ = resolutions;
    return false;
  }
  label_ = std::move(label);
  ++versions_.shape;
  // a new shape gets a new spray (same count, seed and kind, in its box); an edited one
  // keeps its points, which rebuildLocator has classified again
  if (respray && !points_.empty()) spray(spray_);
  if (probe_) retrace();
  return true;
}

bool Scene2D::setShape(std::span<const Vec2> points, std::string label,
                       std::span<const std::size_t> lines, const std::string& source) {
  try {
    ConvexPolygon polygon(points, lines);
    return adopt(std::move(polygon), std::move(label), true);
  } catch (const Error& e) {
    setError(located(source, e));
  } catch (const std::bad_alloc&) {
    setError(source.empty() ? "out of memory" : source + ": out of memory");
  }
  return false;
}

bool Scene2D::generate(PolygonKind kind, std::size_t n, std::uint64_t seed) {
  try {
    std::vector<Vec2> v = generatePolygon(kind, n, seed);
    std::string label = std::string(toString(kind)) + ", " + std::to_string(n) + " vertices";
    if (kind == PolygonKind::Random || kind == PolygonKind::Triangle || kind == PolygonKind::Offset)
      label += ", seed " + std::to_string(seed);
    return setShape(v, std::move(label));
  } catch (const Error& e) {
    setError(e.what());
  }
  return false;
}

bool Scene2D::loadFile(const std::string& path) {
  try {
    PointList list = readPoints2D(path);
    return setShape(list.points, baseName(path), list.lines, path);
  } catch (const Error& e) {
    setError(located(path, e));
  } catch (const std::bad_alloc&) {
    setError(path + ": out of memory");
  }
  return false;
}

// === Method

bool Scene2D::rebuildLocator() {
  try {
    Locator2D next(*polygon_, method_, resolution_[static_cast<std::size_t>(method_)]);
    stats_ = next.stats();
    std::vector<Cell2D> cells;
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
  hovered_ = -1;
  if (hoverPoint_) hover(hoverPoint_);
  classify();
  retrace();
  ++versions_.overlay;
  return true;
}

void Scene2D::setMethod(Method2D m) {
  if (m == method_ && locator_) return;
  const Method2D previous = method_;
  method_ = m;
  if (!rebuildLocator()) method_ = previous;
}

bool Scene2D::setResolution(std::uint32_t r) {
  std::uint32_t& slot = resolution_[static_cast<std::size_t>(method_)];
  chosen_[static_cast<std::size_t>(method_)] = true;
  if (slot == r) return true;
  const std::uint32_t previous = slot;
  slot = r;
  if (rebuildLocator()) return true;
  slot = previous;
  return false;
}

std::uint32_t Scene2D::effectiveResolution() const {
  if (const auto* u = locator_->get<UniformLocator>()) return u->slabCount();
  if (const auto* p = locator_->get<PolarLocator>()) return p->slabsPerOctant();
  return 0;
}

std::optional<Vec2> Scene2D::centre() const {
  const auto* p = locator_->get<PolarLocator>();
  if (!p || cells_.empty()) return std::nullopt;  // no cells: core found no centre inside
  return p->centre();
}

// === Spray

void Scene2D::spray(const SpraySettings& s) {
  spray_ = s;
  try {
    points_ = generatePoints(*polygon_, s.count, s.seed, s.nearBoundary);
  } catch (const std::bad_alloc&) {
    points_.clear();
    setError("out of memory spraying " + std::to_string(s.count) + " points");
  }
  classify();
}

void Scene2D::clearSpray() {
  points_.clear();
  classify();
}

void Scene2D::classify() {
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

void Scene2D::place(Vec2 p) {
  probe_ = Probe{p, locator_->trace(p)};
  ++versions_.overlay;
}

void Scene2D::clearProbe() {
  if (!probe_) return;
  probe_.reset();
  ++versions_.overlay;
}

void Scene2D::retrace() {
  if (probe_) probe_->trace = locator_->trace(probe_->point);
}

// === Hover

void Scene2D::hover(std::optional<Vec2> p) {
  hoverPoint_ = p;
  std::ptrdiff_t cell = -1;
  if (p) {
    // the common case first: the cursor is still in the same cell
    if (hovered_ >= 0 && hovered_ < static_cast<std::ptrdiff_t>(cells_.size()) &&
        outlineContains(cells_[static_cast<std::size_t>(hovered_)].outline, *p))
      cell = hovered_;
    else
      cell = pickCell(cells_, *p);
  }
  if (cell != hovered_) {
    hovered_ = cell;
    ++versions_.overlay;
  }
}

// === Drag

void Scene2D::beginDrag(std::size_t i) {
  if (i >= polygon_->size()) return;
  drag_ = Drag{i, polygon_->vertex(i), false, {}};
  ++versions_.overlay;
}

bool Scene2D::dragTo(Vec2 p) {
  if (!drag_) return false;
  const std::size_t i = drag_->vertex;
  drag_->cursor = p;
  ++versions_.overlay;
  std::vector<Vec2> moved(polygon_->vertices().begin(), polygon_->vertices().end());
  moved[i] = p;
  try {
    ConvexPolygon candidate(moved);
    if (candidate.size() != moved.size()) {
      drag_->rejected = true;
      drag_->message = "vertex " + std::to_string(i) +
                       " would lie on the segment of its neighbours or on another vertex";
      return false;
    }
    // normalisation may start the ring elsewhere or reverse it: follow the dragged vertex
    const auto source = candidate.sourceIndex();
    const auto it = std::find(source.begin(), source.end(), static_cast<std::uint32_t>(i));
    const std::size_t now = static_cast<std::size_t>(it - source.begin());
    const std::string label = label_.ends_with(" (edited)") ? label_ : label_ + " (edited)";
    if (!adopt(std::move(candidate), label, false)) {
      drag_->rejected = true;
      drag_->message = error_;
      return false;
    }
    drag_->vertex = now;
    drag_->rejected = false;
    drag_->message.clear();
    return true;
  } catch (const Error& e) {
    drag_->rejected = true;
    drag_->message = e.what();
  }
  return false;
}

void Scene2D::endDrag() {
  if (!drag_) return;
  if (drag_->rejected)
    setError("vertex drag: " + drag_->message + "; the last valid shape is kept");
  drag_.reset();
  ++versions_.overlay;
}

// === Compare

std::vector<CompareRow> Scene2D::compare(double secondsPerMethod) const {
  std::vector<Vec2> temporary;
  std::span<const Vec2> pts = points_;
  std::span<const Location> reference = classes_;
  std::vector<Location> referenceTemp;
  if (pts.empty()) {
    temporary = generatePoints(*polygon_, 100000, 1, false);
    referenceTemp.resize(temporary.size());
    locator_->locate(temporary, referenceTemp);
    pts = temporary;
    reference = referenceTemp;
  }
  constexpr std::size_t kChunk = 4096;
  std::vector<Location> out(pts.size());
  std::vector<CompareRow> rows;
  for (Method2D m : kAllMethods2D) {
    CompareRow row;
    row.method = m;
    try {
      const auto t0 = Clock::now();
      Locator2D loc(*polygon_, m, resolution_[static_cast<std::size_t>(m)]);
      row.buildMs = 1e3 * secondsSince(t0);
      const Stats2D st = loc.stats();
      row.bytes = st.bytes;
      row.cells = st.cells;
      // warm up on one chunk, then time whole chunks until done or out of budget
      const std::size_t warm = std::min(kChunk, pts.size());
      loc.locate(pts.first(warm), std::span<Location>(out).first(warm));
      const auto t1 = Clock::now();
      std::size_t done = 0;
      while (done < pts.size()) {
        const std::size_t k = std::min(kChunk, pts.size() - done);
        loc.locate(pts.subspan(done, k), std::span<Location>(out).subspan(done, k));
        done += k;
        if (secondsSince(t1) > secondsPerMethod) break;
      }
      const double seconds = secondsSince(t1);
      row.points = done;
      row.nsPerPoint = done ? 1e9 * seconds / static_cast<double>(done) : 0.0;
      for (std::size_t i = 0; i < done; ++i) row.disagreements += out[i] != reference[i];
    } catch (const Error&) {
      row.points = 0;
    }
    rows.push_back(row);
  }
  return rows;
}

}  // namespace convexloc::viewer
