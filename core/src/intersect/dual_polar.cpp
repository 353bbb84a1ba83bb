// convexloc — the dual method: cells of directions, the dual polygon's polar slabs taken
// about the origin, propose the vertices where a line's side function is largest and
// smallest; exact comparisons confirm them.
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
// the unit outward normal of its edge. The normals' antipodes are added: the shape is then
// centrally symmetric, so its centre of area is the origin and the polar locator's centre
// lies within rounding of it, and every direction's cone is at most half a turn.
// Q is the strictly convex hull of these 2N points (exact predicates; a normal that rounding
// leaves on or inside the hull is dropped), and its polar locator, about one cell per vertex
// of Q (slabsFor), is the dual that the trace, `info` and the viewer show.
//
// The direction cells. The proposals come from a table of the same shape indexed by w
// itself, as if from the origin rather than from c* (within rounding of it): a direction's
// octant (the sign bits of w and whether |w_y| > |w_x|) and its slab floor(q min/max) in it,
// q = slabsFor(|Q|) slabs per octant, so 8q cells about as many as Q's vertices. A slab is
// at most 1/q radians wide, against a regular N-gon's cone of 2 pi / N per vertex with
// 8q about 2N: at most one cone's border falls inside a cell, and the vertices farthest along
// its directions are at most two consecutive ones. The build finds, for every cell
// counter-clockwise, the vertex farthest along its first and its last direction (one pointer
// once around the ring, floating point: a proposal, never a decision); the cell proposes the
// first where they are at most two consecutive vertices, else the one farthest along its
// middle direction. Each cell keeps one record of 64 bytes, one cache line: four consecutive
// vertices of P, from the one before its proposal to two after it (RingWindow); its
// proposal's index lies in a table of its own, read only where a window does not confirm.
//
// The query. For f(x) = w . (x - p1) with w = (p2 - p1) turned a quarter counter-clockwise,
// f is largest at the vertex farthest along w and smallest at the one farthest along -w.
// Negating w flips both sign bits and keeps the slab, so the cells of w and -w are a pair,
// stored side by side: a line computes one index from its two points (no table read) and
// reads one aligned 128-byte block.
//
// Exactness and cost. The window confirms its second or third vertex when neither of its
// ring neighbours (both in the window) is strictly larger, with exact comparisons: that is
// the exact test for a largest vertex (ring2d.hpp), so the answer, from the exact signs at
// the two vertices reached, is exact whatever the proposals were. Where the window confirms
// neither, the climb (ring2d.hpp) goes on over the ring from the proposal and stops only at a
// largest vertex. A query is O(1) with two cache lines read when both windows confirm, which
// holds for every line whose cells' directions have at most two farthest vertices: polygons
// whose turning angles lie within a modest factor of 2 pi / N (regular, random, elliptic). A
// cell spanning many more (a polygon whose turning angles span many orders of magnitude) may
// need a longer climb: after kClimbMoves moves, bisection finishes in O(log N).
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
#include "polar/index.hpp"

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

// Slabs per octant for a dual of n vertices: 8 q cells, pi / (4 q) radians wide on average and
// at most 1 / q, against an average cone of 2 pi / n per dual edge. With q = n / 8 a cell is
// one average cone wide on average and 1.3 at most, so its window (two consecutive
// candidates) holds the extreme for nearly every line.
std::uint32_t slabsFor(std::size_t n) {
  return static_cast<std::uint32_t>(std::clamp<std::size_t>(n / 8, 8, std::size_t{1} << 23));
}

// The direction cell of w and of -w (see the file's head): the octant's sign bits and
// whether |y| > |x|, with the slab floor(q min/max); -w flips both sign bits and keeps the
// slab, so its cell is the other of the pair. False when w is zero or not finite.
[[gnu::always_inline]] inline bool directionCells(double wx, double wy, std::uint32_t q,
                                                  std::int64_t& up, std::int64_t& down) noexcept {
  polar::OctantSlab o;
  if (!polar::octantSlab(wx, wy, static_cast<double>(q), q, o)) return false;
  const unsigned sx = o.octant >> 2, sy = o.octant >> 1 & 1u, steep = o.octant & 1u;
  const std::int64_t pair = (((sx ^ sy) << 1 | steep) * std::int64_t{q} + o.slab) * 2;
  up = pair + sx;
  down = pair + (sx ^ 1u);
  return true;
}

// the direction with sign bits sx, sy, |y| > |x| when `steep`, and min/max = t
Vec2 directionWith(unsigned sx, unsigned sy, bool steep, double t) {
  const double ax = steep ? t : 1.0, ay = steep ? 1.0 : t;
  return {sx ? -ax : ax, sy ? -ay : ay};
}

