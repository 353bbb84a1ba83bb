// convexloc-viewer — the Planes mode's state and its inspector text.
#include "logic/dual/planes3d.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "logic/dual/lines2d.hpp"

namespace convexloc::viewer {
namespace {

// the offset slider's reach and the plane's patch: the box's radius grown by this factor
constexpr double kGrow = 1.15;
// a plane's patch reaches at least this many offset reaches around its foot
constexpr double kFarPatch = 0.35;
// the dual's unit sphere drawn this many of the box's largest half-sides wide
constexpr double kDualSize = 0.75;
// the gap between the box's middle and the dual's cube, in the box's largest half-sides
// (beyond the plane's patch, which reaches 1.3)
constexpr double kDualGap = 1.9;

// unit vectors u, v with u x v = n (n unit)
void planeAxes(glm::dvec3 n, glm::dvec3& u, glm::dvec3& v) {
  const glm::dvec3 a = std::fabs(n.x) < 0.6 ? glm::dvec3(1, 0, 0) : glm::dvec3(0, 1, 0);
  u = glm::normalize(glm::cross(a, n));
  v = glm::cross(n, u);
}

// the polygon `poly` keeps on the side d . x <= h (one step of Sutherland-Hodgman)
std::vector<glm::dvec3> keepBelow(const std::vector<glm::dvec3>& poly, glm::dvec3 d, double h) {
  std::vector<glm::dvec3> out;
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec3 a = poly[i], b = poly[(i + 1) % poly.size()];
    const double fa = glm::dot(d, a) - h, fb = glm::dot(d, b) - h;
    if (fa <= 0.0) out.push_back(a);
    if ((fa < 0.0 && fb > 0.0) || (fa > 0.0 && fb < 0.0))
      out.push_back(a + fa / (fa - fb) * (b - a));
  }
  return out;
}

// the square of half-side `half` around m in the plane (u, v), clipped to the box
std::vector<glm::dvec3> patchIn(const Bounds3& box, glm::dvec3 m, glm::dvec3 u, glm::dvec3 v,
                                double half) {
  std::vector<glm::dvec3> poly = {m - half * u - half * v, m + half * u - half * v,
                                  m + half * u + half * v, m - half * u + half * v};
  for (int a = 0; a < 3; ++a) {
    glm::dvec3 d(0.0);
    d[a] = 1.0;
    poly = keepBelow(poly, d, box.hi[a]);
    poly = keepBelow(poly, -d, -box.lo[a]);
  }
  return poly;
}

// the unit normal of the plane through three points (drawing and sliders only)
glm::dvec3 normalOf(const std::array<Vec3, 3>& q) {
  const glm::dvec3 n = glm::cross(toGlm(q[1]) - toGlm(q[0]), toGlm(q[2]) - toGlm(q[0]));
  const double len = glm::length(n);
  return len > 0.0 ? n / len : glm::dvec3(0.0, 0.0, 1.0);
}

// the dual cell's part of the story: the cells of y and -y and what they proposed
void describeCells(const PlaneProbe3D& p, std::vector<TraceLine>& out) {
  const PlaneTrace& t = p.dual;
  if (!t.proposed) {
    out.push_back({TraceLine::Step, "no dual cell: the climbs started at vertex 0"});
    return;
  }
  out.push_back({TraceLine::Heading, "dual cube map (the direction y)"});
  out.push_back({TraceLine::Step, "y = -N / |N| = " + approx(t.direction.x, 3) + ", " +
                                      approx(t.direction.y, 3) + ", " + approx(t.direction.z, 3)});
  out.push_back({TraceLine::Step,
                 "cell " + std::to_string(p.cellUp) + " of y lists " + std::to_string(t.listedMax) +
                     " dual face" + (t.listedMax == 1 ? "" : "s") +
                     "; y's direction cell proposes vertex " + std::to_string(t.startMax)});
  out.push_back({TraceLine::Step, "cell " + std::to_string(p.cellDown) + " of -y lists " +
                                      std::to_string(t.listedMin) + " dual face" +
                                      (t.listedMin == 1 ? "" : "s") + "; -y's proposes vertex " +
                                      std::to_string(t.startMin)});
  out.push_back({TraceLine::Step, std::to_string(t.climbSteps) + " climb move" +
                                      (t.climbSteps == 1 ? "" : "s") + " to the extremes"});
}

}  // namespace

