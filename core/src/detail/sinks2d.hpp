// convexloc (internal) — trace sinks and edge tests of the 2D locators: the query code is
// written once and either records what it does or not.
//
// A query template takes a Sink and reports each step to it; NoSink2D's calls are empty and
// compile away, so locate() and the batches pay nothing for trace().
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <span>

#include "convexloc/locate2d.hpp"
#include "convexloc/predicates.hpp"
#include "detail/sink_queries.hpp"

namespace convexloc::detail {

// === Sinks

// records nothing; compiles away in locate()
struct NoSink2D {
  void ray(std::uint32_t, int) {}
  void edge(std::uint32_t, int) {}
  void cell(std::int64_t, int) {}
  void crowded() {}
  void outsideBox() {}
  void atCentre() {}
  void apex(Vec2) {}
  void radius(double, float, float, bool) {}
  void uniformIndex(double, double, double, std::uint32_t) {}
  // the radius filter runs
  static constexpr bool radii() { return true; }
  // the first of the ascending `ys` above y (std::upper_bound)
  static std::size_t upperBound(std::span<const double> ys, double y) {
    return static_cast<std::size_t>(std::upper_bound(ys.begin(), ys.end(), y) - ys.begin());
  }
};

// records every step into a Trace2D
struct TraceSink2D {
  Trace2D& t;
  void ray(std::uint32_t v, int s) { t.rays.push_back({v, s}); }
  void edge(std::uint32_t e, int s) { t.edges.push_back({e, s}); }
  void cell(std::int64_t c, int octant) {
    t.cell = c;
    t.octant = octant;
  }
  void crowded() { t.crowded = true; }
  void outsideBox() { t.outsideBox = true; }
  void atCentre() { t.atCentre = true; }
  void apex(Vec2 a) { t.apex = a; }
  void radius(double d2, float in2, float out2, bool decided) {
    t.distance = std::sqrt(d2);
    t.innerRadius = std::sqrt(static_cast<double>(in2));
    t.outerRadius = std::sqrt(static_cast<double>(out2));
    t.byRadius = decided;
  }
  // eq. (4)'s numbers: slab = floor((y - yMin) * scale), scale = slabs / (box height)
  void uniformIndex(double y, double yMin, double scale, std::uint32_t slabs) {
    t.uniform = {yMin, 1.0 / scale, (y - yMin) * scale, slabs};
  }
  // the radius filter runs unless the trace was asked without it
  bool radii() const { return t.radiusFilter; }
  // std::upper_bound's bisection (half the range each probe), each probe recorded
  std::size_t upperBound(std::span<const double> ys, double y) {
    std::size_t first = 0, count = ys.size();
    while (count > 0) {
      const std::size_t half = count / 2, mid = first + half;
      const bool above = !(y < ys[mid]);
      t.probes.push_back({static_cast<std::uint32_t>(mid), ys[mid], above});
      first = above ? mid + 1 : first;
      count = above ? count - half - 1 : half;
    }
    return first;
  }
};

// the 2D sinks, for SinkQueries
template <>
struct Sinks<Trace2D> {
  using None = NoSink2D;
  using Record = TraceSink2D;
};

// === Edge tests

// orient2d of p against edge e of the ring v
inline int edgeSign(std::span<const Vec2> v, std::uint32_t e, Vec2 p) {
  std::uint32_t next = e + 1 == v.size() ? 0 : e + 1;
  return orient2d(v[e], v[next], p);
}

// tests p against the listed edges, stopping at the first outer side; exact when the list
// holds every edge p can exit through
template <class Sink>
inline Location testEdges(std::span<const Vec2> v, const std::uint32_t* first,
                          const std::uint32_t* last, Vec2 p, Sink& sink) {
  bool zero = false;
  for (const std::uint32_t* it = first; it != last; ++it) {
    int s = edgeSign(v, *it, p);
    sink.edge(*it, s);
    if (s < 0) return Location::Outside;
    zero |= s == 0;
  }
  return zero ? Location::Boundary : Location::Inside;
}

// p has an infinite or NaN coordinate: no polygon contains it, and no predicate may see it
// (the exact fallback cannot represent it)
inline bool nonFinite(Vec2 p) {
  return !(std::isfinite(p.x) && std::isfinite(p.y));
}

// p outside the closed box
inline bool outsideBox(const Box2& b, Vec2 p) {
  return !(p.x >= b.lo.x && p.x <= b.hi.x && p.y >= b.lo.y && p.y <= b.hi.y);
}

}  // namespace convexloc::detail
