// An independent exact reference for lines against convex polygons: every vertex's side from
// reference2d.hpp's rational signs, the boundary hits LineHit defines, and segment clipping by
// exact Cyrus-Beck with the ends rounded once to the nearest double. Shares no code with core's
// intersect/. Used by the unit tests and the intersect fuzz target.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "convexloc/intersect2d.hpp"
#include "reference2d.hpp"

namespace ref {

using convexloc::BoundaryHit;
using convexloc::Crossing;
using convexloc::LineHit;
using convexloc::Segment2D;

// exact sign of (p2 - p1) x (v - p1), from the filtered rational reference
inline int side(Vec2 p1, Vec2 p2, Vec2 v) {
  return cross(v, p1, p2);
}

// the crossing and the boundary hits, as LineHit defines them, from all the signs
inline LineHit referenceHit(const std::vector<Vec2>& ring, Vec2 p1, Vec2 p2) {
  const std::size_t n = ring.size();
  std::vector<int> s(n);
  bool above = false, below = false;
  for (std::size_t i = 0; i < n; ++i) {
    s[i] = side(p1, p2, ring[i]);
    above |= s[i] > 0;
    below |= s[i] < 0;
  }
  LineHit hit;
  auto idx = [](std::size_t i) { return static_cast<std::uint32_t>(i); };
  if (above && below) {
    hit.crossing = Crossing::Crosses;
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t j = (i + 1) % n;
      const BoundaryHit at = s[j] == 0 ? BoundaryHit{idx(j), true} : BoundaryHit{idx(i), false};
      if (s[i] < 0 && s[j] >= 0) hit.exit = at;
      if (s[i] > 0 && s[j] <= 0) hit.entry = at;
    }
    return hit;
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (s[i] != 0) continue;
    hit.crossing = Crossing::Touches;
    hit.entry = hit.exit = {idx(i), true};
    const std::size_t j = (i + 1) % n;
    if (s[j] == 0) {
      // along edge i: forwards when the polygon lies on the left
      hit.entry = {idx(above ? i : j), true};
      hit.exit = {idx(above ? j : i), true};
      return hit;
    }
    if (s[(i + n - 1) % n] != 0) return hit;
  }
  return hit;
}

// the double nearest to q, ties to even, by bisection over the bit patterns
inline double nearest(const mpq_class& q) {
  const mpq_class a = abs(q);
  std::uint64_t lo = 0, hi = 0x7ff0000000000000ULL;  // lo <= |q| < hi as doubles
  while (hi - lo > 1) {
    const std::uint64_t mid = lo + (hi - lo) / 2;
    if (mpq_class(std::bit_cast<double>(mid)) <= a)
      lo = mid;
    else
      hi = mid;
  }
  const double below = std::bit_cast<double>(lo), above = std::bit_cast<double>(hi);
  const mpq_class dl = a - below, dh = mpq_class(above) - a;
  const double r = dl < dh ? below : (dh < dl ? above : ((lo & 1) == 0 ? below : above));
  return sgn(q) < 0 ? -r : r;
}

// the part of the segment inside, by exact Cyrus-Beck in the parameter t in [0, 1]
inline std::optional<Segment2D> referenceClip(const std::vector<Vec2>& ring, Vec2 s1, Vec2 s2) {
  const mpq_class dx = mpq_class(s2.x) - s1.x, dy = mpq_class(s2.y) - s1.y;
  mpq_class lo = 0, hi = 1;
  for (std::size_t i = 0; i < ring.size(); ++i) {
    const Vec2 a = ring[i], b = ring[(i + 1) % ring.size()];
    const mpq_class ex = mpq_class(b.x) - a.x, ey = mpq_class(b.y) - a.y;
    // inner side: e x (s1 + t d - a) >= 0, i.e. g0 + t g1 >= 0
    const mpq_class g0 = ex * (mpq_class(s1.y) - a.y) - ey * (mpq_class(s1.x) - a.x);
    const mpq_class g1 = ex * dy - ey * dx;
    if (sgn(g1) == 0) {
      if (sgn(g0) < 0) return std::nullopt;
      continue;
    }
    const mpq_class t = -g0 / g1;
    if (sgn(g1) > 0)
      lo = std::max(lo, t);
    else
      hi = std::min(hi, t);
  }
  if (lo > hi) return std::nullopt;
  auto at = [&](const mpq_class& t) {
    if (t == 0) return s1;
    if (t == 1) return s2;
    return Vec2{nearest(s1.x + t * dx), nearest(s1.y + t * dy)};
  };
  return Segment2D{at(lo), at(hi)};
}

}  // namespace ref
