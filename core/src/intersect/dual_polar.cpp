// convexloc — the dual method: the polar locator of the dual polygon proposes the vertices
// where a line's side function is largest and smallest, an exact climb confirms them.
//
// Duality. Let c be strictly inside P = {x : a_i . (x - c) <= 1} (one a_i per edge) and
// P* = conv{a_i} its polar dual, with the origin strictly inside. Edge i of P is vertex a_i
// of P*, and vertex v_j of P (between edges j - 1 and j) is the edge of P* from a_(j-1) to
// a_j. The vertex of P farthest along a direction w is v_j exactly when w lies in the cone
// of a_(j-1) and a_j, that is when the ray from the origin along w leaves P* through the edge
// dual to v_j: the question "which vertex is extreme along w" is point location's "through
// which edge does the ray from the centre leave", asked of P*'s polar subdivision.
//
// The dual polygon built. Only the directions of the a_i matter to that question, so each is
// the unit outward normal of its edge. The normals' antipodes are added: the vertex extreme
// along -w is then read from the same cell, and the shape is centrally symmetric, so its
// centre of area is the origin and the polar locator's centre lies within rounding of it.
// Q is the strictly convex hull of these 2N points (exact predicates; a normal that rounding
// leaves on or inside the hull is dropped). Each edge of Q is labelled with the vertex of P
// largest along its middle direction and the one largest along the opposite direction
// (floating point: a label is a proposal, never a decision).
//
// The query. For f(x) = w . (x - p1) with w = (p2 - p1) turned a quarter counter-clockwise,
// the cell is the one of the point c* + w / |w|_max, c* the locator's centre, and proposes the
// labels of the middle edge it lists. Conservative cell: by the polar locator's contract the
// cell lists every edge of Q through which the ray from c* towards that point leaves Q. That
// ray differs from the origin's ray along w by |c*| and the rounding of the point, so it
// leaves through the edge E the origin's ray leaves through, or, when w points within that
// distance of a vertex of Q, through E's neighbour. E's label is the extreme vertex along w
// except where w lies within rounding of a normal (the label is then its neighbour) or in
// the arc of a dropped normal. The cell's edges are a consecutive run, so the proposal is at
// most half the run's labels away from E's.
//
// Exactness and cost. The proposals only say where the climb (ring2d.hpp) starts; it compares
// vertices exactly and stops only at a largest vertex, and the answer comes from the exact
// signs at the two vertices it reaches, whatever the proposals were. It is O(1) when each
// proposal is within kClimbMoves of the extreme: so whenever the cell lists at most about
// 2 kClimbMoves edges, which holds for polygons whose turning angles lie within a modest
// factor of 2 pi / N (regular, random, elliptic). A cell that lists many more (a polygon
// whose turning angles span many orders of magnitude) may need a longer climb: after
// kClimbMoves moves, bisection finishes in O(log N).
#include "intersect/dual_polar.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <span>
#include <vector>

#include "convexloc/generate2d.hpp"
#include "convexloc/polygon.hpp"
#include "convexloc/table.hpp"
#include "intersect/ring2d.hpp"

