// convexloc — the local checks of a polyhedron: the mesh's arrays, faces and edges, its
// topology, its volume, zero-area triangles and convexity across every edge.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numeric>
#include <string>

#include "convexloc/error.hpp"
#include "convexloc/predicates.hpp"
#include "detail/polyhedron_build.hpp"

namespace convexloc::detail {
namespace {

constexpr std::uint32_t kNone = 0xffffffffu;

// what ends every refusal that reading the vertices' convex hull would cure
constexpr const char* kHullCures =
    "; --hull reads the convex hull of the vertices instead (hull=True in Python)";

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

// the merged vertices of an input face, consecutive repeats dropped
void mergedFace(std::span<const std::uint32_t> face, const std::vector<std::uint32_t>& id,
                std::vector<std::uint32_t>& poly) {
  poly.clear();
  for (std::uint32_t k : face)
    if (poly.empty() || poly.back() != id[k]) poly.push_back(id[k]);
  while (poly.size() > 1 && poly.back() == poly.front()) poly.pop_back();
}

// union-find root with path halving
std::uint32_t findRoot(std::vector<std::uint32_t>& parent, std::uint32_t x) {
  while (parent[x] != x) {
    parent[x] = parent[parent[x]];
    x = parent[x];
  }
  return x;
}

// the slot of t's edge running from p to q (-1 when t has none)
int edgeSlot(const ConvexPolyhedron::Triangle& t, std::uint32_t p, std::uint32_t q) {
  for (int k = 0; k < 3; ++k)
    if (t[k] == p && t[(k + 1) % 3] == q) return k;
  return -1;
}

}  // namespace

PolyhedronBuilder::PolyhedronBuilder(ConvexPolyhedron& out, const MeshData& mesh,
                                     std::vector<std::uint32_t>* suspects)
    : out_(out), mesh_(mesh), suspects_(suspects) {}

// === names of witnesses

std::string PolyhedronBuilder::vertexName(std::uint32_t k) const {
  return "vertex " + std::to_string(out_.sourceVertex_[k]) + ' ' + show(out_.vertices_[k]);
}

std::string PolyhedronBuilder::edgeName(std::uint32_t a, std::uint32_t b) const {
  return "edge " + std::to_string(out_.sourceVertex_[a]) + '-' +
         std::to_string(out_.sourceVertex_[b]) + " from " + show(out_.vertices_[a]) + " to " +
         show(out_.vertices_[b]);
}

std::string PolyhedronBuilder::faceName(std::uint32_t t) const {
  return "face " + std::to_string(out_.sourceFace_[t]);
}

std::size_t PolyhedronBuilder::vertexLine(std::size_t i) const {
  return mesh_.vertexLines.empty() ? 0 : mesh_.vertexLines[i];
}

std::size_t PolyhedronBuilder::faceLine(std::size_t f) const {
  return mesh_.faceLines.empty() ? 0 : mesh_.faceLines[f];
}

std::size_t PolyhedronBuilder::triangleLine(std::uint32_t t) const {
  return faceLine(out_.sourceFace_[t]);
}

void PolyhedronBuilder::blame(const std::vector<std::uint32_t>& corners) const {
  if (suspects_)
    for (std::uint32_t w : corners) suspects_->push_back(out_.sourceVertex_[w]);
}

// === the mesh as given

void PolyhedronBuilder::checkArrays() const {
  const std::size_t n = mesh_.vertices.size();
  if (mesh_.faceStart.empty() || mesh_.faceStart.front() != 0 ||
      mesh_.faceStart.back() != mesh_.indices.size() ||
      !std::is_sorted(mesh_.faceStart.begin(), mesh_.faceStart.end()))
    throw UsageError("MeshData: faceStart must run from 0 to the number of indices");
  if (!mesh_.vertexLines.empty() && mesh_.vertexLines.size() != n)
    throw UsageError("MeshData: vertexLines must be empty or match the vertices");
  if (!mesh_.faceLines.empty() && mesh_.faceLines.size() != mesh_.faceCount())
    throw UsageError("MeshData: faceLines must be empty or match the faces");
  if (n > kMaxPolyhedronVertices)
    throw UsageError("too many vertices: " + std::to_string(n) + " (the limit is " +
                     std::to_string(kMaxPolyhedronVertices) + ")");
}

void PolyhedronBuilder::checkFiniteVertices() const {
  const std::vector<Vec3>& pts = mesh_.vertices;
  for (std::size_t i = 0; i < pts.size(); ++i)
    if (!std::isfinite(pts[i].x) || !std::isfinite(pts[i].y) || !std::isfinite(pts[i].z))
      throw GeometryError("vertex " + std::to_string(i) + ' ' + show(pts[i]) +
                              " has a coordinate that is not a finite number",
                          vertexLine(i));
}

void PolyhedronBuilder::checkFaces() {
  const std::size_t n = mesh_.vertices.size(), m = mesh_.faceCount();
  if (m == 0) throw GeometryError("the mesh has no faces", n ? vertexLine(n - 1) : 0);
  out_.inputFaces_ = m;
  used_.assign(n, 0);
  for (std::size_t f = 0; f < m; ++f) {
    auto face = mesh_.face(f);
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
      used_[v] = 1;
    }
    triangleBound_ += face.size() - 2;
  }
  if (triangleBound_ > kMaxPolyhedronFaces)
    throw UsageError("too many faces: " + std::to_string(triangleBound_) +
                     " triangles (the limit is " + std::to_string(kMaxPolyhedronFaces) + ")");
}

