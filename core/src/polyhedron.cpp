// convexloc — validation and normalisation of convex polyhedra.
//
// The checks run from the cheap and local to the global, so that the first error is the
// most specific one: indices and numbers, faces, edges (open, non-manifold, orientation),
// pieces and Euler characteristic, volume, then convexity edge by edge (exact orient3d),
// and last the global test that the surface wraps around its inside exactly once.
#include "convexloc/polyhedron.hpp"

#include <gmpxx.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>
#include <sstream>
#include <string>

#include "convexloc/error.hpp"
#include "convexloc/predicates.hpp"

namespace convexloc {
namespace {

constexpr std::uint32_t kNone = 0xffffffffu;

// "(x, y, z)" with enough digits to find the point again
std::string show(Vec3 p) {
  std::ostringstream s;
  s.precision(17);
  s << '(' << p.x << ", " << p.y << ", " << p.z << ')';
  return s.str();
}

// a, b, c lie on one line (exact: every component of (b - a) x (c - a) is zero)
bool collinear(Vec3 a, Vec3 b, Vec3 c) {
  return orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) == 0 &&
         orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}) == 0 &&
         orient2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x}) == 0;
}

// b lies between a and c, given that the three are collinear
bool between(Vec3 a, Vec3 b, Vec3 c) {
  auto in = [](double lo, double v, double hi) {
    return (lo <= v && v <= hi) || (hi <= v && v <= lo);
  };
  return in(a.x, b.x, c.x) && in(a.y, b.y, c.y) && in(a.z, b.z, c.z);
}

// the sign of the 2D orientation of a, b, c projected on the first coordinate plane where
// the triangle a, b, c does not degenerate, together with d projected on the same plane
std::pair<int, int> planarSides(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  int s = orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y});
  if (s != 0) return {s, orient2d({a.x, a.y}, {b.x, b.y}, {d.x, d.y})};
  s = orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z});
  if (s != 0) return {s, orient2d({a.y, a.z}, {b.y, b.z}, {d.y, d.z})};
  s = orient2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x});
  return {s, orient2d({a.z, a.x}, {b.z, b.x}, {d.z, d.x})};
}

// the solid angle of triangle a, b, c seen from the origin (Van Oosterom and Strackee)
double solidAngle(Vec3 a, Vec3 b, Vec3 c) {
  auto dot = [](Vec3 u, Vec3 v) { return u.x * v.x + u.y * v.y + u.z * v.z; };
  auto len = [&](Vec3 u) { return std::sqrt(dot(u, u)); };
  double det =
      a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
  double la = len(a), lb = len(b), lc = len(c);
  double den = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
  return 2.0 * std::atan2(det, den);
}

// six times the signed volume of the tetrahedron (o, a, b, c), in long double
long double sixVolume(Vec3 o, Vec3 a, Vec3 b, Vec3 c, long double (&p)[3][3]) {
  const Vec3 abc[3] = {a, b, c};
  for (int k = 0; k < 3; ++k) {
    p[k][0] = static_cast<long double>(abc[k].x) - o.x;
    p[k][1] = static_cast<long double>(abc[k].y) - o.y;
    p[k][2] = static_cast<long double>(abc[k].z) - o.z;
  }
  return p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
         p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
         p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
}

// union-find root with path halving
std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

// exact sign of det[p - g; q - g; r - g] for a rational g
int rationalOrient(Vec3 p, Vec3 q, Vec3 r, const mpq_class (&g)[3]) {
  mpq_class m[3][3] = {{mpq_class(p.x) - g[0], mpq_class(p.y) - g[1], mpq_class(p.z) - g[2]},
                       {mpq_class(q.x) - g[0], mpq_class(q.y) - g[1], mpq_class(q.z) - g[2]},
                       {mpq_class(r.x) - g[0], mpq_class(r.y) - g[1], mpq_class(r.z) - g[2]}};
  mpq_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                  m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                  m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return mpq_sgn(det.get_mpq_t());
}

// the double next to v in direction dir (-1, 0 or +1)
double nudge(double v, int dir) {
  if (dir == 0) return v;
  return std::nextafter(v, dir > 0 ? HUGE_VAL : -HUGE_VAL);
}

}  // namespace

ConvexPolyhedron::ConvexPolyhedron(const MeshData& mesh) : ConvexPolyhedron(mesh, nullptr) {}

