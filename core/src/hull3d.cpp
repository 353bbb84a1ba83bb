// convexloc — the exact convex hull of a 3D point cloud: randomized incremental insertion
// with conflict lists, every decision an exact orient3d sign.
//
// Why the result is the exact hull of the given doubles.
//   A triangle (a, b, c) of the hull is counter-clockwise seen from outside, so
//   orient3d(a, b, c, q) > 0 for q strictly inside its plane. A point q SEES a triangle when
//   orient3d(a, b, c, q) < 0, exactly; a point on the plane (sign 0) sees nothing.
//   Invariant, after each step: the triangles form a closed, consistently oriented surface
//   that bounds H = conv(inserted points), its corners are inserted points, and every point
//   not yet inserted either sees the one triangle its conflict list puts it in, or lies in H
//   (inside or on), and then it is dropped for good (H only grows).
//   - Start: four points with orient3d != 0 (hullOf refuses the cloud otherwise): a
//     tetrahedron, each face oriented with its opposite corner inside. A point that sees none
//     of its four faces is inside or on it.
//   - Inserting p, which sees some triangle (p is strictly outside H): the triangles p sees
//     are the part of H's surface in front of p, which the central projection from p maps
//     one to one onto the inside of H's convex shadow: a disc. At each vertex v they are the
//     faces whose normal n has n . (p - v) > 0, a contiguous run around v (v's normals bound
//     a convex cone), so the disc's boundary pinches nowhere: the horizon is one simple
//     cycle of edges, each between a triangle p sees and one it does not. Replacing the seen
//     triangles by (a, b, p) for every horizon edge a -> b gives the boundary of
//     H' = conv(H u {p}). No new triangle is degenerate: were p on the line ab, the seen
//     triangle on that edge would have sign 0, not < 0. A new triangle may be coplanar with
//     the unseen one across its horizon edge (p on that plane), never folded onto it: the
//     unseen triangle's side of the line ab in its plane lies strictly inside the seen
//     triangle's plane.
//   - Conflicts: a point q that saw a removed triangle F and lies outside H' sees one of the
//     new triangles. Take x' in H's interior near a point of F's relative interior: the
//     segment x'q leaves H through F, and leaves H' at a point y outside H, which lies on a
//     new triangle (the unremoved ones lie in H); for a generic x', y is interior to it,
//     and q, beyond y on the segment from an interior point, is strictly outside its plane.
//     So q is tested against the new triangles only; seeing none, it is in H' and dropped.
//   At the end every point was inserted (a corner of H) or dropped while in a subset of the
//   final H: every input point is inside or on the hull, and every corner is an input point.
//   A point on a triangle's plane does not see it: if it is in H it is dropped, not made a
//   corner, so coplanar points end inside or on the boundary. A point inserted while it was
//   outside, and left by later points on an edge or inside a face, keeps its triangles (all
//   nondegenerate, coplanar neighbours allowed) until canonicalSurface (hull_surface.cpp)
//   drops it and writes the surface in its one canonical form. ConvexPolyhedron validates
//   the triangles exactly once more, and buildCone throws std::logic_error should the
//   horizon ever not be one simple cycle (the argument above says it always is).
// Cost: O(n log n) expected for a random insertion order; the order here is a biased
// randomized one over the points sorted along a Morton curve (fixed seed: the same doubles
// give the same triangles), from a large starting tetrahedron; each point sits in one
// conflict list, and a step allocates nothing once the arrays have grown.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/polyhedron.hpp"
#include "convexloc/predicates.hpp"
#include "detail/hull_surface.hpp"
#include "detail/polyhedron_build.hpp"

