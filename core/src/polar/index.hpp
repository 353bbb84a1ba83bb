// convexloc (internal) — the polar locator's index function, shared by its build and its
// queries.
//
// The index. Seen from the centre c, a direction (dx, dy) has a pseudo-angle P in [0, 8):
// its octant (counter-clockwise from +x, from the signs of dx and dy and whether
// |dy| > |dx|) plus the ratio min(|dx|, |dy|) / max(|dx|, |dy|), which is monotone in the
// angle inside the octant (rising in even octants, falling in odd ones). With q slabs per
// octant, the cell of a point is floor(q * P) in exact arithmetic; the query computes it as
// cellIndex() below: the octant index from the sign bits and the comparison (exact), the
// slab from the ratio, and kOctantLayout's base and step to turn both into the cell.
//
// Conservative cells. In doubles the ratio carries a relative error of at most 2 ulps (one
// rounding in each subtraction, one in the division), so the cell a query computes lies
// within 2^-50 of its exact P, and on an octant border it may land on either side. The build
// evaluates the same quantities for each vertex (pseudoAngle, with the query's own
// operations) and registers every edge on the cells of its span widened by kPolarMargin, far
// above those errors and far below a cell. So every point maps to a cell listing the edge its
// ray from the centre exits through, and "inside iff on the inner side of every edge listed"
// is exact; a crowded cell's edges form one counter-clockwise run, searched by bisection.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

#include "convexloc/locate2d.hpp"

namespace convexloc::polar {

// the widening of every edge's span of pseudo-angles: far above the query's 2^-50, far below
// a cell
inline constexpr double kPolarMargin = 0x1p-40;

// per octant index (sign bit of dx, sign bit of dy, |dy| > |dx|): the octant counter-clockwise
// from +x, and whether the ratio min/max falls as the angle grows in it
struct OctantLayout {
  std::uint32_t octant;
  bool falling;
};
inline constexpr OctantLayout kOctantLayout[8] = {{0, false}, {1, true},  {7, true},  {6, false},
                                                  {3, true},  {2, false}, {4, false}, {5, true}};

// a direction's place among q slabs per octant: its octant index (kOctantLayout's: sign bit
// of dx, sign bit of dy, |dy| > |dx|) and its slab floor(q min/max), clamped to q - 1
struct OctantSlab {
  unsigned octant = 0;
  std::uint32_t slab = 0;
};

// The octant and slab of direction (dx, dy) with q slabs per octant (`scale` is q as a
// double); false for the zero direction, a non-finite one, or one too long for the
// arithmetic. The polar query, its trace and the dual's direction cells all index by it.
[[gnu::always_inline]] inline bool octantSlab(double dx, double dy, double scale, std::uint32_t q,
                                              OctantSlab& out) noexcept {
  const double ax = std::fabs(dx), ay = std::fabs(dy);
  const double hi = std::max(ax, ay), lo = std::min(ax, ay);  // maxsd / minsd, no branch
  if (!(ax + ay < std::numeric_limits<double>::infinity()) || hi == 0) return false;
  out.slab = std::min(static_cast<std::uint32_t>(lo / hi * scale), q - 1);
  out.octant = (std::signbit(dx) ? 4u : 0u) | (std::signbit(dy) ? 2u : 0u) | (ay > ax ? 1u : 0u);
  return true;
}

// the cell p maps to, or -1 for the centre itself, a non-finite point, or one too far for
// the arithmetic
[[gnu::always_inline]] inline std::int64_t cellIndex(const detail::PolarIndex& index,
                                                     Vec2 p) noexcept {
  OctantSlab o;
  if (!octantSlab(p.x - index.centre.x, p.y - index.centre.y, index.slabScale, index.slabsPerOctant,
                  o))
    return -1;
  return index.cellBase[o.octant] + index.cellStep[o.octant] * static_cast<std::int64_t>(o.slab);
}

// the squared distance of p from c, as the query computes it
inline double distance2(Vec2 p, Vec2 c) {
  const double dx = p.x - c.x, dy = p.y - c.y;
  return dx * dx + dy * dy;
}

// Quadrant and canonical coordinates (u > 0, v >= 0) of a direction; false for (0, 0).
// Each quadrant is the direction rotated by a multiple of 90 degrees, which is exact.
inline bool canonical(double dx, double dy, int& quad, double& u, double& v) {
  if (dy >= 0 && dx > 0) {
    quad = 0;
    u = dx;
    v = dy;
  } else if (dx <= 0 && dy > 0) {
    quad = 1;
    u = dy;
    v = -dx;
  } else if (dx < 0 && dy <= 0) {
    quad = 2;
    u = -dx;
    v = -dy;
  } else if (dx >= 0 && dy < 0) {
    quad = 3;
    u = -dy;
    v = dx;
  } else {
    return false;
  }
  return true;
}

// the pseudo-angle in [0, 8] of a direction, computed with the query's own operations
inline double pseudoAngle(double dx, double dy) {
  int quad = 0;
  double u = 0, v = 0;
  canonical(dx, dy, quad, u, v);
  return v <= u ? 2 * quad + v / u : 2 * quad + 1 + (1 - u / v);
}

// a direction with this pseudo-angle (for drawing and the radii's estimates, never an index)
inline Vec2 directionOf(double angle) {
  int oct = std::clamp(static_cast<int>(std::floor(angle)), 0, 7);
  double f = angle - oct;
  double u = 1, v = f;
  if (oct % 2) {
    u = 1 - f;
    v = 1;
  }
  switch (oct / 2) {
    case 0: return {u, v};
    case 1: return {-v, u};
    case 2: return {-u, -v};
    default: return {v, -u};
  }
}

}  // namespace convexloc::polar
