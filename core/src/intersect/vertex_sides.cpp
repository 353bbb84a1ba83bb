// convexloc — a line against a polygon from every vertex's side: O(N), the baseline.
//
// Each vertex's side is the exact orient2d of the line's own two points against it. The
// ring is walked once; where consecutive signs go from strictly below the line to on or
// above it the line leaves the polygon (counter-clockwise, f rises where the boundary heads
// out along the line's direction), and where they go from strictly above to on or below it
// enters: at the vertex when its sign is zero, else inside the edge between them.
#include <cstdint>
#include <span>

#include "convexloc/predicates.hpp"
#include "intersect/hits2d.hpp"
#include "intersect/ring2d.hpp"

namespace convexloc::detail {

Crossing crossingBySides(std::span<const Vec2> ring, Vec2 p1, Vec2 p2) noexcept {
  bool above = false, below = false, on = false;
  for (const Vec2 v : ring) {
    const int s = orient2d(p1, p2, v);
    above |= s > 0;
    below |= s < 0;
    on |= s == 0;
    if (above && below) return Crossing::Crosses;
  }
  return on ? Crossing::Touches : Crossing::Misses;
}

LineHit hitsBySides(std::span<const Vec2> ring, Vec2 p1, Vec2 p2) noexcept {
  const std::size_t n = ring.size();
  const int first = orient2d(p1, p2, ring[0]);
  bool above = false, below = false;
  std::uint32_t onVertex = 0, onEdge = 0;
  bool anyOn = false, edgeOn = false;
  LineHit hit;
  int s = first;
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = nextOf(i, n);
    const int t = j == 0 ? first : orient2d(p1, p2, ring[j]);
    above |= s > 0;
    below |= s < 0;
    if (s == 0) {
      anyOn = true;
      onVertex = i;
      if (t == 0) edgeOn = true, onEdge = i;
    }
    const BoundaryHit at = t == 0 ? BoundaryHit{j, true} : BoundaryHit{i, false};
    if (s < 0 && t >= 0) hit.exit = at;
    if (s > 0 && t <= 0) hit.entry = at;
    s = t;
  }
  if (above && below) {
    hit.crossing = Crossing::Crosses;
    return hit;
  }
  if (!anyOn) return {};
  if (edgeOn) return alongEdge(onEdge, nextOf(onEdge, n), above);
  return {Crossing::Touches, {onVertex, true}, {onVertex, true}};
}

}  // namespace convexloc::detail
