// convexloc — clipping a segment to a polygon: the line's entry and exit (O(log N) for the
// bisection and dual methods, O(N) for vertices), then a few exact tests and at most two
// exact intersections rounded once.
//
// The segment s1 -> s2 lies on its own line, which runs in the segment's direction d. A
// crossing line enters the polygon at a point E and leaves at X. A point s of the line lies
// before E exactly when it is on the outer side of E's edge line (after E the line is
// inside, on the inner side of every edge line, and it crosses E's edge line there, not
// along it: a line along an edge only touches); after X exactly when it is on the outer side
// of X's edge line. Where E is a vertex, either edge at it serves, and the test is the sign
// of d . (s - E), exact like every other. The part inside runs from the later of s1 and E
// to the earlier of s2 and X; it is empty when s2 lies before E or s1 after X. A touching
// line meets the polygon in a vertex or along an edge, points that are doubles; the part is
// the overlap of the two intervals along d.
#include <cmath>
#include <cstddef>
#include <optional>

#include "convexloc/intersect2d.hpp"
#include "convexloc/predicates.hpp"
#include "detail/exact_number.hpp"
#include "intersect/ring2d.hpp"

namespace convexloc {

namespace {

// the point turned a quarter clockwise: R(b) - R(a) is b - a turned, exactly
Vec2 turned(Vec2 p) {
  return {p.y, -p.x};
}

// the sign of d . (y - x) for d = s2 - s1: > 0 when y lies after x along the segment's line
int order(Vec2 s1, Vec2 s2, Vec2 x, Vec2 y) noexcept {
  return crossDiff2d(turned(s1), turned(s2), x, y);
}

// the sign of d . (s - H) for the boundary point H a hit names: where s lies along the line
// against it (-1 before, 0 at, 1 after); `leaving` tells the exit from the entry
int sideOfHit(std::span<const Vec2> ring, BoundaryHit h, bool leaving, Vec2 s1, Vec2 s2,
              Vec2 s) noexcept {
  if (h.atVertex) return order(s1, s2, ring[h.index], s);
  const int outer = -orient2d(ring[h.index], ring[detail::nextOf(h.index, ring.size())], s);
  return leaving ? outer : -outer;
}

// the inside of a touching line: the overlap of the segment with the touched vertices
std::optional<Segment2D> clipTouching(std::span<const Vec2> ring, const LineHit& hit, Vec2 s1,
                                      Vec2 s2) {
  const Vec2 first = ring[hit.entry.index], last = ring[hit.exit.index];
  const Vec2 from = order(s1, s2, s1, first) > 0 ? first : s1;
  const Vec2 to = order(s1, s2, last, s2) > 0 ? last : s2;
  if (order(s1, s2, from, to) < 0) return std::nullopt;
  return Segment2D{from, to};
}

// the inside of a crossing line, between its entry and exit
std::optional<Segment2D> clipCrossing(std::span<const Vec2> ring, const LineHit& hit, Vec2 s1,
                                      Vec2 s2) {
  if (sideOfHit(ring, hit.entry, false, s1, s2, s2) < 0) return std::nullopt;
  if (sideOfHit(ring, hit.exit, true, s1, s2, s1) > 0) return std::nullopt;
  auto pointOf = [&](BoundaryHit h) {
    if (h.atVertex) return ring[h.index];
    return roundedIntersection(s1, s2, ring[h.index], ring[detail::nextOf(h.index, ring.size())]);
  };
  const Vec2 from = sideOfHit(ring, hit.entry, false, s1, s2, s1) >= 0 ? s1 : pointOf(hit.entry);
  const Vec2 to = sideOfHit(ring, hit.exit, true, s1, s2, s2) <= 0 ? s2 : pointOf(hit.exit);
  return Segment2D{from, to};
}

}  // namespace

Vec2 roundedIntersection(Vec2 p1, Vec2 p2, Vec2 a, Vec2 b) {
  // a + t (b - a) with t = (d x (p1 - a)) / (d x (b - a)), d = p2 - p1, all exact
  using detail::ExactRational, detail::exactRational, detail::Rounding, detail::toDouble;
  const ExactRational ax = exactRational(a.x), ay = exactRational(a.y);
  const ExactRational dx = exactRational(p2.x) - exactRational(p1.x),
                      dy = exactRational(p2.y) - exactRational(p1.y);
  const ExactRational ex = exactRational(b.x) - ax, ey = exactRational(b.y) - ay;
  const ExactRational wx = exactRational(p1.x) - ax, wy = exactRational(p1.y) - ay;
  const ExactRational t = (dx * wy - dy * wx) / (dx * ey - dy * ex);
  return {toDouble(ax + t * ex, Rounding::Nearest), toDouble(ay + t * ey, Rounding::Nearest)};
}

std::optional<Segment2D> LineIntersector::clip(Vec2 s1, Vec2 s2) const {
  const LineHit hit = intersect(s1, s2);
  switch (hit.crossing) {
    case Crossing::Misses: return std::nullopt;
    case Crossing::Touches: return clipTouching(ring_, hit, s1, s2);
    case Crossing::Crosses: return clipCrossing(ring_, hit, s1, s2);
  }
  return std::nullopt;
}

}  // namespace convexloc