namespace convexloc {
namespace {

constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();
// the seed of the insertion order: fixed, so that a hull is a function of its points
constexpr std::uint64_t kOrderSeed = 0x68756c6c;

// v's 21 low bits spread to every third bit
std::uint64_t spreadBits(std::uint64_t v) noexcept {
  v &= 0x1fffff;
  v = (v | v << 32) & 0x1f00000000ffff;
  v = (v | v << 16) & 0x1f0000ff0000ff;
  v = (v | v << 8) & 0x100f00f00f00f00f;
  v = (v | v << 4) & 0x10c30c30c30c30c3;
  v = (v | v << 2) & 0x1249249249249249;
  return v;
}

// the input indices sorted by the Morton code of their point on a 2^21 grid over the
// bounding box (floating point, and NaN or overflow only lands a point in a corner cell:
// this orders the work, it decides nothing)
std::vector<std::uint32_t> mortonOrder(std::span<const Vec3> points) {
  Vec3 lo = points[0], hi = points[0];
  for (const Vec3 p : points) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  auto cell = [](double value, double low, double high) -> std::uint64_t {
    const double t = (value - low) / (high - low) * 0x1p21;
    return t > 0 ? static_cast<std::uint64_t>(std::min(t, 0x1p21 - 1)) : 0;
  };
  std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(points.size());
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    const Vec3 p = points[i];
    keyed[i] = {spreadBits(cell(p.x, lo.x, hi.x)) | spreadBits(cell(p.y, lo.y, hi.y)) << 1 |
                    spreadBits(cell(p.z, lo.z, hi.z)) << 2,
                i};
  }
  std::sort(keyed.begin(), keyed.end());
  std::vector<std::uint32_t> order(points.size());
  for (std::size_t i = 0; i < keyed.size(); ++i) order[i] = keyed[i].second;
  return order;
}

// A biased randomized insertion order (Amenta, Choi and Rote) over n points stored in Morton
// order: each point falls in the last round with probability 1/2, the one before with 1/4,
// and so on (the first round takes the rest, about 1024 points); rounds run in turn, the
// first in random order, each later one in Morton order. Random enough for the expected
// O(n log n), local enough for the caches.
std::vector<std::uint32_t> insertionRounds(std::size_t n) {
  int rounds = 0;
  while ((std::size_t{1024} << rounds) < n) ++rounds;
  Rng rng(kOrderSeed);
  std::vector<std::uint8_t> roundOf(n);
  std::vector<std::size_t> start(rounds + 2, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const int late = std::min(std::countr_zero(rng.next()), rounds);
    roundOf[i] = static_cast<std::uint8_t>(rounds - late);
    ++start[roundOf[i] + 1];
  }
  for (int r = 0; r <= rounds; ++r) start[r + 1] += start[r];
  std::vector<std::uint32_t> order(n);
  for (std::uint32_t i = 0; i < n; ++i) order[start[roundOf[i]]++] = i;
  // the first round in random order: a sweep along the curve would keep distant points in
  // the conflict lists of the first triangles, and test them again at every step
  for (std::size_t i = start[0]; i > 1; --i) std::swap(order[i - 1], order[rng.below(i)]);
  return order;
}

// one triangle of the growing hull, counter-clockwise seen from outside
struct Face {
  std::array<std::uint32_t, 3> v;   // corners, indices into the points
  std::array<std::uint32_t, 3> nb;  // nb[k]: the triangle across the edge v[k] -> v[k + 1]
  std::uint32_t conflicts;          // the first point that sees this triangle, or kNone
  std::uint32_t mark;               // 2 * step (+ 1 when p sees it) of the last look; kNone: free
};

// The incremental hull of a cloud from four points not in one plane; see the file's head.
class IncrementalHull {
 public:
  IncrementalHull(std::span<const Vec3> points, const std::array<std::uint32_t, 4>& simplex);
  // the hull's triangles, counter-clockwise seen from outside, over input indices, and the
  // neighbours of each (nb[t][k] across the edge from corner k to corner k + 1)
  void surface(std::vector<std::array<std::uint32_t, 3>>& triangles,
               std::vector<std::array<std::uint32_t, 3>>& neighbours) const;

 private:
  void start(const std::array<std::uint32_t, 4>& simplex);
  void insert(std::uint32_t p);
  void findVisible(std::uint32_t p);
  void buildCone(std::uint32_t p);
  void reassign(std::uint32_t p);
  std::uint32_t newFace(std::uint32_t a, std::uint32_t b, std::uint32_t c);

  // whether q sees triangle f: q strictly on the outer side of its plane, exactly
  bool sees(std::uint32_t q, std::uint32_t f) const noexcept {
    const auto& v = faces_[f].v;
    return orient3d(pts_[v[0]], pts_[v[1]], pts_[v[2]], pts_[q]) < 0;
  }
  // puts q in the conflict list of triangle f
  void attach(std::uint32_t q, std::uint32_t f) noexcept {
    owner_[q] = f;
    next_[q] = faces_[f].conflicts;
    faces_[f].conflicts = q;
  }