// === The mode

void Planes3D::setEnabled(bool on) {
  if (on == enabled_) return;
  enabled_ = on;
  dual_.reset();  // built afresh by the next sync
  ++version_;
}

void Planes3D::sync(const Scene3D& scene) {
  if (!enabled_) return;
  const Versions& v = scene.versions();
  if (dual_ && scene_ == &scene && shapeSeen_ == v.shape) {
    if (structureSeen_ != v.structure) {
      structureSeen_ = v.structure;  // the scene's locator classifies the section
      answer();
    }
    return;
  }
  scene_ = &scene;
  shapeSeen_ = v.shape;
  structureSeen_ = v.structure;
  rebuild(scene);
}

void Planes3D::rebuild(const Scene3D& scene) {
  const ConvexPolyhedron& p = scene.polyhedron();
  dual_ = std::make_unique<PlaneIntersector>(p, PlaneMethod::Dual);
  baseline_ = std::make_unique<PlaneIntersector>(p, PlaneMethod::Vertices);
  dualCells_.clear();
  if (const CubemapLocator* cube = dual_->dualLocator()) dualCells_ = cube->cells();
  box_ = scene.bounds();
  glm::dvec3 sum(0.0);
  for (const Vec3 v : p.vertices()) sum += toGlm(v);
  centre_ = sum / static_cast<double>(std::max<std::size_t>(p.vertexCount(), 1));
  reach_ = kGrow * std::max(box_.radius(), 1e-300);
  placeAgain();
  if (asked_)
    answer();
  else
    setSliders(sliders_);
}

void Planes3D::placeDual(glm::dvec3 side) {
  side_ = side;
  placeAgain();
  ++version_;
}

void Planes3D::placeAgain() {
  // the dual's unit sphere as large as the box's largest half-side, its cube beside the box
  const glm::dvec3 size = box_.hi - box_.lo;
  const double e = std::max(0.5 * std::max({size.x, size.y, size.z}), 1e-300);
  const CubemapLocator* cube = dual_ ? dual_->dualLocator() : nullptr;
  const double h = cube && cube->cubeHalfSize() > 0.0 ? cube->cubeHalfSize() : 1.0;
  place_.scale = kDualSize * e;
  place_.middle = box_.middle() + (kDualGap * e + place_.scale * h) * side_;
  dualHalf_ = place_.scale * h;
}

Bounds3 Planes3D::both() const {
  Bounds3 b = grownBox();
  // the plane's patch and its three points too, so that a plane given shows whole
  if (plane_) {
    for (const glm::dvec3& k : plane_->patch) b.lo = glm::min(b.lo, k), b.hi = glm::max(b.hi, k);
    for (const Vec3 q : plane_->q) b.lo = glm::min(b.lo, toGlm(q)), b.hi = glm::max(b.hi, toGlm(q));
  }
  b.lo = glm::min(b.lo, place_.middle - dualHalf_);
  b.hi = glm::max(b.hi, place_.middle + dualHalf_);
  return b;
}

Bounds3 Planes3D::grownBox() const {
  Bounds3 grown = box_;
  grown.lo -= (kGrow - 1.0) * (box_.hi - box_.lo);
  grown.hi += (kGrow - 1.0) * (box_.hi - box_.lo);
  return grown;
}

bool Planes3D::setPlane(Vec3 q1, Vec3 q2, Vec3 q3) {
  if (collinear(q1, q2, q3)) return false;
  asked_ = std::array<Vec3, 3>{q1, q2, q3};
  const glm::dvec3 n = normalOf(*asked_);
  sliders_.offset = glm::dot(n, toGlm(q1) - centre_);
  sliders_.azimuth = std::atan2(n.y, n.x);
  sliders_.elevation = std::asin(std::clamp(n.z, -1.0, 1.0));
  answer();
  return true;
}

