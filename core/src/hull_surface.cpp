// convexloc — the canonical surface of an exact 3D hull: the extreme points as corners, the
// maximal planes as faces, one triangulation whatever order the points came in.
//
// Why the kept corners are exactly the extreme points.
//   The incremental hull's triangles bound H = conv(points); their corners are input points,
//   and some lie on an edge of H or inside a face of H (made corners while they were
//   outside, then covered by later points). Adjacent triangles lie in one plane iff the far
//   corner of one is on the other's plane (exact orient3d = 0); a flood fill over such
//   neighbours gathers each face of H, which is a convex polygon, so the boundary edges of
//   its triangles chain into one loop, counter-clockwise from outside. A point inside a face
//   is on no loop. A point on an edge of H, strictly between its ends, lies between its two
//   neighbours on every loop through it: collinear with them. An extreme point v is a corner
//   of every face of H that holds it (a face is H cut by a supporting plane, and v is extreme
//   in it): on each loop through v its neighbours and v are not collinear, and v is on at
//   least three loops. So "not collinear with its loop neighbours" (exact orient2d on the
//   three coordinate planes) keeps every extreme point and nothing else.
//   The faces are the planes of H, so each face's loop without its dropped points is the
//   convex polygon of its extreme points, in counter-clockwise order: a fan from any corner
//   covers it with nondegenerate triangles (no three corners of it are collinear).
//   Everything that is written out depends only on H: corners sorted by coordinates, a fan
//   from each face's smallest corner, faces ordered by their first two corners (no two faces
//   share a directed edge, so the order is strict).
#include "detail/hull_surface.hpp"

#include <algorithm>
#include <numeric>
#include <stdexcept>
#include <utility>

#include "convexloc/predicates.hpp"
#include "detail/polyhedron_build.hpp"