  std::vector<std::uint32_t> ids_;  // per point: its index in the input
  std::vector<Vec3> pts_;           // the input points in Morton order
  std::vector<Face> faces_;
  std::vector<std::uint32_t> free_;     // removed triangles, for reuse
  std::vector<std::uint32_t> owner_;    // per point: the triangle it sees, or kNone
  std::vector<std::uint32_t> next_;     // per point: the next point of its conflict list
  std::vector<std::uint32_t> startOf_;  // per point: the new triangle whose horizon edge starts
                                        // there (during one step), else kNone
  std::vector<std::uint32_t> visible_;  // the triangles p sees
  std::vector<std::pair<std::uint32_t, std::uint32_t>> horizon_;  // (seen triangle, edge)
  std::vector<std::uint32_t> fresh_;                              // the triangles made for p
  std::uint32_t step_ = 1;
};

IncrementalHull::IncrementalHull(std::span<const Vec3> points,
                                 const std::array<std::uint32_t, 4>& simplex)
    : ids_(mortonOrder(points)),
      owner_(points.size(), kNone),
      next_(points.size(), kNone),
      startOf_(points.size(), kNone) {
  // the points in Morton order, so that points near in space are near in memory
  pts_.reserve(points.size());
  std::vector<std::uint32_t> local(points.size());
  for (std::uint32_t i = 0; i < ids_.size(); ++i) {
    pts_.push_back(points[ids_[i]]);
    local[ids_[i]] = i;
  }
  start({local[simplex[0]], local[simplex[1]], local[simplex[2]], local[simplex[3]]});
  for (const std::uint32_t p : insertionRounds(points.size()))
    if (owner_[p] != kNone) insert(p);
}

std::uint32_t IncrementalHull::newFace(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  const Face face{{a, b, c}, {kNone, kNone, kNone}, kNone, 0};
  if (free_.empty()) {
    faces_.push_back(face);
    return static_cast<std::uint32_t>(faces_.size() - 1);
  }
  const std::uint32_t f = free_.back();
  free_.pop_back();
  faces_[f] = face;
  return f;
}

// the tetrahedron on the simplex, each face with its opposite corner inside, and every
// other point in the conflict list of one face it sees
void IncrementalHull::start(const std::array<std::uint32_t, 4>& s) {
  const std::array<std::array<std::uint32_t, 4>, 4> sides = {{{s[0], s[1], s[2], s[3]},
                                                              {s[0], s[1], s[3], s[2]},
                                                              {s[0], s[2], s[3], s[1]},
                                                              {s[1], s[2], s[3], s[0]}}};
  for (auto t : sides) {
    if (orient3d(pts_[t[0]], pts_[t[1]], pts_[t[2]], pts_[t[3]]) < 0) std::swap(t[1], t[2]);
    newFace(t[0], t[1], t[2]);
  }
  for (std::uint32_t f = 0; f < 4; ++f)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = faces_[f].v[k], b = faces_[f].v[(k + 1) % 3];
      for (std::uint32_t g = 0; g < 4; ++g)
        for (int j = 0; j < 3; ++j)
          if (faces_[g].v[j] == b && faces_[g].v[(j + 1) % 3] == a) faces_[f].nb[k] = g;
    }
  for (std::uint32_t q = 0; q < pts_.size(); ++q) {
    if (std::find(s.begin(), s.end(), q) != s.end()) continue;
    for (std::uint32_t f = 0; f < 4; ++f)
      if (sees(q, f)) {
        attach(q, f);
        break;
      }
  }
}

void IncrementalHull::insert(std::uint32_t p) {
  findVisible(p);
  buildCone(p);
  reassign(p);
  ++step_;
}

// every triangle p sees (a connected set, from the one p's conflict list names), and the
// horizon: each edge between a seen triangle and an unseen one
void IncrementalHull::findVisible(std::uint32_t p) {
  const std::uint32_t looked = 2 * step_, seen = looked + 1;
  visible_.clear();
  horizon_.clear();
  visible_.push_back(owner_[p]);
  faces_[owner_[p]].mark = seen;
  for (std::size_t i = 0; i < visible_.size(); ++i) {
    const std::uint32_t f = visible_[i];
    for (std::uint32_t k = 0; k < 3; ++k) {
      const std::uint32_t g = faces_[f].nb[k];
      if (faces_[g].mark != seen && faces_[g].mark != looked) {
        faces_[g].mark = sees(p, g) ? seen : looked;
        if (faces_[g].mark == seen) visible_.push_back(g);
      }
      if (faces_[g].mark == looked) horizon_.emplace_back(f, k);
    }
  }
}

