// convexloc — the dual method in 3D: the dual polyhedron's cells of directions propose the
// vertices where a plane's side function is largest and smallest, an exact climb over the
// vertex graph confirms them.
//
// Duality. With the polar dual P* of P about a point c strictly inside, face f of P is a
// vertex a_f of P*, and vertex v of P is the face of P* spanned by the a_f of the faces
// around v. The vertex of P farthest along a direction w is v exactly when w lies in the cone
// of those a_f, that is when the ray from the origin along w leaves P* through the face dual
// to v: cube-map point location's question, asked of P*. Only the directions of the a_f
// matter. Two tables answer it here:
//   - the cube map of Q, the exact hull of the unit outward face normals (the dual itself),
//     which lists per cell the faces of Q the cell's rays may leave through: for `info`, the
//     viewer and the trace (how many faces a plane's cells list);
//   - the direction grid, a cube map of directions with side g per cube face and no lists,
//     its cells found and numbered as the cube map's base cells (cubemap/index.hpp):
//     each cell proposes the vertex of P farthest along the cell's middle direction (the face
//     of Q that direction's ray leaves through, found at build time by a floating-point climb
//     from the previous cell's vertex) and holds a copy of that vertex's star record.
// A star record (dual_cubemap.hpp) is all a climb reads of a vertex: the vertex and its
// neighbours' coordinates, and where each neighbour's own record lies; one per vertex, laid
// out on cache lines. A cell's copy (four cache lines, degree 8 at most; a vertex of higher
// degree is found through its index instead) makes the proposal's star the one read that
// depends on nothing but the plane, and a move one more read.
//
// The query. For G(v) = orient3d(q1, q2, q3, v) = (q1 - v) . N, N = (q2 - q1) x (q3 - q1), G
// is largest at the vertex farthest along w = -N and smallest at the one farthest along N.
// The grid cells of w and of -w are computed from w alone (no table read), and each proposes
// its vertex: the extreme for directions near the cell's middle, a neighbour of it or close
// for the rest of the cell, since a cell is about half a vertex's cone wide on a finely
// tessellated surface (about 2 cells per vertex).
//
// Exactness and cost. The climb compares vertices exactly (graph3d.hpp) and stops only at a
// vertex none of whose neighbours is strictly larger, a largest vertex, so the answer, from
// the exact signs of G at the two vertices it reaches, is exact whatever the proposals. It
// reads the proposal's star (the cell's copy: four cache lines requested at once), and each
// move one more record and a vertex's degree in comparisons. It is O(1) when the proposals
// are within a few moves of the extremes (fine surfaces, as above); where they are not (a
// polyhedron whose vertex cones differ in size by orders of magnitude, or with vertices of
// very high degree) the climb is longer, O(V) at worst.
#include "intersect/dual_cubemap.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <queue>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/table.hpp"
#include "cubemap/index.hpp"
#include "detail/bit_cast.hpp"

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