ConvexPolyhedron::ConvexPolyhedron(const MeshData& mesh, std::vector<std::uint32_t>* suspects) {
  const std::vector<Vec3>& pts = mesh.vertices;
  const std::size_t n = pts.size();
  if (mesh.faceStart.empty() || mesh.faceStart.front() != 0 ||
      mesh.faceStart.back() != mesh.indices.size() ||
      !std::is_sorted(mesh.faceStart.begin(), mesh.faceStart.end()))
    throw UsageError("MeshData: faceStart must run from 0 to the number of indices");
  const std::size_t m = mesh.faceCount();
  if (!mesh.vertexLines.empty() && mesh.vertexLines.size() != n)
    throw UsageError("MeshData: vertexLines must be empty or match the vertices");
  if (!mesh.faceLines.empty() && mesh.faceLines.size() != m)
    throw UsageError("MeshData: faceLines must be empty or match the faces");
  auto vertexLine = [&](std::size_t i) {
    return mesh.vertexLines.empty() ? 0 : mesh.vertexLines[i];
  };
  auto faceLine = [&](std::size_t f) { return mesh.faceLines.empty() ? 0 : mesh.faceLines[f]; };
  if (n > kMaxPolyhedronVertices)
    throw UsageError("too many vertices: " + std::to_string(n) + " (the limit is " +
                     std::to_string(kMaxPolyhedronVertices) + ")");
  inputFaces_ = m;

  // === numbers and indices
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(pts[i].x) || !std::isfinite(pts[i].y) || !std::isfinite(pts[i].z))
      throw GeometryError("vertex " + std::to_string(i) + ' ' + show(pts[i]) +
                              " has a coordinate that is not a finite number",
                          vertexLine(i));
  if (m == 0) throw GeometryError("the mesh has no faces", n ? vertexLine(n - 1) : 0);
  std::size_t triangleBound = 0;
  std::vector<std::uint8_t> used(n, 0);
  for (std::size_t f = 0; f < m; ++f) {
    auto face = mesh.face(f);
    if (face.size() < 3)
      throw GeometryError("face " + std::to_string(f) + " has " + std::to_string(face.size()) +
                              (face.size() == 1 ? " vertex" : " vertices") +
                              "; a face needs at least 3",
                          faceLine(f));
    for (std::uint32_t v : face) {
      if (v >= n)
        throw GeometryError("face " + std::to_string(f) + " refers to vertex " + std::to_string(v) +
                                ", but there are only " + std::to_string(n) +
                                " vertices (indices are 0-based)",
                            faceLine(f));
      used[v] = 1;
    }
    triangleBound += face.size() - 2;
  }
  if (triangleBound > kMaxPolyhedronFaces)
    throw UsageError("too many faces: " + std::to_string(triangleBound) +
                     " triangles (the limit is " + std::to_string(kMaxPolyhedronFaces) + ")");

  // === merge equal vertices, drop unused ones
  std::vector<std::uint32_t> id(n, kNone);
  {
    std::vector<std::uint32_t> order;
    order.reserve(n);
    for (std::uint32_t i = 0; i < n; ++i)
      if (used[i]) order.push_back(i);
    unused_ = n - order.size();
    auto less = [&](std::uint32_t a, std::uint32_t b) {
      const Vec3 &p = pts[a], &q = pts[b];
      if (p.x != q.x) return p.x < q.x;
      if (p.y != q.y) return p.y < q.y;
      if (p.z != q.z) return p.z < q.z;
      return a < b;
    };
    std::sort(order.begin(), order.end(), less);
    std::vector<std::uint32_t> rep(n, kNone);
    for (std::size_t k = 0; k < order.size(); ++k) {
      bool same = k > 0 && pts[order[k]] == pts[order[k - 1]];
      rep[order[k]] = same ? rep[order[k - 1]] : order[k];
      merged_ += same;
    }
    for (std::uint32_t i = 0; i < n; ++i)
      if (used[i] && rep[i] == i) {
        id[i] = static_cast<std::uint32_t>(vertices_.size());
        vertices_.push_back(pts[i]);
        sourceVertex_.push_back(i);
      }
    for (std::uint32_t i = 0; i < n; ++i)
      if (used[i]) id[i] = id[rep[i]];
  }
  const std::vector<Vec3>& v = vertices_;
  auto vname = [&](std::uint32_t k) {
    return "vertex " + std::to_string(sourceVertex_[k]) + ' ' + show(v[k]);
  };
  auto ename = [&](std::uint32_t a, std::uint32_t b) {
    return "edge " + std::to_string(sourceVertex_[a]) + '-' + std::to_string(sourceVertex_[b]) +
           " from " + show(v[a]) + " to " + show(v[b]);
  };
  auto fname = [&](std::uint32_t t) { return "face " + std::to_string(sourceFace_[t]); };
  auto tline = [&](std::uint32_t t) { return faceLine(sourceFace_[t]); };

  // === faces: drop consecutive repeats, reject other repeats, fan-triangulate
  triangles_.reserve(triangleBound);
  sourceFace_.reserve(triangleBound);
  {
    std::vector<std::uint32_t> poly, sorted;
    for (std::size_t f = 0; f < m; ++f) {
      poly.clear();
      for (std::uint32_t k : mesh.face(f))
        if (poly.empty() || poly.back() != id[k]) poly.push_back(id[k]);
      while (poly.size() > 1 && poly.back() == poly.front()) poly.pop_back();
      if (poly.size() < 3)
        throw GeometryError(
            "face " + std::to_string(f) + " is degenerate: it has fewer than 3 distinct vertices",
            faceLine(f));
      sorted = poly;
      std::sort(sorted.begin(), sorted.end());
      auto twice = std::adjacent_find(sorted.begin(), sorted.end());
      if (twice != sorted.end())
        throw GeometryError("face " + std::to_string(f) + " visits " + vname(*twice) + " twice",
                            faceLine(f));
      for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
        triangles_.push_back({poly[0], poly[i], poly[i + 1]});
        sourceFace_.push_back(static_cast<std::uint32_t>(f));
      }
    }
  }
  const std::uint32_t nt = static_cast<std::uint32_t>(triangles_.size());
  std::vector<Triangle>& tri = triangles_;

  // === edges: each undirected edge must be used exactly twice, in opposite directions.
  // Half-edges are bucketed by their smaller vertex (counting sort), then sorted per bucket.
  neighbours_.assign(nt, {kNone, kNone, kNone});
  {
    const std::uint32_t nv = static_cast<std::uint32_t>(v.size());
    std::vector<std::uint32_t> start(nv + 1, 0);
    for (const Triangle& t : tri)
      for (int k = 0; k < 3; ++k) ++start[std::min(t[k], t[(k + 1) % 3]) + 1];
    std::partial_sum(start.begin(), start.end(), start.begin());
    std::vector<std::uint32_t> half(start.back());
    {
      std::vector<std::uint32_t> cursor(start.begin(), start.end() - 1);
      for (std::uint32_t t = 0; t < nt; ++t)
        for (std::uint32_t k = 0; k < 3; ++k)
          half[cursor[std::min(tri[t][k], tri[t][(k + 1) % 3])]++] = 3 * t + k;
    }
    auto head = [&](std::uint32_t h) { return tri[h / 3][h % 3]; };
    auto tail = [&](std::uint32_t h) { return tri[h / 3][(h % 3 + 1) % 3]; };
    auto other = [&](std::uint32_t h) { return std::max(head(h), tail(h)); };
    for (std::uint32_t a = 0; a < nv; ++a) {
      auto b = half.begin() + start[a], e = half.begin() + start[a + 1];
      std::sort(b, e, [&](std::uint32_t x, std::uint32_t y) {
        return other(x) != other(y) ? other(x) < other(y) : x < y;
      });
      for (auto it = b; it != e;) {
        auto run = it;
        while (run != e && other(*run) == other(*it)) ++run;
        const std::uint32_t h1 = *it, t1 = h1 / 3;
        const std::size_t count = static_cast<std::size_t>(run - it);
        if (count == 1)
          throw GeometryError("the surface is open: " + ename(head(h1), tail(h1)) + " belongs to " +
                                  fname(t1) + " only",
                              tline(t1));
        if (count > 2) {
          std::string faces;
          for (auto k = it; k != run && k - it < 4; ++k)
            faces += (k == it ? "" : ", ") + std::to_string(sourceFace_[*k / 3]);
          if (count > 4) faces += ", ...";
          throw GeometryError("not a manifold: " + ename(head(h1), tail(h1)) + " is shared by " +
                                  std::to_string(count) + " triangles (faces " + faces + ")",
                              tline(it[2] / 3));
        }
        const std::uint32_t h2 = it[1], t2 = h2 / 3;
        if (head(h1) == head(h2))
          throw GeometryError("inconsistent orientation: " + fname(t1) + " and " + fname(t2) +
                                  " both run along " + ename(head(h1), tail(h1)) +
                                  " in the same direction (orient every face the same way)",
                              tline(t2));
        neighbours_[t1][h1 % 3] = t2;
        neighbours_[t2][h2 % 3] = t1;
        it = run;
      }
    }
  }
  std::vector<Triangle>& nb = neighbours_;

  // === one piece, a topological sphere
  {
    std::vector<std::uint32_t> parent(nt);
    std::iota(parent.begin(), parent.end(), 0u);
    for (std::uint32_t t = 0; t < nt; ++t)
      for (std::uint32_t u : nb[t]) parent[findRoot(parent, t)] = findRoot(parent, u);
    std::size_t pieces = 0;
    std::uint32_t stray = kNone;
    const std::uint32_t root0 = findRoot(parent, 0);
    for (std::uint32_t t = 0; t < nt; ++t) {
      if (findRoot(parent, t) == t) ++pieces;
      if (stray == kNone && findRoot(parent, t) != root0) stray = t;
    }
    if (pieces > 1)
      throw GeometryError("the surface has " + std::to_string(pieces) + " separate pieces (" +
                              fname(stray) + " is not connected to " + fname(0) + ")",
                          tline(stray));
    const long long chi = static_cast<long long>(v.size()) - 3LL * nt / 2 + nt;
    if (chi != 2)
      throw GeometryError(
          "the surface is not a sphere: V - E + F = " + std::to_string(chi) +
          " where a convex polyhedron has 2 (a handle, or faces meeting only at a vertex)");
  }

  // === positive volume: four vertices not in one plane
  std::uint32_t tetra[4] = {0, 1, kNone, kNone};
  {
    const std::uint32_t nv = static_cast<std::uint32_t>(v.size());
    for (std::uint32_t i = 2; i < nv && tetra[2] == kNone; ++i)
      if (!collinear(v[0], v[1], v[i])) tetra[2] = i;
    if (tetra[2] == kNone)
      throw GeometryError("zero volume: all " + std::to_string(nv) + " vertices are collinear");
    for (std::uint32_t i = 2; i < nv && tetra[3] == kNone; ++i)
      if (orient3d(v[0], v[1], v[tetra[2]], v[i]) != 0) tetra[3] = i;
    if (tetra[3] == kNone)
      throw GeometryError("zero volume: all " + std::to_string(nv) + " vertices are coplanar");
  }

  // === zero-area triangles: flip the longest edge into the neighbour across it.
  // With b strictly between a and c, triangle (a, b, c) and its neighbour (a, c, d) become
  // (a, b, d) and (b, c, d): both lie in the neighbour's plane, have its orientation and
  // positive area, and cover the same region of the surface.
  {
    std::vector<std::uint8_t> flat(nt, 0);
    std::vector<std::uint32_t> pending;
    for (std::uint32_t t = 0; t < nt; ++t)
      if (collinear(v[tri[t][0]], v[tri[t][1]], v[tri[t][2]])) {
        flat[t] = 1;
        pending.push_back(t);
      }
    // the slot of t's edge running from p to q
    auto slot = [&](std::uint32_t t, std::uint32_t p, std::uint32_t q) {
      for (int k = 0; k < 3; ++k)
        if (tri[t][k] == p && tri[t][(k + 1) % 3] == q) return k;
      return -1;
    };
    while (!pending.empty()) {
      std::vector<std::uint32_t> later;
      for (std::uint32_t t : pending) {
        int mid = 0;  // the corner strictly between the other two
        while (!between(v[tri[t][(mid + 1) % 3]], v[tri[t][mid]], v[tri[t][(mid + 2) % 3]])) ++mid;
        const std::uint32_t b = tri[t][mid], c = tri[t][(mid + 1) % 3], a = tri[t][(mid + 2) % 3];
        const std::uint32_t u = nb[t][(mid + 1) % 3];  // across c -> a
        const int ku = slot(u, a, c);
        const std::uint32_t d = tri[u][(ku + 2) % 3];
        if (flat[u] || d == b) {
          later.push_back(t);
          continue;
        }
        const std::uint32_t nab = nb[t][(mid + 2) % 3], nbc = nb[t][mid];
        const std::uint32_t ncd = nb[u][(ku + 1) % 3], nda = nb[u][(ku + 2) % 3];
        tri[t] = {a, b, d};
        nb[t] = {nab, u, nda};
        tri[u] = {b, c, d};
        nb[u] = {nbc, ncd, t};
        nb[nda][slot(nda, a, d)] = t;
        nb[nbc][slot(nbc, c, b)] = u;
        sourceFace_[t] = sourceFace_[u];
        flat[t] = 0;
        ++slivers_;
      }
      if (later.size() == pending.size()) {
        const std::uint32_t t = later.front();
        if (suspects) {
          for (std::uint32_t k : later)
            for (std::uint32_t w : tri[k]) suspects->push_back(sourceVertex_[w]);
        }
        throw GeometryError(fname(t) + " is degenerate: " + vname(tri[t][0]) + ", " +
                                vname(tri[t][1]) + " and " + vname(tri[t][2]) +
                                " are collinear (zero area) and no neighbouring face absorbs them",
                            tline(t));
      }
      pending.swap(later);
    }
  }

  // === convexity across every edge, exact: the far vertex of the neighbour must lie on
  // the inner side of the triangle's plane, or in it without folding back over the triangle
  {
    std::size_t convex = 0, reflex = 0;
    std::uint32_t firstConvex = kNone, firstReflex = kNone;
    std::vector<std::uint32_t> convexEdges, reflexEdges;  // for suspects only
    for (std::uint32_t t = 0; t < nt; ++t)
      for (std::uint32_t k = 0; k < 3; ++k) {
        const std::uint32_t u = nb[t][k];
        if (u < t) continue;
        const std::uint32_t a = tri[t][k], b = tri[t][(k + 1) % 3], p = tri[t][(k + 2) % 3];
        std::uint32_t q = tri[u][0];
        for (std::uint32_t w : tri[u])
          if (w != a && w != b) q = w;
        const int s = orient3d(v[a], v[b], v[p], v[q]);
        if (s > 0) {
          if (convex++ == 0) firstConvex = 3 * t + k;
          if (suspects) convexEdges.push_back(a);
        } else if (s < 0) {
          if (reflex++ == 0) firstReflex = 3 * t + k;
          if (suspects) reflexEdges.push_back(a);
        } else {
          auto [sp, sq] = planarSides(v[a], v[b], v[p], v[q]);
          if (sp * sq >= 0) {
            if (suspects) suspects->push_back(sourceVertex_[q]);
            throw GeometryError("not convex: " + fname(t) + " and " + fname(u) +
                                    " lie in one plane and fold onto each other at " + ename(a, b),
                                std::max(tline(t), tline(u)));
          }
        }
      }
    if (convex > 0 && reflex > 0) {
      // the minority is the reflex side: the mesh may be inverted as a whole
      const bool reflexIsMinority = reflex <= convex;
      const std::uint32_t h = reflexIsMinority ? firstReflex : firstConvex;
      if (suspects) {
        for (std::uint32_t w : reflexIsMinority ? reflexEdges : convexEdges)
          suspects->push_back(sourceVertex_[w]);
      }
      const std::uint32_t t = h / 3, k = h % 3, u = nb[t][k];
      throw GeometryError("not convex: reflex " + ename(tri[t][k], tri[t][(k + 1) % 3]) +
                              " between " + fname(t) + " and " + fname(u),
                          std::max(tline(t), tline(u)));
    }
    if (convex == 0 && reflex == 0)
      throw GeometryError("zero volume: every face lies in one plane");
    inverted_ = convex == 0;
    if (inverted_) {
      for (std::uint32_t t = 0; t < nt; ++t) {
        std::swap(tri[t][1], tri[t][2]);
        nb[t] = {nb[t][2], nb[t][1], nb[t][0]};
      }
    }
  }

  // === global: locally convex is convex only if the surface wraps around once.
  // Seen from a point c strictly inside every face plane, each triangle is a positively
  // oriented spherical triangle and neighbours lie on opposite sides of their common edge, so
  // the central projection is a branched covering of the sphere; its degree, the total solid
  // angle over 4 pi, is 1 exactly when the surface is the boundary of the convex solid.
  auto insideAll = [&](Vec3 c, std::uint32_t& hint) {
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) return false;
    if (orient3d(v[tri[hint][0]], v[tri[hint][1]], v[tri[hint][2]], c) <= 0) return false;
    for (std::uint32_t t = 0; t < nt; ++t)
      if (orient3d(v[tri[t][0]], v[tri[t][1]], v[tri[t][2]], c) <= 0) {
        hint = t;
        return false;
      }
    return true;
  };
  {
    // candidates: the volume centroid, the vertex average, the tetrahedron's centroid
    const Vec3 o = v[0];
    long double vol = 0, cx = 0, cy = 0, cz = 0, ax = 0, ay = 0, az = 0;
    for (const Triangle& t : tri) {
      long double p[3][3];
      const long double d = sixVolume(o, v[t[0]], v[t[1]], v[t[2]], p);
      vol += d;
      cx += d * (p[0][0] + p[1][0] + p[2][0]);
      cy += d * (p[0][1] + p[1][1] + p[2][1]);
      cz += d * (p[0][2] + p[1][2] + p[2][2]);
    }
    for (const Vec3& w : v) {
      ax += (static_cast<long double>(w.x) - o.x) / v.size();
      ay += (static_cast<long double>(w.y) - o.y) / v.size();
      az += (static_cast<long double>(w.z) - o.z) / v.size();
    }
    auto at = [&](long double x, long double y, long double z) {
      return Vec3{static_cast<double>(o.x + x), static_cast<double>(o.y + y),
                  static_cast<double>(o.z + z)};
    };
    std::vector<Vec3> candidates;
    if (vol != 0) candidates.push_back(at(cx / (4 * vol), cy / (4 * vol), cz / (4 * vol)));
    candidates.push_back(at(ax, ay, az));
    long double tx = 0, ty = 0, tz = 0;
    for (std::uint32_t k : tetra) {
      tx += (static_cast<long double>(v[k].x) - o.x) / 4;
      ty += (static_cast<long double>(v[k].y) - o.y) / 4;
      tz += (static_cast<long double>(v[k].z) - o.z) / 4;
    }
    candidates.push_back(at(tx, ty, tz));
    // the doubles around the first candidate, for polyhedra a few ulps thick
    const Vec3 first = candidates.front();
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz)
          if (dx || dy || dz)
            candidates.push_back({nudge(first.x, dx), nudge(first.y, dy), nudge(first.z, dz)});
    std::uint32_t hint = 0;
    for (Vec3 c : candidates)
      if (insideAll(c, hint)) {
        centre_ = c;
        break;
      }
  }
  std::vector<Vec3> rel(v.size());  // each vertex as seen from the centre
  mpq_class g[3];                   // the exact centre when there is no double one
  if (centre_) {
    const Vec3 c = *centre_;
    for (std::size_t i = 0; i < v.size(); ++i) rel[i] = {v[i].x - c.x, v[i].y - c.y, v[i].z - c.z};
  } else {
    // no double point works: decide with the exact centroid g of the tetrahedron found above,
    // strictly inside the solid if it is convex. A face with g on its outer side or in its
    // plane has one of the four vertices strictly outside: the surface is not convex.
    for (std::uint32_t k : tetra) {
      g[0] += mpq_class(v[k].x) / 4;
      g[1] += mpq_class(v[k].y) / 4;
      g[2] += mpq_class(v[k].z) / 4;
    }
    for (std::uint32_t t = 0; t < nt; ++t) {
      const Vec3 p = v[tri[t][0]], q = v[tri[t][1]], r = v[tri[t][2]];
      if (rationalOrient(p, q, r, g) > 0) continue;
      std::uint32_t out = tetra[0];
      for (std::uint32_t k : tetra)
        if (orient3d(p, q, r, v[k]) < 0) out = k;
      throw GeometryError("not convex: " + vname(out) + " lies outside the plane of " + fname(t),
                          tline(t));
    }
    for (std::size_t i = 0; i < v.size(); ++i) {
      const mpq_class x = mpq_class(v[i].x) - g[0], y = mpq_class(v[i].y) - g[1],
                      z = mpq_class(v[i].z) - g[2];
      rel[i] = {x.get_d(), y.get_d(), z.get_d()};
    }
  }
  {
    // scale by powers of two so that no product below overflows or underflows; a difference
    // that overflowed is taken at half scale
    bool overflow = false;
    for (const Vec3& r : rel)
      overflow |= !std::isfinite(r.x) || !std::isfinite(r.y) || !std::isfinite(r.z);
    if (overflow) {
      for (std::size_t i = 0; i < v.size(); ++i) {
        if (centre_) {
          const Vec3 c = *centre_;
          rel[i] = {v[i].x * 0.5 - c.x * 0.5, v[i].y * 0.5 - c.y * 0.5, v[i].z * 0.5 - c.z * 0.5};
        } else {
          const mpq_class x = (mpq_class(v[i].x) - g[0]) / 2, y = (mpq_class(v[i].y) - g[1]) / 2,
                          z = (mpq_class(v[i].z) - g[2]) / 2;
          rel[i] = {x.get_d(), y.get_d(), z.get_d()};
        }
      }
    }
    // Each axis gets its own power of two: a positive scaling of the axes does not change
    // the winding number, and it makes a needle or slab far thinner along one axis than
    // along another well shaped (at one common scale, a box 1e308 by 1e160 by 1e169 loses
    // its thin directions in rounding, and triangles that see 0 turn get half a turn each).
    Vec3 extent{};
    for (const Vec3& r : rel)
      extent = {std::max(extent.x, std::fabs(r.x)), std::max(extent.y, std::fabs(r.y)),
                std::max(extent.z, std::fabs(r.z))};
    auto shiftFor = [](double e) {
      return e > 0 ? -std::ilogb(e) : 0;
    };  // 2^shift may not be a double
    const int sx = shiftFor(extent.x), sy = shiftFor(extent.y), sz = shiftFor(extent.z);
    for (Vec3& r : rel) r = {std::ldexp(r.x, sx), std::ldexp(r.y, sy), std::ldexp(r.z, sz)};
  }
  {
    // every face has the centre strictly inside (the double centre, or g above), so each
    // solid angle is positive and the sum is 4 pi times the degree, up to rounding far below
    // the gap between 4 pi and 8 pi
    double total = 0;
    for (const Triangle& t : tri) total += solidAngle(rel[t[0]], rel[t[1]], rel[t[2]]);
    const double turns = total / (4 * std::numbers::pi);
    if (!(turns < 1.5))
      throw GeometryError("not convex: the surface winds " + std::to_string(std::lround(turns)) +
                          " times around its inside" +
                          (centre_ ? " point " + show(*centre_) : std::string()));
  }

  bounds_ = {v[0], v[0]};
  for (const Vec3& w : v) {
    bounds_.lo = {std::min(bounds_.lo.x, w.x), std::min(bounds_.lo.y, w.y),
                  std::min(bounds_.lo.z, w.z)};
    bounds_.hi = {std::max(bounds_.hi.x, w.x), std::max(bounds_.hi.y, w.y),
                  std::max(bounds_.hi.z, w.z)};
  }
}