namespace convexloc::detail {
namespace {

using Triangle = std::array<std::uint32_t, 3>;
constexpr std::uint32_t kNone = 0xffffffffu;

// x, then y, then z
bool lexLess(Vec3 a, Vec3 b) {
  if (a.x != b.x) return a.x < b.x;
  if (a.y != b.y) return a.y < b.y;
  return a.z < b.z;
}

// the corner of u that is not on the edge a, b
std::uint32_t farCorner(const Triangle& u, std::uint32_t a, std::uint32_t b) {
  for (std::uint32_t w : u)
    if (w != a && w != b) return w;
  return u[0];
}

// faces as lists of triangles (CSR): triangles flood-filled across exactly coplanar edges
struct Faces {
  std::vector<std::uint32_t> start{0}, members;
};

Faces coplanarFaces(std::span<const Vec3> p, std::span<const Triangle> tri,
                    std::span<const Triangle> nb) {
  const auto nt = static_cast<std::uint32_t>(tri.size());
  std::vector<std::uint32_t> seen(nt, kNone);
  Faces faces;
  faces.members.reserve(nt);
  for (std::uint32_t t = 0; t < nt; ++t) {
    if (seen[t] != kNone) continue;
    seen[t] = t;
    const std::size_t first = faces.members.size();
    faces.members.push_back(t);
    for (std::size_t i = first; i < faces.members.size(); ++i) {
      const Triangle& x = tri[faces.members[i]];
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t u = nb[faces.members[i]][k];
        if (seen[u] != kNone) continue;
        const std::uint32_t w = farCorner(tri[u], x[k], x[(k + 1) % 3]);
        if (orient3d(p[x[0]], p[x[1]], p[x[2]], p[w]) != 0) continue;
        seen[u] = t;
        faces.members.push_back(u);
      }
    }
    faces.start.push_back(static_cast<std::uint32_t>(faces.members.size()));
  }
  return faces;
}

// each face's boundary loop, counter-clockwise from outside (CSR like Faces)
Faces boundaryLoops(std::size_t pointCount, std::span<const Triangle> tri,
                    std::span<const Triangle> nb, const Faces& faces) {
  std::vector<std::uint32_t> faceOf(tri.size()), next(pointCount, kNone);
  const std::size_t count = faces.start.size() - 1;
  for (std::uint32_t f = 0; f < count; ++f)
    for (std::uint32_t i = faces.start[f]; i < faces.start[f + 1]; ++i)
      faceOf[faces.members[i]] = f;
  Faces loops;
  for (std::uint32_t f = 0; f < count; ++f) {
    std::uint32_t first = kNone, edges = 0;
    for (std::uint32_t i = faces.start[f]; i < faces.start[f + 1]; ++i) {
      const std::uint32_t t = faces.members[i];
      for (int k = 0; k < 3; ++k)
        if (faceOf[nb[t][k]] != f) {
          next[tri[t][k]] = tri[t][(k + 1) % 3];
          first = first == kNone ? tri[t][k] : first;
          ++edges;
        }
    }
    const std::size_t at = loops.members.size();
    for (std::uint32_t a = first; a != kNone && loops.members.size() - at <= edges;) {
      loops.members.push_back(a);
      a = std::exchange(next[a], kNone);
      if (a == first) a = kNone;
    }
    if (loops.members.size() - at != edges || edges < 3)
      throw std::logic_error("hull: a face's boundary is not one loop");
    loops.start.push_back(static_cast<std::uint32_t>(loops.members.size()));
  }
  return loops;
}

// per point: 1 where it is a corner not collinear with its neighbours on some loop
std::vector<std::uint8_t> extremeCorners(std::span<const Vec3> p, const Faces& loops) {
  std::vector<std::uint8_t> extreme(p.size(), 0);
  for (std::size_t f = 0; f + 1 < loops.start.size(); ++f) {
    const std::uint32_t* loop = loops.members.data() + loops.start[f];
    const std::size_t m = loops.start[f + 1] - loops.start[f];
    for (std::size_t i = 0; i < m; ++i) {
      const std::uint32_t v = loop[i];
      if (!extreme[v] && !collinear(p[loop[(i + m - 1) % m]], p[v], p[loop[(i + 1) % m]]))
        extreme[v] = 1;
    }
  }
  return extreme;
}

// each loop as the ranks of its extreme corners (kNone: not one), from the smallest rank
Faces rankedPolygons(const Faces& loops, const std::vector<std::uint32_t>& rank) {
  Faces polygons;
  std::vector<std::uint32_t>& out = polygons.members;
  for (std::size_t f = 0; f + 1 < loops.start.size(); ++f) {
    const auto at = static_cast<std::ptrdiff_t>(out.size());
    for (std::uint32_t i = loops.start[f]; i < loops.start[f + 1]; ++i)
      if (const std::uint32_t r = rank[loops.members[i]]; r != kNone) out.push_back(r);
    if (out.size() - static_cast<std::size_t>(at) < 3)
      throw std::logic_error("hull: a face has fewer than 3 corners");
    std::rotate(out.begin() + at, std::min_element(out.begin() + at, out.end()), out.end());
    polygons.start.push_back(static_cast<std::uint32_t>(out.size()));
  }
  return polygons;
}

}  // namespace

CanonicalSurface canonicalSurface(std::span<const Vec3> points, std::span<const Triangle> triangles,
                                  std::span<const Triangle> neighbours) {
  const Faces loops = boundaryLoops(points.size(), triangles, neighbours,
                                    coplanarFaces(points, triangles, neighbours));
  const std::vector<std::uint8_t> extreme = extremeCorners(points, loops);
  CanonicalSurface out;
  for (std::uint32_t i = 0; i < points.size(); ++i)
    if (extreme[i]) out.corners.push_back(i);
  std::sort(out.corners.begin(), out.corners.end(),
            [&](std::uint32_t a, std::uint32_t b) { return lexLess(points[a], points[b]); });
  std::vector<std::uint32_t> rank(points.size(), kNone);
  for (std::uint32_t r = 0; r < out.corners.size(); ++r) rank[out.corners[r]] = r;
  const Faces polygons = rankedPolygons(loops, rank);
  // the faces in order of their first two corners, each as a fan from its first
  const std::vector<std::uint32_t>& c = polygons.members;
  std::vector<std::uint32_t> order(polygons.start.size() - 1);
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t f, std::uint32_t g) {
    const std::uint32_t a = polygons.start[f], b = polygons.start[g];
    return c[a] != c[b] ? c[a] < c[b] : c[a + 1] < c[b + 1];
  });
  out.triangles.reserve(2 * out.corners.size());
  for (const std::uint32_t f : order) {
    const std::uint32_t at = polygons.start[f], end = polygons.start[f + 1];
    for (std::uint32_t i = at + 1; i + 1 < end; ++i)
      out.triangles.push_back({c[at], c[i], c[i + 1]});
  }
  return out;
}

}  // namespace convexloc::detail
