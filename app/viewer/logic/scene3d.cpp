// convexloc-viewer — the 3D scene's state transitions.
#include "logic/scene3d.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <utility>

#include "convexloc/error.hpp"
#include "convexloc/timing.hpp"
#include "convexloc/mesh_reader.hpp"

namespace convexloc::viewer {
namespace {

std::string located(const std::string& source, const Error& e) {
  std::string out = source;
  if (!source.empty()) {
    if (e.line() != 0) out += ":" + std::to_string(e.line());
    out += ": ";
  }
  out += e.what();
  return out;
}

std::string baseName(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

constexpr std::uint32_t kDefaultGrid = 8;
constexpr std::size_t kDefaultSpray = 1500;
constexpr std::uint32_t kSectionSamples = 160;

}  // namespace

Scene3D::Scene3D() {
  generate(PolyhedronKind::Icosahedron, 20, 1);
  // an 8 x 8 grid per cube face: most cells list one face, and the cells an edge or a
  // vertex projects into stand out
  resolution_ = kDefaultGrid;
  rebuildLocator();
  spray({kDefaultSpray, 1, false});
}

void Scene3D::setError(std::string message) {
  error_ = std::move(message);
  ++errorSerial_;
}

// === Shape

bool Scene3D::adopt(ConvexPolyhedron poly, std::string label) {
  std::optional<ConvexPolyhedron> previous = std::move(poly_);
  const std::uint32_t resolution = resolution_;
  poly_.emplace(std::move(poly));
  if (!chosen_) resolution_ = 0;  // core's choice unless the user chose
  if (!rebuildLocator()) {
    poly_ = std::move(previous);
    resolution_ = resolution;
    return false;
  }
  label_ = std::move(label);
  ++versions_.shape;
  // the slicing plane through the middle of the new box
  const Bounds3 b = bounds();
  slice_.offset = b.middle()[slice_.axis];
  pinned_ = hovered_ = -1;
  probe_.reset();
  resection();
  if (!points_.empty()) spray(spray_);
  return true;
}

bool Scene3D::setMesh(const MeshData& mesh, std::string label, const std::string& source) {
  try {
    ConvexPolyhedron poly(mesh);
    return adopt(std::move(poly), std::move(label));
  } catch (const Error& e) {
    setError(located(source, e));
  } catch (const std::bad_alloc&) {
    setError(source.empty() ? "out of memory" : source + ": out of memory");
  }
  return false;
}

bool Scene3D::generate(PolyhedronKind kind, std::size_t n, std::uint64_t seed) {
  try {
    const MeshData mesh = generatePolyhedron(kind, n, seed);
    std::string label = std::string(toString(kind));
    label += ", about " + std::to_string(n) + " faces, seed " + std::to_string(seed);
    return setMesh(mesh, std::move(label));
  } catch (const Error& e) {
    setError(e.what());
  }
  return false;
}

bool Scene3D::loadFile(const std::string& path) {
  try {
    const MeshData mesh = readMesh(path);
    return setMesh(mesh, baseName(path), path);
  } catch (const Error& e) {
    setError(located(path, e));
  } catch (const std::bad_alloc&) {
    setError(path + ": out of memory");
  }
  return false;
}

Bounds3 Scene3D::bounds() const {
  const Box3 b = poly_->bounds();
  return {toGlm(b.lo), toGlm(b.hi)};
}

// === Method

bool Scene3D::rebuildLocator() {
  try {
    Locator3D next(*poly_, method_, resolution_);
    stats_ = next.stats();
    std::vector<Cell3D> cells;
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
  if (pinned_ >= static_cast<std::ptrdiff_t>(cells_.size())) pinned_ = -1;
  classify();
  resection();
  retrace();
  ++versions_.overlay;
  return true;
}

void Scene3D::setMethod(Method3D m) {
  if (m == method_ && locator_) return;
  const Method3D previous = method_;
  method_ = m;
  pinned_ = -1;
  if (!rebuildLocator()) method_ = previous;
}

bool Scene3D::setResolution(std::uint32_t g) {
  chosen_ = true;
  if (g == resolution_) return true;
  const std::uint32_t previous = resolution_;
  resolution_ = g;
  pinned_ = -1;
  if (rebuildLocator()) return true;
  resolution_ = previous;
  return false;
}

std::uint32_t Scene3D::effectiveResolution() const {
  if (const auto* c = locator_->get<CubemapLocator>()) return c->resolution();
  return 0;
}

std::optional<Vec3> Scene3D::centre() const {
  if (const auto* c = locator_->get<CubemapLocator>()) return c->centre();
  if (const auto* w = locator_->get<WalkLocator>()) return w->centre();
  return poly_->centre();
}

double Scene3D::cubeHalfSize() const {
  if (const auto* c = locator_->get<CubemapLocator>(); c && !cells_.empty())
    return c->cubeHalfSize();
  return 0.0;
}

// === Spray

void Scene3D::spray(const SpraySettings& s) {
  spray_ = s;
  try {
    points_ = generatePoints3D(*poly_, s.count, s.seed, s.nearBoundary);
  } catch (const std::bad_alloc&) {
    points_.clear();
    setError("out of memory spraying " + std::to_string(s.count) + " points");
  }
  classify();
}

void Scene3D::clearSpray() {
  points_.clear();
  classify();
}

void Scene3D::classify() {
  classes_.resize(points_.size());
  const auto t0 = Clock::now();
  locator_->locate(points_, classes_);
  const double seconds = secondsSince(t0);
  locateNsPerPoint_ = points_.empty() ? 0.0 : 1e9 * seconds / static_cast<double>(points_.size());
  counts_ = {0, 0, 0};
  for (Location l : classes_) ++counts_[static_cast<std::size_t>(l)];
  ++versions_.points;
}

// === Slice

std::array<glm::dvec3, 4> Scene3D::sliceRectangle() const {
  const Bounds3 b = bounds();
  const int a = slice_.axis, u = (a + 1) % 3, v = (a + 2) % 3;
  const glm::dvec3 grow = 0.15 * (b.hi - b.lo);
  glm::dvec3 lo = b.lo - grow, hi = b.hi + grow;
  std::array<glm::dvec3, 4> r;
  for (int k = 0; k < 4; ++k) {
    glm::dvec3 p{0.0};
    p[a] = slice_.offset;
    p[u] = (k == 1 || k == 2) ? hi[u] : lo[u];
    p[v] = (k >= 2) ? hi[v] : lo[v];
    r[static_cast<std::size_t>(k)] = p;
  }
  return r;
}

void Scene3D::setSlice(SlicePlane s) {
  s.axis = std::clamp(s.axis, 0, 2);
  const Bounds3 b = bounds();
  const double margin = 0.15 * (b.hi[s.axis] - b.lo[s.axis]);
  s.offset = std::clamp(s.offset, b.lo[s.axis] - margin, b.hi[s.axis] + margin);
  if (s.axis == slice_.axis && s.offset == slice_.offset) return;
  slice_ = s;
  resection();
}

std::optional<glm::dvec3> Scene3D::hitSlice(const Ray3& ray) const {
  const int a = slice_.axis;
  if (ray.direction[a] == 0.0) return std::nullopt;
  const double t = (slice_.offset - ray.origin[a]) / ray.direction[a];
  if (!(t > 0.0)) return std::nullopt;
  glm::dvec3 p = ray.at(t);
  p[a] = slice_.offset;  // exactly on the plane
  const auto r = sliceRectangle();
  const int u = (a + 1) % 3, v = (a + 2) % 3;
  if (p[u] < r[0][u] || p[u] > r[2][u] || p[v] < r[0][v] || p[v] > r[2][v]) return std::nullopt;
  return p;
}

void Scene3D::resection() {
  const auto r = sliceRectangle();
  const int a = slice_.axis, u = (a + 1) % 3, v = (a + 2) % 3;
  section_.n = kSectionSamples;
  section_.corner = r[0];
  section_.du = glm::dvec3(0.0);
  section_.dv = glm::dvec3(0.0);
  section_.du[u] = (r[2][u] - r[0][u]) / kSectionSamples;
  section_.dv[v] = (r[2][v] - r[0][v]) / kSectionSamples;
  // each sample at the middle of its square, classified by the locator in one batch
  std::vector<Vec3> samples;
  samples.reserve(static_cast<std::size_t>(kSectionSamples) * kSectionSamples);
  for (std::uint32_t j = 0; j < kSectionSamples; ++j)
    for (std::uint32_t i = 0; i < kSectionSamples; ++i) {
      glm::dvec3 p = section_.corner + (i + 0.5) * section_.du + (j + 0.5) * section_.dv;
      p[a] = slice_.offset;
      samples.push_back(toVec3(p));
    }
  section_.classes.resize(samples.size());
  locator_->locate(samples, section_.classes);
  ++versions_.section;
}

// === Probe

void Scene3D::place(Vec3 p) {
  probe_ = Probe3D{p, locator_->trace(p)};
  ++versions_.overlay;
}

void Scene3D::clearProbe() {
  if (!probe_) return;
  probe_.reset();
  ++versions_.overlay;
}

void Scene3D::retrace() {
  if (probe_) probe_->trace = locator_->trace(probe_->point);
}

std::ptrdiff_t Scene3D::probeCell() const {
  if (!probe_ || probe_->trace.cubeFace < 0) return -1;
  const Trace3D& t = probe_->trace;
  for (std::size_t k = 0; k < cells_.size(); ++k) {
    const Cell3D& c = cells_[k];
    if (c.cubeFace == t.cubeFace && c.level == t.level && c.i == t.cellI && c.j == t.cellJ)
      return static_cast<std::ptrdiff_t>(k);
  }
  return -1;
}

// === Cells under the cursor

std::ptrdiff_t Scene3D::pickCell(const Ray3& ray) const {
  const double h = cubeHalfSize();
  const auto c = centre();
  if (!(h > 0.0) || !c) return -1;
  // where the ray leaves the drawing cube (slabs), in double: a drawing matter
  const glm::dvec3 lo = toGlm(*c) - h, hi = toGlm(*c) + h;
  double t0 = 0.0, t1 = std::numeric_limits<double>::infinity();
  for (int a = 0; a < 3; ++a) {
    if (ray.direction[a] == 0.0) {
      if (ray.origin[a] < lo[a] || ray.origin[a] > hi[a]) return -1;
      continue;
    }
    double ta = (lo[a] - ray.origin[a]) / ray.direction[a],
           tb = (hi[a] - ray.origin[a]) / ray.direction[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
  }
  if (t0 > t1) return -1;
  // the far side, where the cells are drawn (behind the polyhedron, seen from inside)
  const glm::dvec3 p = ray.at(t1);
  // the cube face: the dominant axis of p - c (+x, -x, +y, -y, +z, -z)
  const glm::dvec3 d = p - toGlm(*c);
  int axis = 0;
  for (int a = 1; a < 3; ++a)
    if (std::abs(d[a]) > std::abs(d[axis])) axis = a;
  const int face = 2 * axis + (d[axis] < 0.0 ? 1 : 0);
  const int u = (axis + 1) % 3, v = (axis + 2) % 3;
  // the cell whose square (core's corners) holds p
  for (std::size_t k = 0; k < cells_.size(); ++k) {
    const Cell3D& cell = cells_[k];
    if (cell.cubeFace != face) continue;
    double ulo = INFINITY, uhi = -INFINITY, vlo = INFINITY, vhi = -INFINITY;
    for (const Vec3& q : cell.corners) {
      const glm::dvec3 g = toGlm(q);
      ulo = std::min(ulo, g[u]);
      uhi = std::max(uhi, g[u]);
      vlo = std::min(vlo, g[v]);
      vhi = std::max(vhi, g[v]);
    }
    if (p[u] >= ulo && p[u] <= uhi && p[v] >= vlo && p[v] <= vhi)
      return static_cast<std::ptrdiff_t>(k);
  }
  return -1;
}

void Scene3D::hover(std::optional<Ray3> ray) {
  const std::ptrdiff_t cell = ray ? pickCell(*ray) : -1;
  if (cell != hovered_) {
    hovered_ = cell;
    ++versions_.overlay;
  }
}

void Scene3D::pin(std::ptrdiff_t cell) {
  if (cell >= static_cast<std::ptrdiff_t>(cells_.size())) cell = -1;
  if (cell == pinned_) return;
  pinned_ = cell;
  ++versions_.overlay;
}

// === Compare

std::vector<CompareRow3D> Scene3D::compare(double secondsPerMethod) const {
  std::vector<Vec3> temporary;
  std::span<const Vec3> pts = points_;
  std::span<const Location> reference = classes_;
  std::vector<Location> referenceTemp;
  if (pts.empty()) {
    temporary = generatePoints3D(*poly_, 50000, 1, false);
    referenceTemp.resize(temporary.size());
    locator_->locate(temporary, referenceTemp);
    pts = temporary;
    reference = referenceTemp;
  }
  constexpr std::size_t kChunk = 2048;
  std::vector<Location> out(pts.size());
  std::vector<CompareRow3D> rows;
  for (Method3D m : kAllMethods3D) {
    CompareRow3D row;
    row.method = m;
    try {
      const auto t0 = Clock::now();
      Locator3D loc(*poly_, m, m == Method3D::Cubemap ? resolution_ : 0);
      row.buildMs = 1e3 * secondsSince(t0);
      const Stats3D st = loc.stats();
      row.bytes = st.bytes;
      row.cells = st.cells;
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