int ConvexPolyhedron::side(std::size_t t, Vec3 p) const noexcept {
  const Triangle& f = triangles_[t];
  return orient3d(vertices_[f[0]], vertices_[f[1]], vertices_[f[2]], p);
}

double ConvexPolyhedron::volume() const noexcept {
  const Vec3 o = vertices_[0];
  long double six = 0;
  for (const Triangle& t : triangles_) {
    long double p[3][3];
    six += sixVolume(o, vertices_[t[0]], vertices_[t[1]], vertices_[t[2]], p);
  }
  return static_cast<double>(six / 6);
}

double ConvexPolyhedron::area() const noexcept {
  long double twice = 0;
  for (const Triangle& t : triangles_) {
    const Vec3 a = vertices_[t[0]], b = vertices_[t[1]], c = vertices_[t[2]];
    long double ux = static_cast<long double>(b.x) - a.x, uy = static_cast<long double>(b.y) - a.y,
                uz = static_cast<long double>(b.z) - a.z;
    long double wx = static_cast<long double>(c.x) - a.x, wy = static_cast<long double>(c.y) - a.y,
                wz = static_cast<long double>(c.z) - a.z;
    long double nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
    twice += std::sqrt(nx * nx + ny * ny + nz * nz);
  }
  return static_cast<double>(twice / 2);
}

}  // namespace convexloc
