// convexloc — faces as planes: adjacent triangles that lie in exactly one plane are merged
// into one plane face before any locator builds.
//
// Two triangles sharing an edge lie in one plane iff the far corner of one is on the plane
// of the other (exact orient3d = 0); the relation is transitive along the shared triangle,
// so a flood fill over such neighbours gathers each plane face. On a convex surface a plane
// face is a convex polygon (checkConvexEdges refused folds), so its boundary edges, taken in
// the triangles' own counter-clockwise order, chain into one loop. A fan-triangulated cap
// of 4094 slivers becomes one face, tested by one fat triangle of its corners.
#include <cstdint>
#include <string>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/predicates.hpp"
#include "detail/polyhedron_build.hpp"

namespace convexloc::detail {
namespace {

constexpr std::uint32_t kNone = 0xffffffffu;

using Triangle = ConvexPolyhedron::Triangle;

// the corner of triangle u that is not on its edge shared with a, b
std::uint32_t farCorner(const Triangle& u, std::uint32_t a, std::uint32_t b) {
  for (std::uint32_t w : u)
    if (w != a && w != b) return w;
  return u[0];
}

// squared length of b - a, in double (for choosing, never deciding)
double length2(Vec3 a, Vec3 b) {
  const double x = b.x - a.x, y = b.y - a.y, z = b.z - a.z;
  return x * x + y * y + z * z;
}

// squared length of (b - a) x (c - a), in double (for choosing, never deciding)
double cross2(Vec3 a, Vec3 b, Vec3 c) {
  const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
  const double wx = c.x - a.x, wy = c.y - a.y, wz = c.z - a.z;
  const double nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
  return nx * nx + ny * ny + nz * nz;
}

// Three corners of a loop far apart, in loop order (so counter-clockwise from outside):
// the first, the farthest from it, and the farthest from the line through both. A fat
// triangle keeps the floating-point filter of the plane tests sharp.
Triangle fatTriangle(const std::vector<Vec3>& v, const std::uint32_t* loop, std::size_t m) {
  std::size_t b = 1, c = 2;
  double best = -1;
  for (std::size_t i = 1; i < m; ++i) {
    const double d = length2(v[loop[0]], v[loop[i]]);
    if (d > best) best = d, b = i;
  }
  best = -1;
  for (std::size_t i = 1; i < m; ++i) {
    const double d = i == b ? -1 : cross2(v[loop[0]], v[loop[b]], v[loop[i]]);
    if (d > best) best = d, c = i;
  }
  if (c < b) std::swap(b, c);
  return {loop[0], loop[b], loop[c]};
}

}  // namespace

void PolyhedronBuilder::mergePlanes() {
  const std::vector<Vec3>& v = out_.vertices_;
  const std::vector<Triangle>& tri = out_.triangles_;
  const std::vector<Triangle>& nb = out_.neighbours_;
  const auto nt = static_cast<std::uint32_t>(tri.size());
  std::vector<std::uint32_t>& planeOf = out_.planeOf_;
  planeOf.assign(nt, kNone);
  std::uint32_t planes = 0;
  std::vector<std::uint32_t> stack;
  for (std::uint32_t t = 0; t < nt; ++t) {
    if (planeOf[t] != kNone) continue;
    planeOf[t] = planes;
    stack.assign(1, t);
    while (!stack.empty()) {
      const std::uint32_t x = stack.back();
      stack.pop_back();
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t u = nb[x][k];
        if (planeOf[u] != kNone) continue;
        const std::uint32_t w = farCorner(tri[u], tri[x][k], tri[x][(k + 1) % 3]);
        if (orient3d(v[tri[x][0]], v[tri[x][1]], v[tri[x][2]], v[w]) != 0) continue;
        planeOf[u] = planes;
        stack.push_back(u);
      }
    }
    ++planes;
  }
  groupTrianglesByPlane(planes);
  chainPlaneLoops();
}

void PolyhedronBuilder::groupTrianglesByPlane(std::uint32_t planes) {
  // a counting sort by plane: each face's triangles stay in increasing order
  std::vector<std::uint32_t>& start = out_.trianglesStart_;
  start.assign(planes + 1, 0);
  for (std::uint32_t f : out_.planeOf_) ++start[f + 1];
  for (std::uint32_t f = 0; f < planes; ++f) start[f + 1] += start[f];
  out_.planeTriangles_.resize(out_.planeOf_.size());
  std::vector<std::uint32_t> cursor(start.begin(), start.end() - 1);
  for (std::uint32_t t = 0; t < out_.planeOf_.size(); ++t)
    out_.planeTriangles_[cursor[out_.planeOf_[t]]++] = t;
}

void PolyhedronBuilder::chainPlaneLoops() {
  const std::vector<Triangle>& tri = out_.triangles_;
  const std::vector<Triangle>& nb = out_.neighbours_;
  const std::size_t planes = out_.trianglesStart_.size() - 1;
  std::vector<std::uint32_t> next(out_.vertices_.size(), kNone);
  out_.planes_.resize(planes);
  out_.loops_.clear();
  out_.loopStart_.assign(1, 0);
  for (std::size_t f = 0; f < planes; ++f) {
    const std::span<const std::uint32_t> members = out_.planeTriangles(f);
    std::uint32_t first = kNone, edges = 0;
    for (std::uint32_t t : members)
      for (int k = 0; k < 3; ++k)
        if (out_.planeOf_[nb[t][k]] != f) {
          next[tri[t][k]] = tri[t][(k + 1) % 3];
          if (first == kNone) first = tri[t][k];
          ++edges;
        }
    const std::size_t at = out_.loops_.size();
    for (std::uint32_t a = first; a != kNone && out_.loops_.size() - at <= edges;) {
      out_.loops_.push_back(a);
      const std::uint32_t b = next[a];
      next[a] = kNone;
      a = b == first ? kNone : b;
    }
    const std::size_t m = out_.loops_.size() - at;
    for (std::uint32_t x : std::span(out_.loops_).subspan(at)) next[x] = kNone;
    if (m != edges || m < 3)  // a plane face of a convex surface is one disc
      throw GeometryError("not convex: the coplanar triangles of face " +
                          std::to_string(out_.sourceFace_[members[0]]) +
                          " do not form one polygon");
    out_.loopStart_.push_back(static_cast<std::uint32_t>(out_.loops_.size()));
    const Triangle fat = members.size() == 1
                             ? tri[members[0]]
                             : fatTriangle(out_.vertices_, out_.loops_.data() + at, m);
    const std::vector<Vec3>& v = out_.vertices_;
    out_.planes_[f] = collinear(v[fat[0]], v[fat[1]], v[fat[2]]) ? tri[members[0]] : fat;
  }
}

}  // namespace convexloc::detail
