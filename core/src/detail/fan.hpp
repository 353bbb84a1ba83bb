// convexloc (internal) — bisection over the fan of diagonals from vertex 0 (the wedge
// method), shared by `wedge` and by the polar locator's fallback.
//
// For a counter-clockwise, strictly convex ring v, the rays from v[0] through v[1] .. v[n-1]
// cut the polygon into the fan triangles (v[0], v[i], v[i+1]). A point clockwise of the
// first ray or counter-clockwise of the last is outside; otherwise bisection over the rays
// finds the triangle whose wedge holds it, and the one edge (v[i], v[i+1]) of that triangle
// on the boundary decides, with the two outer rays' own edges where p lies on them.
#pragma once

#include <cstdint>
#include <span>

#include "convexloc/predicates.hpp"
#include "detail/sinks2d.hpp"

namespace convexloc::detail {

// the class of p in the ring v by bisection over the fan from v[0]
template <class Sink>
Location fanLocate(std::span<const Vec2> v, Vec2 p, Sink& sink) {
  if (nonFinite(p)) return Location::Outside;
  const std::uint32_t n = static_cast<std::uint32_t>(v.size());
  const Vec2 o = v[0];
  sink.apex(o);  // the rays below start here, also when polar falls back to the fan
  int first = orient2d(o, v[1], p);
  sink.ray(1, first);
  if (first < 0) return Location::Outside;  // clockwise of the first edge's line
  int last = orient2d(o, v[n - 1], p);
  sink.ray(n - 1, last);
  if (last > 0) return Location::Outside;  // counter-clockwise of the last edge's line
  if (first == 0 && last == 0) return Location::Boundary;  // p is vertex 0
  std::uint32_t lo = 1, hi = n - 1;  // orient(o, v[lo], p) >= 0 >= orient(o, v[hi], p)
  while (hi - lo > 1) {
    std::uint32_t mid = lo + (hi - lo) / 2;
    int s = orient2d(o, v[mid], p);
    sink.ray(mid, s);
    if (s >= 0)
      lo = mid;
    else
      hi = mid;
  }
  int s = orient2d(v[lo], v[hi], p);
  sink.edge(lo, s);
  if (s < 0) return Location::Outside;
  if (s == 0) return Location::Boundary;
  // strictly inside triangle edge lo; on the fan's outer rays means on edge 0 or n-1
  if ((lo == 1 && first == 0) || (hi == n - 1 && last == 0)) return Location::Boundary;
  return Location::Inside;
}

}  // namespace convexloc::detail
