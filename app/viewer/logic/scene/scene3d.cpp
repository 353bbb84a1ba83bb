// convexloc-viewer — the 3D scene's own state transitions: its shape, the slicing plane
// and its section, the hovered and the pinned cell.
#include "logic/scene/scene3d.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "convexloc/mesh_reader.hpp"

namespace convexloc::viewer {
namespace {

constexpr std::uint32_t kDefaultGrid = 8;
constexpr std::size_t kDefaultSpray = 1500;

}  // namespace

std::vector<Vec3> Traits3D::sprayPoints(const ConvexPolyhedron& p, std::size_t n,
                                        std::uint64_t seed, bool nearBoundary) {
  return generatePoints3D(p, n, seed, nearBoundary);
}

ConvexPolyhedron Traits3D::readShape(const std::string& path) {
  const MeshData mesh = readMesh(path);
  // a point cloud (a scan's PLY) has no surface of its own: the viewer shows its convex hull,
  // as it does for any mesh with --hull
  if (hullOfFiles || (mesh.faceCount() == 0 && !mesh.vertices.empty()))
    return ConvexPolyhedron::hullOf(mesh.vertices);
  return ConvexPolyhedron(mesh);
}

Scene3D::Scene3D() {
  generate(PolyhedronKind::Icosahedron, 20, 1);
  // an 8 x 8 grid per cube face: most cells list one face, and the cells an edge or a
  // vertex projects into stand out
  resolution_[0] = kDefaultGrid;
  rebuildLocator();
  spray({kDefaultSpray, 1, false});
}

// === Shape

bool Scene3D::adoptShape(ConvexPolyhedron poly, std::string label) {
  if (!swapShape(std::move(poly), std::move(label), true)) return false;
  // the slicing plane through the middle of the new box
  const Bounds3 b = bounds();
  slice_.offset = b.middle()[slice_.axis];
  pinned_ = pinned2_ = hovered_ = -1;
  pinKey_.reset();
  pinKey2_.reset();
  probe_.reset();
  resection();
  if (!points_.empty()) spray(spray_);
  return true;
}

bool Scene3D::setMesh(const MeshData& mesh, std::string label, const std::string& source) {
  return guarded(source, [&] { return adoptShape(ConvexPolyhedron(mesh), std::move(label)); });
}

std::string generatedLabel(PolyhedronKind kind, const ConvexPolyhedron& p, std::uint64_t seed) {
  // the faces it has (planes, as every count the viewer shows), not the count asked for
  std::string label = std::string(toString(kind)) + ", " + std::to_string(p.planeCount()) +
                      (p.planeCount() == 1 ? " face" : " faces");
  if (p.faceCount() != p.planeCount())
    label += " (" + std::to_string(p.faceCount()) + " triangles)";
  const bool random = kind == PolyhedronKind::SphereHull || kind == PolyhedronKind::CubeHull ||
                      kind == PolyhedronKind::EllipsoidHull;
  if (random) label += ", seed " + std::to_string(seed);
  return label;
}

bool Scene3D::generate(PolyhedronKind kind, std::size_t n, std::uint64_t seed) {
  return guarded("", [&] {
    ConvexPolyhedron p(generatePolyhedron(kind, n, seed));
    std::string label = generatedLabel(kind, p, seed);
    return adoptShape(std::move(p), std::move(label));
  });
}

Bounds3 Scene3D::bounds() const {
  const Box3 b = shape_->bounds();
  return {toGlm(b.lo), toGlm(b.hi)};
}

// === Method

void Scene3D::cellsChanged() {
  hovered_ = -1;
  // the pinned cells come back where the new cells hold them (a method switched back)
  pinned_ = findCell(pinKey_);
  pinned2_ = findCell(pinKey2_);
  resection();
}

std::uint32_t Scene3D::effectiveResolution() const {
  if (const auto* c = locator_->get<CubemapLocator>()) return c->resolution();
  return 0;
}

std::optional<Vec3> Scene3D::centre() const {
  if (const auto* c = locator_->get<CubemapLocator>()) return c->centre();
  if (const auto* w = locator_->get<WalkLocator>()) return w->centre();
  return shape_->centre();
}

double Scene3D::cubeHalfSize() const {
  if (const auto* c = locator_->get<CubemapLocator>(); c && !cells_.empty())
    return c->cubeHalfSize();
  return 0.0;
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
  // du and dv are zero along the axis: every sample lies exactly on the plane
  glm::dvec3 du(0.0), dv(0.0);
  du[u] = (r[2][u] - r[0][u]) / kSectionSamples;
  dv[v] = (r[2][v] - r[0][v]) / kSectionSamples;
  section_ = sampleSection(*locator_, r[0], du, dv, kSectionSamples);
  ++versions_.section;
}

Section sampleSection(const Locator3D& locator, glm::dvec3 corner, glm::dvec3 du, glm::dvec3 dv,
                      std::uint32_t n) {
  Section s;
  s.n = n;
  s.corner = corner;
  s.du = du;
  s.dv = dv;
  std::vector<Vec3> samples;
  samples.reserve(static_cast<std::size_t>(n) * n);
  for (std::uint32_t j = 0; j < n; ++j)
    for (std::uint32_t i = 0; i < n; ++i)
      samples.push_back(toVec3(corner + (i + 0.5) * du + (j + 0.5) * dv));
  s.classes.resize(samples.size());
  locator.locate(samples, s.classes);
  return s;
}

std::ptrdiff_t cellOf(const std::vector<Cell3D>& cells, const Trace3D& t) {
  if (t.cubeFace < 0) return -1;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const Cell3D& c = cells[k];
    if (c.cubeFace == t.cubeFace && c.level == t.level && c.i == t.cellI && c.j == t.cellJ)
      return static_cast<std::ptrdiff_t>(k);
  }
  return -1;
}

