// convexloc (internal) — where a line meets a polygon's boundary, from the vertices' exact
// sides.
#pragma once

#include <cstdint>
#include <span>

#include "convexloc/intersect2d.hpp"

namespace convexloc::detail {

// The crossing of the line p1 -> p2 from every vertex's side: O(N), stopping early once
// vertices on both sides are seen.
Crossing crossingBySides(std::span<const Vec2> ring, Vec2 p1, Vec2 p2) noexcept;

// The crossing and the entry and exit (see LineHit) from every vertex's side: O(N).
LineHit hitsBySides(std::span<const Vec2> ring, Vec2 p1, Vec2 p2) noexcept;

// The crossing and the entry and exit from a vertex where f is largest and one where it is
// smallest, with their exact signs: O(log N), bisection along the two chains between them.
LineHit hitsFromExtremes(std::span<const Vec2> ring, Vec2 p1, Vec2 p2, std::uint32_t largest,
                         std::uint32_t smallest, int largestSign, int smallestSign) noexcept;

// The hits of a line lying along edge `edge` (both its vertices on the line): in the line's
// direction, the edge runs backwards when the polygon lies on the line's right (polygonLeft
// false), forwards otherwise.
inline LineHit alongEdge(std::uint32_t edge, std::uint32_t next, bool polygonLeft) noexcept {
  const BoundaryHit start{edge, true}, end{next, true};
  return polygonLeft ? LineHit{Crossing::Touches, start, end}
                     : LineHit{Crossing::Touches, end, start};
}

}  // namespace convexloc::detail