void PolyhedronBuilder::mergeVertices() {
  const std::vector<Vec3>& pts = mesh_.vertices;
  const std::size_t n = pts.size();
  id_.assign(n, kNone);
  std::vector<std::uint32_t> order;
  order.reserve(n);
  for (std::uint32_t i = 0; i < n; ++i)
    if (used_[i]) order.push_back(i);
  out_.unused_ = n - order.size();
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
    out_.merged_ += same;
  }
  for (std::uint32_t i = 0; i < n; ++i)
    if (used_[i] && rep[i] == i) {
      id_[i] = static_cast<std::uint32_t>(out_.vertices_.size());
      out_.vertices_.push_back(pts[i]);
      out_.sourceVertex_.push_back(i);
    }
  for (std::uint32_t i = 0; i < n; ++i)
    if (used_[i]) id_[i] = id_[rep[i]];
}

void PolyhedronBuilder::fanTriangulate() {
  out_.triangles_.reserve(triangleBound_);
  out_.sourceFace_.reserve(triangleBound_);
  std::vector<std::uint32_t> poly, sorted;
  for (std::size_t f = 0; f < mesh_.faceCount(); ++f) {
    mergedFace(mesh_.face(f), id_, poly);
    if (poly.size() < 3)
      throw GeometryError(
          "face " + std::to_string(f) + " is degenerate: it has fewer than 3 distinct vertices",
          faceLine(f));
    sorted = poly;
    std::sort(sorted.begin(), sorted.end());
    auto twice = std::adjacent_find(sorted.begin(), sorted.end());
    if (twice != sorted.end())
      throw GeometryError("face " + std::to_string(f) + " visits " + vertexName(*twice) + " twice",
                          faceLine(f));
    for (std::size_t i = 1; i + 1 < poly.size(); ++i) {
      out_.triangles_.push_back({poly[0], poly[i], poly[i + 1]});
      out_.sourceFace_.push_back(static_cast<std::uint32_t>(f));
    }
  }
}

