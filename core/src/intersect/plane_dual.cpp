// convexloc — the dual method in 3D: the cube map of the dual polyhedron proposes the
// vertices where a plane's side function is largest and smallest, an exact climb over the
// vertex graph confirms them.
//
// Duality. With the polar dual P* of P about a point c strictly inside, face f of P is a
// vertex a_f of P*, and vertex v of P is the face of P* spanned by the a_f of the faces
// around v. The vertex of P farthest along a direction w is v exactly when w lies in the
// cone of those a_f, that is when the ray from the origin along w leaves P* through the face
// dual to v: cube-map point location's question, asked of P*. Only the directions of the
// a_f matter, so the dual built here, Q, is Qhull's hull of the unit outward face normals
// (coplanar faces give one normal, up to rounding; Qhull may drop a point within rounding
// of the hull). Q's vertices lie on the unit sphere; each triangle of Q is labelled with the
// vertex of P farthest along its middle direction (floating point, a proposal only).
//
// The query. For G(v) = orient3d(q1, q2, q3, v) = (q1 - v) . N, N = (q2 - q1) x (q3 - q1), G
// is largest at the vertex farthest along w = -N and smallest at the one farthest along N.
// The cube map is asked for the cell of the point y = w / |w| on the unit sphere (and of -y)
// and proposes the label of the middle face that cell lists. Conservative cell: by the cube
// map's contract the cell lists every face of Q through which the ray from its centre c*
// through y leaves Q. The triangle T of Q that the origin's ray along w meets lies within
// its sagitta h (the gap between T and the sphere, about the square of T's angular size over
// 8) of y, so the ray from c* through y leaves Q within about h |y - c*| / (its distance to
// Q's inner sphere) of y: through T or a triangle near it, whose label is the extreme vertex
// or one of its neighbours in the vertex graph. On a finely tessellated surface (many small
// faces, h tiny) the proposal is the extreme vertex, or one move from it, except where w lies
// within rounding of a face normal.
//
// Exactness and cost. The climb (graph3d.hpp) compares vertices exactly and stops only at a
// largest vertex, so the answer, from the exact signs of G at the two vertices it reaches, is
// exact whatever the proposals. Each move costs a vertex's degree in comparisons. It is O(1)
// when the proposals are within a few moves of the extremes (above); where they are not (a
// coarse dual on a polyhedron with few faces, or rounding) the climb is longer, O(V) at worst.
#include "intersect/plane_dual.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/table.hpp"

namespace convexloc::detail {

namespace {

// b - a scaled by a power of two to magnitudes near 1 (halved first where it would overflow)
Vec3 scaledDifference(Vec3 a, Vec3 b) {
  Vec3 d{b.x - a.x, b.y - a.y, b.z - a.z};
  if (!(std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z) <= std::numeric_limits<double>::max()))
    d = {b.x * 0.5 - a.x * 0.5, b.y * 0.5 - a.y * 0.5, b.z * 0.5 - a.z * 0.5};
  const double big = std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z)});
  if (big == 0) return d;
  const int shift = -std::ilogb(big);
  return {std::ldexp(d.x, shift), std::ldexp(d.y, shift), std::ldexp(d.z, shift)};
}

// the unit vector along u x v (zero when they are parallel)
Vec3 unitCross(Vec3 u, Vec3 v) {
  const Vec3 n{u.y * v.z - u.z * v.y, u.z * v.x - u.x * v.z, u.x * v.y - u.y * v.x};
  const double length = std::sqrt(n.x * n.x + n.y * n.y + n.z * n.z);
  if (!(length > 0)) return {};
  return {n.x / length, n.y / length, n.z / length};
}

// the unit outward normal of every face, repeats removed
std::vector<Vec3> unitNormals(const ConvexPolyhedron& p) {
  std::vector<Vec3> out;
  out.reserve(p.faceCount());
  const auto v = p.vertices();
  for (const auto& t : p.triangles()) {
    const Vec3 n =
        unitCross(scaledDifference(v[t[0]], v[t[1]]), scaledDifference(v[t[0]], v[t[2]]));
    if (n.x != 0 || n.y != 0 || n.z != 0) out.push_back(n);
  }
  auto less = [](Vec3 a, Vec3 b) {
    return a.x != b.x ? a.x < b.x : (a.y != b.y ? a.y < b.y : a.z < b.z);
  };
  std::sort(out.begin(), out.end(), less);
  out.erase(std::unique(out.begin(), out.end()), out.end());
  return out;
}