// a triangle (a, b, p) on every horizon edge a -> b, linked to the unseen triangle across
// a -> b and to its two new neighbours (the horizon is one simple cycle)
void IncrementalHull::buildCone(std::uint32_t p) {
  fresh_.clear();
  for (const auto& [f, k] : horizon_) {
    const std::uint32_t a = faces_[f].v[k], b = faces_[f].v[(k + 1) % 3];
    const std::uint32_t g = faces_[f].nb[k];
    const std::uint32_t n = newFace(a, b, p);
    faces_[n].nb[0] = g;
    for (auto& across : faces_[g].nb)
      if (across == f) across = n;
    if (startOf_[a] != kNone) throw std::logic_error("hull: the horizon is not a simple cycle");
    startOf_[a] = n;
    fresh_.push_back(n);
  }
  for (const std::uint32_t n : fresh_) {
    const std::uint32_t m = startOf_[faces_[n].v[1]];
    if (m == kNone) throw std::logic_error("hull: the horizon is not a closed cycle");
    faces_[n].nb[1] = m;
    faces_[m].nb[2] = n;
  }
  for (const std::uint32_t n : fresh_) startOf_[faces_[n].v[0]] = kNone;
}

// every point that saw a removed triangle moves to a new triangle it sees, or is dropped (it
// lies in the new hull); the removed triangles are freed
void IncrementalHull::reassign(std::uint32_t p) {
  for (const std::uint32_t f : visible_) {
    for (std::uint32_t q = faces_[f].conflicts, after = kNone; q != kNone; q = after) {
      after = next_[q];
      owner_[q] = kNone;
      if (q == p) continue;
      for (const std::uint32_t n : fresh_)
        if (sees(q, n)) {
          attach(q, n);
          break;
        }
    }
    faces_[f].mark = kNone;
    free_.push_back(f);
  }
}

void IncrementalHull::surface(std::vector<std::array<std::uint32_t, 3>>& triangles,
                              std::vector<std::array<std::uint32_t, 3>>& neighbours) const {
  std::vector<std::uint32_t> live(faces_.size(), kNone);
  std::uint32_t count = 0;
  for (std::uint32_t f = 0; f < faces_.size(); ++f)
    if (faces_[f].mark != kNone) live[f] = count++;
  triangles.clear();
  neighbours.clear();
  triangles.reserve(count);
  neighbours.reserve(count);
  for (const Face& f : faces_)
    if (f.mark != kNone) {
      triangles.push_back({ids_[f.v[0]], ids_[f.v[1]], ids_[f.v[2]]});
      neighbours.push_back({live[f.nb[0]], live[f.nb[1]], live[f.nb[2]]});
    }
}

// Four points not in one plane: the first point, the first one unequal to it, the first one
// off their line, the first one off their plane. Throws GeometryError saying what the cloud is
// when there are none.
std::array<std::uint32_t, 4> firstSimplex(std::span<const Vec3> points) {
  const std::size_t n = points.size();
  if (n < 4)
    throw GeometryError("a hull needs at least 4 points not in one plane, got " +
                        (n == 0 ? std::string("none") : std::to_string(n)));
  const std::string zero = "the hull has zero volume: the " + std::to_string(n) + " points ";
  std::uint32_t b = 1, c = 0, d = 0;
  while (b < n && points[b] == points[0]) ++b;
  if (b == n) throw GeometryError(zero + "are all equal to " + detail::show(points[0]));
  for (c = b + 1; c < n && detail::collinear(points[0], points[b], points[c]); ++c) {
  }
  if (c == n)
    throw GeometryError(zero + "are collinear, on the line through point 0 " +
                        detail::show(points[0]) + " and point " + std::to_string(b) + " " +
                        detail::show(points[b]));
  for (d = c + 1; d < n && orient3d(points[0], points[b], points[c], points[d]) == 0; ++d) {
  }
  if (d == n)
    throw GeometryError(zero + "are coplanar, on the plane through points 0, " + std::to_string(b) +
                        " and " + std::to_string(c));
  return {0, b, c, d};
}

