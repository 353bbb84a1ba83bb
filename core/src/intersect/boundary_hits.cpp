// convexloc — where a line meets a polygon's boundary, from its two extreme vertices:
// O(log N).
//
// Counter-clockwise from a smallest vertex to a largest one f never falls, and from the
// largest back to the smallest it never rises (ring2d.hpp). On a crossing line the first
// chain goes from strictly below the line to strictly above it, so "strictly below" holds on
// a prefix of it and bisection finds the first vertex on or above: that vertex when it is on
// the line, else the edge into it. That point is the exit: there the boundary, heading
// counter-clockwise, crosses the line from right to left, so the line's direction points out
// of the polygon. The second chain gives the entry the same way. Every sign is exact.
#include <cstdint>
#include <span>

#include "convexloc/predicates.hpp"
#include "intersect/hits2d.hpp"
#include "intersect/ring2d.hpp"

namespace convexloc::detail {

namespace {

// where the chain counter-clockwise from `from` (sign `sign`, not 0) to `to` (strictly
// opposite sign) first stops having that sign
BoundaryHit firstLeaving(std::span<const Vec2> ring, Vec2 p1, Vec2 p2, std::uint32_t from,
                         std::uint32_t to, int sign) noexcept {
  const std::size_t n = ring.size();
  auto at = [&](std::uint32_t k) {
    const std::size_t i = from + k;
    return static_cast<std::uint32_t>(i >= n ? i - n : i);
  };
  std::uint32_t lo = 0, hi = static_cast<std::uint32_t>((to + n - from) % n);
  int hiSign = -sign;
  while (hi - lo > 1) {
    const std::uint32_t mid = lo + (hi - lo) / 2;
    const int s = orient2d(p1, p2, ring[at(mid)]);
    if (s == sign) {
      lo = mid;
    } else {
      hi = mid;
      hiSign = s;
    }
  }
  const std::uint32_t j = at(hi);
  return hiSign == 0 ? BoundaryHit{j, true} : BoundaryHit{prevOf(j, n), false};
}

}  // namespace

LineHit hitsFromExtremes(std::span<const Vec2> ring, Vec2 p1, Vec2 p2, std::uint32_t largest,
                         std::uint32_t smallest, int largestSign, int smallestSign) noexcept {
  const Crossing crossing = crossingOf(largestSign, smallestSign);
  if (crossing == Crossing::Misses) return {};
  if (crossing == Crossing::Crosses)
    return {Crossing::Crosses, firstLeaving(ring, p1, p2, largest, smallest, 1),
            firstLeaving(ring, p1, p2, smallest, largest, -1)};
  // touching: at the extreme on the line, and at its neighbour too when that edge lies on it
  const std::size_t n = ring.size();
  const bool polygonLeft = largestSign != 0;
  const std::uint32_t at = polygonLeft ? smallest : largest;
  const std::uint32_t next = nextOf(at, n), prev = prevOf(at, n);
  if (orient2d(p1, p2, ring[next]) == 0) return alongEdge(at, next, polygonLeft);
  if (orient2d(p1, p2, ring[prev]) == 0) return alongEdge(prev, at, polygonLeft);
  return {Crossing::Touches, {at, true}, {at, true}};
}

}  // namespace convexloc::detail