// the vertices scaled by a power of two to magnitudes near 1, for floating-point dot products
std::vector<Vec3> scaledVertices(std::span<const Vec3> v) {
  double big = 0.0;
  for (const Vec3 p : v) big = std::max({big, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
  const int shift = big > 0 ? -std::ilogb(big) : 0;
  std::vector<Vec3> out;
  out.reserve(v.size());
  for (const Vec3 p : v)
    out.push_back({std::ldexp(p.x, shift), std::ldexp(p.y, shift), std::ldexp(p.z, shift)});
  return out;
}

double dot(Vec3 a, Vec3 b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}

// from vertex `at`, to the best neighbour while one lies farther along w (floating point)
std::uint32_t climbAlong(const VertexGraph& graph, const std::vector<Vec3>& v, Vec3 w,
                         std::uint32_t at) {
  for (std::size_t k = 0; k < v.size(); ++k) {
    std::uint32_t best = at;
    double bestDot = dot(w, v[at]);
    for (const std::uint32_t n : graph.of(at))
      if (const double d = dot(w, v[n]); d > bestDot) best = n, bestDot = d;
    if (best == at) break;
    at = best;
  }
  return at;
}

// For every triangle of the dual, the vertex of P farthest along its middle direction: a
// breadth-first walk over the dual's triangles, each climb starting from its parent's label.
std::vector<std::uint32_t> labelFaces(const ConvexPolyhedron& dual, const VertexGraph& graph,
                                      const std::vector<Vec3>& scaled) {
  const auto q = dual.vertices();
  const auto tri = dual.triangles();
  auto middle = [&](std::size_t t) {
    const Vec3 a = q[tri[t][0]], b = q[tri[t][1]], c = q[tri[t][2]];
    return Vec3{a.x + b.x + c.x, a.y + b.y + c.y, a.z + b.z + c.z};
  };
  constexpr std::uint32_t kUnset = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> labels(tri.size(), kUnset);
  std::queue<std::uint32_t> pending;
  labels[0] = climbAlong(graph, scaled, middle(0), 0);
  pending.push(0);
  while (!pending.empty()) {
    const std::uint32_t t = pending.front();
    pending.pop();
    for (const std::uint32_t n : dual.neighbours()[t]) {
      if (labels[n] != kUnset) continue;
      labels[n] = climbAlong(graph, scaled, middle(n), labels[t]);
      pending.push(n);
    }
  }
  return labels;
}

}  // namespace

DualCubemap3D::DualCubemap3D(const ConvexPolyhedron& polyhedron, const VertexGraph& graph) {
  const std::vector<Vec3> normals = unitNormals(polyhedron);
  try {
    const ConvexPolyhedron dual = ConvexPolyhedron::hullOf(normals);
    dualVertices_ = dual.vertexCount();
    labels_ = labelFaces(dual, graph, scaledVertices(polyhedron.vertices()));
    cube_.emplace(dual);
  } catch (const GeometryError&) {
    labels_.clear();  // no dual: every query climbs from vertex 0
  }
}

Vec3 DualCubemap3D::aim(Vec3 q1, Vec3 q2, Vec3 q3) noexcept {
  // w = -N, N = (q2 - q1) x (q3 - q1): G is largest along w
  return unitCross(scaledDifference(q1, q3), scaledDifference(q1, q2));
}

bool DualCubemap3D::propose(Vec3 q1, Vec3 q2, Vec3 q3, std::uint32_t& largest,
                            std::uint32_t& smallest, std::uint32_t& listedLargest,
                            std::uint32_t& listedSmallest) const noexcept {
  if (!cube_) return false;
  const Vec3 w = aim(q1, q2, q3);
  const auto up = cube_->cellFaces(w), down = cube_->cellFaces({-w.x, -w.y, -w.z});
  if (up.empty() || down.empty()) return false;
  largest = labels_[up[up.size() / 2]];
  smallest = labels_[down[down.size() / 2]];
  listedLargest = static_cast<std::uint32_t>(up.size());
  listedSmallest = static_cast<std::uint32_t>(down.size());
  return true;
}

std::size_t DualCubemap3D::bytes() const noexcept {
  return (cube_ ? cube_->stats().bytes : 0) + bytesOf(labels_);
}

}  // namespace convexloc::detail