// === Probe

std::ptrdiff_t Scene3D::probeCell() const {
  if (!probe_) return -1;
  return cellOf(cells_, probe_->trace);
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
  pinKey_ = keyOf(cell);
  if (cell < 0) pinSecond(-1);
  if (cell == pinned_) return;
  pinned_ = cell;
  ++versions_.overlay;
}

void Scene3D::pinSecond(std::ptrdiff_t cell) {
  if (cell >= static_cast<std::ptrdiff_t>(cells_.size())) cell = -1;
  pinKey2_ = keyOf(cell);
  if (cell == pinned2_) return;
  pinned2_ = cell;
  ++versions_.overlay;
}

std::optional<Scene3D::CellKey> Scene3D::keyOf(std::ptrdiff_t cell) const {
  if (cell < 0 || cell >= static_cast<std::ptrdiff_t>(cells_.size())) return std::nullopt;
  const Cell3D& c = cells_[static_cast<std::size_t>(cell)];
  return CellKey{c.cubeFace, c.level, c.i, c.j, effectiveResolution()};
}

std::ptrdiff_t Scene3D::findCell(const std::optional<CellKey>& key) const {
  if (!key || key->grid != effectiveResolution()) return -1;
  for (std::size_t k = 0; k < cells_.size(); ++k) {
    const Cell3D& c = cells_[k];
    if (c.cubeFace == key->cubeFace && c.level == key->level && c.i == key->i && c.j == key->j)
      return static_cast<std::ptrdiff_t>(k);
  }
  return -1;
}

std::pair<std::ptrdiff_t, std::ptrdiff_t> Scene3D::typicalCells() const {
  // the crowded one first: the most faces, then the single-face cell farthest from it
  std::ptrdiff_t many = -1, one = -1;
  std::size_t most = 1;
  for (std::size_t k = 0; k < cells_.size(); ++k)
    if (cells_[k].faces.size() > most) {
      most = cells_[k].faces.size();
      many = static_cast<std::ptrdiff_t>(k);
    }
  double far = -1.0;
  for (std::size_t k = 0; k < cells_.size(); ++k) {
    const Cell3D& c = cells_[k];
    if (c.faces.size() != 1) continue;
    double d = 0.0;
    if (many >= 0) {
      const Cell3D& m = cells_[static_cast<std::size_t>(many)];
      if (c.cubeFace != m.cubeFace) continue;
      d = std::hypot(c.s0 - m.s0, c.t0 - m.t0);
    }
    if (d > far) {
      far = d;
      one = static_cast<std::ptrdiff_t>(k);
    }
  }
  return {one, many};
}

}  // namespace convexloc::viewer