void PolyhedronBuilder::pairEdges() {
  // half-edges are bucketed by their smaller vertex (counting sort), then sorted per bucket
  const std::vector<Triangle>& tri = out_.triangles_;
  const auto nt = static_cast<std::uint32_t>(tri.size());
  const auto nv = static_cast<std::uint32_t>(out_.vertices_.size());
  out_.neighbours_.assign(nt, {kNone, kNone, kNone});
  auto head = [&](std::uint32_t h) { return tri[h / 3][h % 3]; };
  auto tail = [&](std::uint32_t h) { return tri[h / 3][(h % 3 + 1) % 3]; };
  auto other = [&](std::uint32_t h) { return std::max(head(h), tail(h)); };
  std::vector<std::uint32_t> start(nv + 1, 0);
  for (const Triangle& t : tri)
    for (int k = 0; k < 3; ++k) ++start[std::min(t[k], t[(k + 1) % 3]) + 1];
  std::partial_sum(start.begin(), start.end(), start.begin());
  std::vector<std::uint32_t> half(start.back());
  {
    std::vector<std::uint32_t> cursor(start.begin(), start.end() - 1);
    for (std::uint32_t h = 0; h < 3 * nt; ++h) half[cursor[std::min(head(h), tail(h))]++] = h;
  }
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
        throw GeometryError("the surface is open: " + edgeName(head(h1), tail(h1)) +
                                " belongs to " + faceName(t1) + " only" + kHullCures,
                            triangleLine(t1));
      if (count > 2) {
        std::string faces;
        for (auto k = it; k != run && k - it < 4; ++k)
          faces += (k == it ? "" : ", ") + std::to_string(out_.sourceFace_[*k / 3]);
        if (count > 4) faces += ", ...";
        throw GeometryError("not a manifold: " + edgeName(head(h1), tail(h1)) + " is shared by " +
                                std::to_string(count) + " triangles (faces " + faces + ")" +
                                kHullCures,
                            triangleLine(it[2] / 3));
      }
      const std::uint32_t h2 = it[1], t2 = h2 / 3;
      if (head(h1) == head(h2))
        throw GeometryError("inconsistent orientation: " + faceName(t1) + " and " + faceName(t2) +
                                " both run along " + edgeName(head(h1), tail(h1)) +
                                " in the same direction (orient every face the same way)" +
                                kHullCures,
                            triangleLine(t2));
      out_.neighbours_[t1][h1 % 3] = t2;
      out_.neighbours_[t2][h2 % 3] = t1;
      it = run;
    }
  }
}

void PolyhedronBuilder::checkOnePieceSphere() const {
  const auto nt = static_cast<std::uint32_t>(out_.triangles_.size());
  std::vector<std::uint32_t> parent(nt);
  std::iota(parent.begin(), parent.end(), 0u);
  for (std::uint32_t t = 0; t < nt; ++t)
    for (std::uint32_t u : out_.neighbours_[t]) parent[findRoot(parent, t)] = findRoot(parent, u);
  std::size_t pieces = 0;
  std::uint32_t stray = kNone;
  const std::uint32_t root0 = findRoot(parent, 0);
  for (std::uint32_t t = 0; t < nt; ++t) {
    if (findRoot(parent, t) == t) ++pieces;
    if (stray == kNone && findRoot(parent, t) != root0) stray = t;
  }
  if (pieces > 1)
    throw GeometryError("the surface has " + std::to_string(pieces) + " separate pieces (" +
                            faceName(stray) + " is not connected to " + faceName(0) + ")" +
                            kHullCures,
                        triangleLine(stray));
  const long long chi = static_cast<long long>(out_.vertices_.size()) - 3LL * nt / 2 + nt;
  if (chi != 2)
    throw GeometryError(
        "the surface is not a sphere: V - E + F = " + std::to_string(chi) +
        " where a convex polyhedron has 2 (a handle, or faces meeting only at a vertex)" +
        kHullCures);
}

// === the geometry

void PolyhedronBuilder::findTetrahedron() {
  const std::vector<Vec3>& v = out_.vertices_;
  const auto nv = static_cast<std::uint32_t>(v.size());
  tetra_[2] = tetra_[3] = kNone;
  for (std::uint32_t i = 2; i < nv && tetra_[2] == kNone; ++i)
    if (!collinear(v[0], v[1], v[i])) tetra_[2] = i;
  if (tetra_[2] == kNone)
    throw GeometryError("zero volume: all " + std::to_string(nv) + " vertices are collinear");
  for (std::uint32_t i = 2; i < nv && tetra_[3] == kNone; ++i)
    if (orient3d(v[0], v[1], v[tetra_[2]], v[i]) != 0) tetra_[3] = i;
  if (tetra_[3] == kNone)
    throw GeometryError("zero volume: all " + std::to_string(nv) + " vertices are coplanar");
}