namespace convexloc::detail {

namespace {

// b - a, halved first where the difference would overflow (a direction only)
Vec2 direction(Vec2 a, Vec2 b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  if (std::fabs(dx) + std::fabs(dy) <= std::numeric_limits<double>::max()) return {dx, dy};
  return {b.x * 0.5 - a.x * 0.5, b.y * 0.5 - a.y * 0.5};
}

// the unit outward normal of every edge of the ring, and its antipode
std::vector<Vec2> normalsAndAntipodes(std::span<const Vec2> ring) {
  std::vector<Vec2> out;
  out.reserve(2 * ring.size());
  for (std::uint32_t i = 0; i < ring.size(); ++i) {
    const Vec2 e = direction(ring[i], ring[nextOf(i, ring.size())]);
    const double m = std::max(std::fabs(e.x), std::fabs(e.y));
    const double x = e.y / m, y = -e.x / m, length = std::sqrt(x * x + y * y);
    out.push_back({x / length, y / length});
    out.push_back({-x / length, -y / length});
  }
  return out;
}

// the ring scaled by a power of two to magnitudes near 1, for floating-point dot products
std::vector<Vec2> scaledRing(std::span<const Vec2> ring) {
  double big = 0.0;
  for (const Vec2 v : ring) big = std::max({big, std::fabs(v.x), std::fabs(v.y)});
  const int shift = big > 0 ? -std::ilogb(big) : 0;
  std::vector<Vec2> out;
  out.reserve(ring.size());
  for (const Vec2 v : ring) out.push_back({std::ldexp(v.x, shift), std::ldexp(v.y, shift)});
  return out;
}

// from vertex `at`, forward while the next vertex lies farther along w (floating point)
std::uint32_t advanceAlong(const std::vector<Vec2>& ring, Vec2 w, std::uint32_t at) {
  for (std::size_t k = 0; k < ring.size(); ++k) {
    const std::uint32_t next = nextOf(at, ring.size());
    const double rise = w.x * (ring[next].x - ring[at].x) + w.y * (ring[next].y - ring[at].y);
    if (!(rise > 0)) break;
    at = next;
  }
  return at;
}

// the vertex farthest along w, by a scan (floating point)
std::uint32_t farthestAlong(const std::vector<Vec2>& ring, Vec2 w) {
  std::uint32_t best = 0;
  double bestDot = -std::numeric_limits<double>::infinity();
  for (std::uint32_t i = 0; i < ring.size(); ++i) {
    const double d = w.x * ring[i].x + w.y * ring[i].y;
    if (d > bestDot) best = i, bestDot = d;
  }
  return best;
}

// For each edge of the dual polygon, counter-clockwise, the vertices of the ring farthest
// along its middle direction and along the opposite one. Both turn counter-clockwise with
// the edges, so two pointers go once around the ring: O(N + edges).
std::vector<ExtremePair> labelEdges(std::span<const Vec2> dual, std::span<const Vec2> ring) {
  const std::vector<Vec2> scaled = scaledRing(ring);
  std::vector<ExtremePair> labels(dual.size());
  for (std::uint32_t k = 0; k < dual.size(); ++k) {
    const Vec2 a = dual[k], b = dual[nextOf(k, dual.size())];
    const Vec2 w{a.x + b.x, a.y + b.y}, opposite{-w.x, -w.y};
    ExtremePair& l = labels[k];
    if (k == 0) {
      l = {farthestAlong(scaled, w), farthestAlong(scaled, opposite)};
    } else {
      l = {advanceAlong(scaled, w, labels[k - 1].largest),
           advanceAlong(scaled, opposite, labels[k - 1].smallest)};
    }
  }
  return labels;
}

}  // namespace

DualPolar2D::DualPolar2D(std::span<const Vec2> ring) {
  const std::vector<Vec2> hull = convexHull(normalsAndAntipodes(ring));
  if (hull.size() < 3) return;  // cannot happen for a polygon; propose() then says no
  const ConvexPolygon dual(hull);
  dualVertices_ = dual.size();
  vertices_.assign(dual.vertices().begin(), dual.vertices().end());
  const std::vector<ExtremePair> labels = labelEdges(dual.vertices(), ring);
  polar_.emplace(dual);
  const std::optional<Vec2> centre = polar_->centre();
  if (!centre) {  // no cell to aim from: propose() says no and every query searches
    polar_.reset();
    return;
  }
  centre_ = *centre;
  byCell_.resize(polar_->cellCount());
  for (std::uint32_t c = 0; c < byCell_.size(); ++c) {
    const std::span<const std::uint32_t> edges = polar_->cellEdges(c);
    maxPerCell_ = std::max(maxPerCell_, edges.size());
    if (!edges.empty()) byCell_[c] = labels[edges[edges.size() / 2]];
  }
}

bool DualPolar2D::propose(Vec2 p1, Vec2 p2, ExtremePair& out, std::int64_t& cell) const noexcept {
  if (!polar_) return false;
  const Vec2 d = direction(p1, p2);
  const double m = std::max(std::fabs(d.x), std::fabs(d.y));
  cell = polar_->cellIndex({centre_.x - d.y / m, centre_.y + d.x / m});
  if (cell < 0) return false;
  out = byCell_[static_cast<std::size_t>(cell)];
  return true;
}

std::size_t DualPolar2D::bytes() const noexcept {
  return (polar_ ? polar_->stats().bytes : 0) + bytesOf(byCell_);
}

}  // namespace convexloc::detail