void Planes3D::setSliders(PlaneSliders s) {
  const double ce = std::cos(s.elevation);
  const glm::dvec3 n{ce * std::cos(s.azimuth), ce * std::sin(s.azimuth), std::sin(s.elevation)};
  glm::dvec3 u, v;
  planeAxes(n, u, v);
  const glm::dvec3 o = centre_ + s.offset * n;
  const double r = std::max(box_.radius(), 1e-300);
  const std::array<Vec3, 3> q = {toVec3(o), toVec3(o + r * u), toVec3(o + r * v)};
  if (collinear(q[0], q[1], q[2])) return;  // rounding flattened them: keep the last plane
  sliders_ = s;
  asked_ = q;
  answer();
}

void Planes3D::setMethod(PlaneMethod m) {
  if (m == method_) return;
  method_ = m;
  ++version_;
}

void Planes3D::answer() {
  ++version_;
  plane_.reset();
  if (!asked_ || !dual_ || !scene_) return;
  const auto& q = *asked_;
  PlaneProbe3D p;
  p.q = q;
  p.dual = dual_->trace(q[0], q[1], q[2]);
  p.vertices = baseline_->trace(q[0], q[1], q[2]);
  if (const CubemapLocator* cube = dual_->dualLocator(); cube && p.dual.proposed) {
    const Vec3 y = p.dual.direction, down{-y.x, -y.y, -y.z};
    p.cellUp = cellOf(dualCells_, cube->trace(y));
    p.cellDown = cellOf(dualCells_, cube->trace(down));
    const auto up = cube->cellFaces(y), dn = cube->cellFaces(down);
    p.listedUp.assign(up.begin(), up.end());
    p.listedDown.assign(dn.begin(), dn.end());
  }
  // the patch: the square around the box middle's foot on the plane, clipped to the box
  const glm::dvec3 n = normalOf(q);
  glm::dvec3 u, v;
  planeAxes(n, u, v);
  const glm::dvec3 foot = box_.middle() - glm::dot(box_.middle() - toGlm(q[0]), n) * n;
  const double half = reach_;
  // a plane far from the box still shows a patch: the clip box holds a cube around its foot
  Bounds3 clip = grownBox();
  clip.lo = glm::min(clip.lo, foot - kFarPatch * half);
  clip.hi = glm::max(clip.hi, foot + kFarPatch * half);
  p.patch = patchIn(clip, foot, u, v, half);
  const double step = 2.0 * half / kSectionSamples;
  p.section = sampleSection(scene_->locator(), foot - half * u - half * v, step * u, step * v,
                            kSectionSamples);
  plane_ = std::move(p);
}

// === The inspector's text

std::vector<TraceLine> describePlane(const PlaneProbe3D& p, PlaneMethod method,
                                     std::span<const Vec3> dualVertices) {
  std::vector<TraceLine> out;
  const PlaneTrace& t = p.chosen(method);
  out.push_back({TraceLine::Step, "plane through q1 " + exactText(p.q[0])});
  out.push_back({TraceLine::Step, "q2 " + exactText(p.q[1])});
  out.push_back({TraceLine::Step, "q3 " + exactText(p.q[2])});
  out.push_back({TraceLine::Step, "G(v) = orient3d(q1, q2, q3, v), exact"});
  out.push_back({TraceLine::Heading, std::string("method ") + std::string(toString(method)) + ", " +
                                         std::string(costOf(method))});
  if (method == PlaneMethod::Dual) {
    if (!dualVertices.empty())
      out.push_back({TraceLine::Step, "dual P*: " + std::to_string(dualVertices.size()) +
                                          " vertices (the unit face normals)"});
    describeCells(p, out);
  } else {
    out.push_back({TraceLine::Step, "every vertex's sign of G"});
  }
  describeExtremes(t.extremes, "G", t.comparisons, out);
  const PlaneMethod other = method == PlaneMethod::Dual ? PlaneMethod::Vertices : PlaneMethod::Dual;
  const Crossing otherAnswer = p.chosen(other).crossing;
  out.push_back({p.agree() ? TraceLine::Step : TraceLine::Negative,
                 std::string(toString(other)) + " says " + std::string(toString(otherAnswer)) +
                     (p.agree() ? ": the methods agree" : ": the methods DISAGREE")});
  out.push_back({TraceLine::Result, "the plane " + std::string(toString(t.crossing))});
  return out;
}

}  // namespace convexloc::viewer