// The grid's side for a polyhedron of n vertices: about 2 cells per vertex, so a cell is about
// half a vertex's cone of directions on a fine surface; at most 1024 (6 Mi cells of 256 bytes),
// beyond which cells widen and climbs lengthen.
std::uint32_t gridSideFor(std::size_t n) {
  const double side = std::ceil(std::sqrt(2.0 * static_cast<double>(n) / 6.0));
  return static_cast<std::uint32_t>(std::clamp(side, 1.0, 1024.0));
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

// Each record: a header word (vertex, degree), the star's points, then the neighbours'
// record indices two to a word, padded to whole cache lines.
void DualCubemap3D::buildRecords(const ConvexPolyhedron& polyhedron, const VertexGraph& graph,
                                 std::vector<std::uint32_t>& recordOf) {
  const std::uint32_t n = static_cast<std::uint32_t>(polyhedron.vertexCount());
  auto words = [&](std::uint32_t v) {
    const std::size_t degree = graph.of(v).size();
    const std::size_t used = 1 + 3 * (degree + 1) + (degree + 1) / 2;
    return (used + kRecordWords - 1) / kRecordWords;  // in records' units
  };
  recordOf.resize(n);
  std::size_t total = 0;
  for (std::uint32_t v = 0; v < n; ++v) {
    recordOf[v] = static_cast<std::uint32_t>(total);
    total += words(v);
  }
  records_.assign(total * kRecordWords, 0);
  const auto points = polyhedron.vertices();
  for (std::uint32_t v = 0; v < n; ++v) {
    std::uint64_t* w = records_.data() + std::size_t{recordOf[v]} * kRecordWords;
    const auto around = graph.of(v);
    w[0] = v | std::uint64_t{static_cast<std::uint32_t>(around.size())} << 32;
    auto put = [&](std::size_t k, Vec3 p) {
      w[1 + 3 * k] = detail::bit_cast<std::uint64_t>(p.x);
      w[2 + 3 * k] = detail::bit_cast<std::uint64_t>(p.y);
      w[3 + 3 * k] = detail::bit_cast<std::uint64_t>(p.z);
    };
    put(0, points[v]);
    std::uint64_t* links = w + 1 + 3 * (around.size() + 1);
    for (std::size_t k = 0; k < around.size(); ++k) {
      put(k + 1, points[around[k]]);
      links[k / 2] |= std::uint64_t{recordOf[around[k]]} << (k % 2 ? 32 : 0);
    }
  }
}

DualCubemap3D::DualCubemap3D(const ConvexPolyhedron& polyhedron, const VertexGraph& graph) {
  const std::vector<Vec3> scaled = scaledVertices(polyhedron.vertices());
  std::vector<std::uint32_t> recordOf;
  buildRecords(polyhedron, graph, recordOf);
  // the grid: each cell proposes the vertex farthest along its middle direction, climbing
  // from the previous cell's proposal (neighbouring cells, neighbouring vertices)
  side_ = gridSideFor(scaled.size());
  const std::size_t cells = 6 * std::size_t{side_} * side_;
  grid_.assign(cells * kCellWords, 0);
  std::uint32_t at = 0;
  for (std::size_t c = 0; c < cells; ++c) {
    at = climbAlong(graph, scaled, cubemap::cellDirection(c, side_), at);
    std::uint64_t* cell = grid_.data() + c * kCellWords;
    const std::uint64_t* from = records_.data() + std::size_t{recordOf[at]} * kRecordWords;
    const std::size_t words =
        (at + 1 < recordOf.size() ? recordOf[at + 1] * kRecordWords : records_.size()) -
        recordOf[at] * kRecordWords;
    if (words <= kCellWords) {
      std::copy(from, from + words, cell);
    } else {
      cell[0] = at | kElsewhere << 32;
      cell[1] = recordOf[at];
    }
  }
  const std::vector<Vec3> normals = unitNormals(polyhedron);
  try {
    const ConvexPolyhedron dual = ConvexPolyhedron::hullOf(normals);
    dualVertices_ = dual.vertexCount();
    dualFaces_ = dual.planeCount();
    // the cube map locates in the dual's plane faces: each keeps its lowest triangle's label
    const std::vector<std::uint32_t> byTriangle = labelFaces(dual, graph, scaled);
    labels_.resize(dual.planeCount());
    for (std::size_t f = 0; f < dual.planeCount(); ++f)
      labels_[f] = byTriangle[dual.planeTriangles(f)[0]];
    cube_.emplace(dual);
  } catch (const GeometryError&) {
    dualFaces_ = 0;  // no dual: the grid still proposes, the trace lists no cube-map cells
    labels_.clear();
  }
}

Vec3 DualCubemap3D::aim(Vec3 q1, Vec3 q2, Vec3 q3) noexcept {
  // w = -N, N = (q2 - q1) x (q3 - q1): G is largest along w
  return unitCross(scaledDifference(q1, q3), scaledDifference(q1, q2));
}

bool DualCubemap3D::cells(Vec3 q1, Vec3 q2, Vec3 q3, std::int64_t& up,
                          std::int64_t& down) const noexcept {
  const Vec3 w = aim(q1, q2, q3);
  up = cubemap::directionCell(w, side_);
  down = cubemap::directionCell({-w.x, -w.y, -w.z}, side_);
  return up >= 0 && down >= 0;
}

bool DualCubemap3D::listed(Vec3 q1, Vec3 q2, Vec3 q3, std::uint32_t& largest,
                           std::uint32_t& smallest) const noexcept {
  if (!cube_) return false;
  const Vec3 w = aim(q1, q2, q3);
  largest = static_cast<std::uint32_t>(cube_->cellFaces(w).size());
  smallest = static_cast<std::uint32_t>(cube_->cellFaces({-w.x, -w.y, -w.z}).size());
  return true;
}

std::size_t DualCubemap3D::bytes() const noexcept {
  return (cube_ ? cube_->stats().bytes : 0) + bytesOf(grid_) + bytesOf(records_) +
         labels_.size() * sizeof(std::uint32_t);
}

}  // namespace convexloc::detail