// the index of the point where score is largest (the first of equals; NaN never wins)
template <class Score>
std::uint32_t argmax(std::span<const Vec3> points, Score score) {
  std::uint32_t best = 0;
  double top = -1.0;
  for (std::uint32_t i = 0; i < points.size(); ++i)
    if (const double s = score(points[i]); s > top) best = i, top = s;
  return best;
}

// A large starting tetrahedron, so that most inner points are dropped at once: the points of
// least and greatest x, the one farthest from their line, the one farthest from their plane
// (chosen in floating point, checked exactly); `fallback` where the check fails.
std::array<std::uint32_t, 4> spreadSimplex(std::span<const Vec3> points,
                                           const std::array<std::uint32_t, 4>& fallback) {
  const std::uint32_t a = argmax(points, [](Vec3 p) { return -p.x; });
  const std::uint32_t b = argmax(points, [](Vec3 p) { return p.x; });
  const Vec3 pa = points[a], u{points[b].x - pa.x, points[b].y - pa.y, points[b].z - pa.z};
  auto cross = [&u, pa](Vec3 p) {
    const Vec3 w{p.x - pa.x, p.y - pa.y, p.z - pa.z};
    return Vec3{u.y * w.z - u.z * w.y, u.z * w.x - u.x * w.z, u.x * w.y - u.y * w.x};
  };
  const std::uint32_t c = argmax(points, [&](Vec3 p) {
    const Vec3 n = cross(p);
    return n.x * n.x + n.y * n.y + n.z * n.z;
  });
  const Vec3 n = cross(points[c]);
  const std::uint32_t d = argmax(points, [&](Vec3 p) {
    return std::fabs(n.x * (p.x - pa.x) + n.y * (p.y - pa.y) + n.z * (p.z - pa.z));
  });
  if (points[a] == points[b] || detail::collinear(points[a], points[b], points[c]) ||
      orient3d(points[a], points[b], points[c], points[d]) == 0)
    return fallback;
  return {a, b, c, d};
}

// each corner's first index in `points` (corners: sorted by coordinates, -0 as +0)
std::vector<std::uint32_t> firstIndices(std::span<const Vec3> points,
                                        std::span<const Vec3> corners) {
  auto less = [](Vec3 a, Vec3 b) {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
  };
  std::vector<std::uint32_t> first(corners.size(), kNone);
  for (std::uint32_t i = 0; i < points.size(); ++i) {
    const auto at = std::lower_bound(corners.begin(), corners.end(), points[i], less);
    if (at == corners.end() || !(*at == points[i])) continue;
    std::uint32_t& slot = first[static_cast<std::size_t>(at - corners.begin())];
    if (slot == kNone) slot = i;
  }
  return first;
}

}  // namespace

ConvexPolyhedron ConvexPolyhedron::hullOf(std::span<const Vec3> points) {
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Vec3 p = points[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      throw GeometryError("point " + std::to_string(i) +
                          " has a coordinate that is not a finite number");
  }
  if (points.size() > kMaxPolyhedronVertices)
    throw UsageError("too many points for a hull: " + std::to_string(points.size()));
  const std::array<std::uint32_t, 4> simplex = spreadSimplex(points, firstSimplex(points));
  std::vector<std::array<std::uint32_t, 3>> triangles, neighbours;
  IncrementalHull(points, simplex).surface(triangles, neighbours);
  const detail::CanonicalSurface surface = detail::canonicalSurface(points, triangles, neighbours);
  // the extreme points in lexicographic order (-0 written as +0, so that equal hulls have
  // equal bytes), the fans of the plane faces in canonical order
  MeshData mesh;
  mesh.vertices.reserve(surface.corners.size());
  for (const std::uint32_t i : surface.corners) {
    const Vec3 p = points[i];
    mesh.vertices.push_back({p.x + 0.0, p.y + 0.0, p.z + 0.0});
  }
  for (const auto& t : surface.triangles) mesh.addFace(t);
  // every triangle's plane has every point on its inner side or on it (exact orient3d), so
  // the surface is the boundary of the convex hull and winds once around its inside: the
  // validation's floating-point winding count is left out, every exact check still runs
  ConvexPolyhedron hull(mesh, nullptr, true);
  hull.sourceVertex_ = firstIndices(points, hull.vertices());
  return hull;
}

}  // namespace convexloc