// With b strictly between a and c, triangle (a, b, c) and its neighbour (a, c, d) become
// (a, b, d) and (b, c, d): both lie in the neighbour's plane, have its orientation and
// positive area, and cover the same region of the surface. A flat triangle whose neighbour
// is flat too waits for a later round.
void PolyhedronBuilder::flipSlivers() {
  const std::vector<Vec3>& v = out_.vertices_;
  std::vector<Triangle>&tri = out_.triangles_, &nb = out_.neighbours_;
  const auto nt = static_cast<std::uint32_t>(tri.size());
  std::vector<std::uint8_t> flat(nt, 0);
  std::vector<std::uint32_t> pending, later;
  for (std::uint32_t t = 0; t < nt; ++t)
    if (collinear(v[tri[t][0]], v[tri[t][1]], v[tri[t][2]])) flat[t] = 1, pending.push_back(t);
  while (!pending.empty()) {
    later.clear();
    for (std::uint32_t t : pending) {
      int mid = 0;  // the corner strictly between the other two
      while (!between(v[tri[t][(mid + 1) % 3]], v[tri[t][mid]], v[tri[t][(mid + 2) % 3]])) ++mid;
      const std::uint32_t b = tri[t][mid], c = tri[t][(mid + 1) % 3], a = tri[t][(mid + 2) % 3];
      const std::uint32_t u = nb[t][(mid + 1) % 3];  // across c -> a
      const int ku = edgeSlot(tri[u], a, c);
      const std::uint32_t d = tri[u][(ku + 2) % 3];
      if (flat[u] || d == b) {
        later.push_back(t);
        continue;
      }
      const std::uint32_t nab = nb[t][(mid + 2) % 3], nbc = nb[t][mid];
      const std::uint32_t ncd = nb[u][(ku + 1) % 3], nda = nb[u][(ku + 2) % 3];
      tri[t] = {a, b, d}, nb[t] = {nab, u, nda};
      tri[u] = {b, c, d}, nb[u] = {nbc, ncd, t};
      nb[nda][edgeSlot(tri[nda], a, d)] = t;
      nb[nbc][edgeSlot(tri[nbc], c, b)] = u;
      out_.sourceFace_[t] = out_.sourceFace_[u];
      flat[t] = 0;
      ++out_.slivers_;
    }
    if (later.size() == pending.size()) {
      const std::uint32_t t = later.front();
      for (std::uint32_t k : later) blame({tri[k][0], tri[k][1], tri[k][2]});
      throw GeometryError(faceName(t) + " is degenerate: " + vertexName(tri[t][0]) + ", " +
                              vertexName(tri[t][1]) + " and " + vertexName(tri[t][2]) +
                              " are collinear (zero area) and no neighbouring face absorbs them",
                          triangleLine(t));
    }
    pending.swap(later);
  }
}

// The far vertex of each neighbour must lie on the inner side of the triangle's plane, or in
// it without folding back over the triangle. Where some edges are convex and others reflex,
// the minority is the reflex side (the mesh may be inverted as a whole).
void PolyhedronBuilder::checkConvexEdges() {
  const std::vector<Vec3>& v = out_.vertices_;
  std::vector<Triangle>&tri = out_.triangles_, &nb = out_.neighbours_;
  const auto nt = static_cast<std::uint32_t>(tri.size());
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
        if (suspects_) convexEdges.push_back(a);
      } else if (s < 0) {
        if (reflex++ == 0) firstReflex = 3 * t + k;
        if (suspects_) reflexEdges.push_back(a);
      } else if (auto [sp, sq] = planarSides(v[a], v[b], v[p], v[q]); sp * sq >= 0) {
        blame({q});
        throw GeometryError("not convex: " + faceName(t) + " and " + faceName(u) +
                                " lie in one plane and fold onto each other at " + edgeName(a, b) +
                                kHullCures,
                            std::max(triangleLine(t), triangleLine(u)));
      }
    }
  if (convex > 0 && reflex > 0) {
    blame(reflex <= convex ? reflexEdges : convexEdges);
    throwReflex(firstReflex, firstConvex, reflex <= convex);
  }
  if (convex == 0 && reflex == 0) throw GeometryError("zero volume: every face lies in one plane");
  out_.inverted_ = convex == 0;
  if (out_.inverted_)
    for (std::uint32_t t = 0; t < nt; ++t) {
      std::swap(tri[t][1], tri[t][2]);
      nb[t] = {nb[t][2], nb[t][1], nb[t][0]};
    }
}