// The proposal of a cell whose directions' farthest vertices run from `first` to `last`
// counter-clockwise: `first` when they are at most two (the window then holds both), else the
// one farthest along the cell's middle direction.
std::uint32_t proposalOf(const std::vector<Vec2>& scaled, std::uint32_t first, std::uint32_t last,
                         Vec2 middle) {
  if ((last + scaled.size() - first) % scaled.size() <= 1) return first;
  return advanceAlong(scaled, middle, first);
}

}  // namespace

DualPolar2D::DualPolar2D(std::span<const Vec2> ring) {
  const std::vector<Vec2> hull = convexHull(normalsAndAntipodes(ring));
  if (hull.size() < 3) return;  // cannot happen for a polygon; cells() then says no
  const ConvexPolygon dual(hull);
  dualVertices_ = dual.size();
  vertices_.assign(dual.vertices().begin(), dual.vertices().end());
  polar_.emplace(dual, slabsFor(dual.size()));
  const std::optional<Vec2> centre = polar_->centre();
  if (!centre) {  // no cell to aim from: polarCells() says no
    polar_.reset();
  } else {
    centre_ = *centre;
    for (std::uint32_t c = 0; c < polar_->cellCount(); ++c)
      maxPerCell_ = std::max(maxPerCell_, polar_->cellEdges(c).size());
  }
  slabs_ = slabsFor(dual.size());
  buildDirectionCells(ring);
}

// Every direction cell, counter-clockwise from +x (octant by octant, slab by slab in the
// order the angle grows), with one pointer going once around the ring: the vertex farthest
// along each cell's first direction, then along its last. O(N + cells).
void DualPolar2D::buildDirectionCells(std::span<const Vec2> ring) {
  const std::vector<Vec2> scaled = scaledRing(ring);
  const std::size_t n = ring.size();
  const std::uint32_t q = slabs_;
  windows_.resize(8 * std::size_t{q});
  starts_.resize(8 * std::size_t{q});
  std::uint32_t at = farthestAlong(scaled, {1.0, 0.0});
  for (std::uint32_t octant = 0; octant < 8; ++octant) {
    unsigned code = 0;
    while (polar::kOctantLayout[code].octant != octant) ++code;
    const bool falling = polar::kOctantLayout[code].falling;
    const unsigned sx = code >> 2, sy = code >> 1 & 1u;
    const bool steep = code & 1u;
    for (std::uint32_t j = 0; j < q; ++j) {
      const std::uint32_t k = falling ? q - 1 - j : j;
      const double low = static_cast<double>(k) / q, high = static_cast<double>(k + 1) / q;
      const std::uint32_t first =
          advanceAlong(scaled, directionWith(sx, sy, steep, falling ? high : low), at);
      at = advanceAlong(scaled, directionWith(sx, sy, steep, falling ? low : high), first);
      const Vec2 middle = directionWith(sx, sy, steep, (low + high) / 2);
      const std::uint32_t s = proposalOf(scaled, first, at, middle);
      std::int64_t up = 0, down = 0;
      directionCells(middle.x, middle.y, q, up, down);
      const std::uint32_t before = prevOf(s, n), after = nextOf(s, n);
      windows_[static_cast<std::size_t>(up)] = {
          {ring[before], ring[s], ring[after], ring[nextOf(after, n)]}};
      starts_[static_cast<std::size_t>(up)] = s;
    }
  }
}

bool DualPolar2D::cells(Vec2 p1, Vec2 p2, std::int64_t& up, std::int64_t& down) const noexcept {
  if (slabs_ == 0) return false;
  const Vec2 d = direction(p1, p2);
  return directionCells(-d.y, d.x, slabs_, up, down);  // w = d turned a quarter
}

bool DualPolar2D::polarCells(Vec2 p1, Vec2 p2, std::int64_t& up,
                             std::int64_t& down) const noexcept {
  if (!polar_) return false;
  const Vec2 d = direction(p1, p2);
  const double m = std::max(std::fabs(d.x), std::fabs(d.y));
  const double wx = -d.y / m, wy = d.x / m;  // w / |w|max, w = d turned a quarter
  up = polar_->cellIndex({centre_.x + wx, centre_.y + wy});
  down = polar_->cellIndex({centre_.x - wx, centre_.y - wy});
  return up >= 0 && down >= 0;
}

std::size_t DualPolar2D::bytes() const noexcept {
  return (polar_ ? polar_->stats().bytes : 0) + bytesOf(windows_) + bytesOf(starts_);
}

}  // namespace convexloc::detail