void PolyhedronBuilder::throwReflex(std::uint32_t firstReflex, std::uint32_t firstConvex,
                                    bool reflexIsMinority) const {
  const std::uint32_t h = reflexIsMinority ? firstReflex : firstConvex;
  const std::uint32_t t = h / 3, k = h % 3, u = out_.neighbours_[t][k];
  const Triangle& tri = out_.triangles_[t];
  const std::uint32_t a = tri[k], b = tri[(k + 1) % 3], p = tri[(k + 2) % 3];
  std::uint32_t q = out_.triangles_[u][0];
  for (std::uint32_t w : out_.triangles_[u])
    if (w != a && w != b) q = w;
  const std::vector<Vec3>& v = out_.vertices_;
  throw GeometryError("not convex: reflex " + edgeName(a, b) + " between " + faceName(t) + " and " +
                          faceName(u) + ": " + describeFold(measureFold(v[a], v[b], v[p], v[q])),
                      std::max(triangleLine(t), triangleLine(u)));
}

void PolyhedronBuilder::checkPlanarFaces() const {
  std::vector<std::uint32_t> poly;
  for (std::size_t f = 0; f < mesh_.faceCount(); ++f)
    if (mesh_.face(f).size() > 3) {
      mergedFace(mesh_.face(f), id_, poly);
      checkPlanar(f, poly);
    }
}

void PolyhedronBuilder::checkPlanar(std::size_t f, const std::vector<std::uint32_t>& poly) const {
  const std::vector<Vec3>& v = out_.vertices_;
  std::size_t i = 1;
  while (i + 1 < poly.size() && collinear(v[poly[0]], v[poly[i]], v[poly[i + 1]])) ++i;
  if (poly.size() < 4 || i + 1 >= poly.size()) return;  // a triangle, or a degenerate face
  const Triangle plane{poly[0], poly[i], poly[i + 1]};
  for (const std::uint32_t w : poly)
    if (orient3d(v[plane[0]], v[plane[1]], v[plane[2]], v[w]) != 0) {
      blame({w});
      throwNotPlanar(f, plane, w);
    }
}

void PolyhedronBuilder::throwNotPlanar(std::size_t f, const Triangle& a, std::uint32_t w) const {
  const std::vector<Vec3>& v = out_.vertices_;
  long double p[3][3];
  const long double six = sixVolume(v[a[0]], v[a[1]], v[a[2]], v[w], p);
  const long double n[3] = {p[0][1] * p[1][2] - p[0][2] * p[1][1],
                            p[0][2] * p[1][0] - p[0][0] * p[1][2],
                            p[0][0] * p[1][1] - p[0][1] * p[1][0]};
  const long double off = std::fabs(six) / std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  long double size = 0;
  for (const auto& row : p)
    size = std::max(size, std::sqrt(row[0] * row[0] + row[1] * row[1] + row[2] * row[2]));
  char figures[96];
  std::snprintf(figures, sizeof figures, "%.3Lg off the plane (%.3Lg of the face's size)", off,
                off / size);
  throw GeometryError("face " + std::to_string(f) + " is not planar: " + vertexName(w) + " lies " +
                          figures + " through vertices " +
                          std::to_string(out_.sourceVertex_[a[0]]) + ", " +
                          std::to_string(out_.sourceVertex_[a[1]]) + " and " +
                          std::to_string(out_.sourceVertex_[a[2]]) + ", " +
                          roundingVerdict(measureFold(v[a[0]], v[a[1]], v[a[2]], v[w])) +
                          "; a mesh whose coordinates were rounded can be read as the convex hull "
                          "of its vertices instead (--hull; in Python, hull=True)",
                      faceLine(f));
}

}  // namespace convexloc::detail
