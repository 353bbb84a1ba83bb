// convexloc (internal) — trace sinks of the 3D locators: the query code is written once and
// either records what it does or not.
//
// A query template takes a Sink and reports each step to it; NoSink3D's calls are empty and
// compile away, so locate() and the batch pay nothing for trace(). The sinks sit in an
// unnamed namespace: every instantiation of a query template on them is then local to its
// file, and the compiler may drop the empty sink from its signature and tail-call it, as it
// does for any file-local function.
#pragma once

#include <cmath>
#include <cstdint>
#include <optional>

#include "convexloc/locate3d.hpp"
#include "detail/sink_queries.hpp"

namespace convexloc::detail {
namespace {

// records nothing; compiles away in locate()
struct NoSink3D {
  void face(std::uint32_t, int) {}
  void visit(std::uint32_t) {}
  void step(std::uint32_t, std::uint8_t, int) {}
  void cell(int, int, std::uint64_t, std::uint64_t, double, double) {}
  void crowded() {}
  void zone(std::uint32_t, std::uint32_t, std::uint32_t, int) {}
  void sector(std::uint32_t, std::uint32_t, int) {}
  void fallback() {}
  void nonFinite() {}
  void atCentre() {}
  void radius(double, float, float, bool) {}
  void slab(bool) {}
  // the radius filter runs
  static constexpr bool radii() { return true; }
};

// records every step into a Trace3D
struct TraceSink3D {
  Trace3D& t;
  void face(std::uint32_t f, int s) { t.faces.push_back({f, s}); }
  void visit(std::uint32_t f) { t.path.push_back(f); }
  void step(std::uint32_t f, std::uint8_t e, int s) { t.steps.push_back({f, e, s}); }
  void cell(int cubeFace, int level, std::uint64_t i, std::uint64_t j, double s, double tt) {
    t.cubeFace = cubeFace;
    t.level = level;
    t.cellI = static_cast<std::uint32_t>(i);
    t.cellJ = static_cast<std::uint32_t>(j);
    t.s = s;
    t.t = tt;
  }
  void crowded() { t.crowded = true; }
  void zone(std::uint32_t k, std::uint32_t a, std::uint32_t b, int s) {
    t.zoneSteps.push_back({k, a, b, s});
  }
  void sector(std::uint32_t k, std::uint32_t v, int s) { t.sectorSteps.push_back({k, v, s}); }
  void radius(double d2, float in2, float out2, bool decided) {
    t.distance = std::sqrt(d2);
    t.innerRadius = std::sqrt(static_cast<double>(in2));
    t.outerRadius = std::sqrt(static_cast<double>(out2));
    t.byRadius = decided;
  }
  void slab(bool decided) { t.bySlab = decided; }
  void fallback() { t.fallback = true; }
  void nonFinite() { t.nonFinite = true; }
  void atCentre() { t.atCentre = true; }
  // the radius filter runs unless the trace was asked without it
  bool radii() const { return t.radiusFilter; }
};

}  // namespace

// the 3D sinks for SinkQueries
template <>
struct Sinks<Trace3D> {
  using None = NoSink3D;
  using Record = TraceSink3D;
};

namespace {

// the trace of one query: `query(sink)` runs it into a TraceSink3D, its answer the result
template <class Query>
Trace3D traced(Method3D method, std::optional<Vec3> centre, Query&& query,
               TraceOptions options = {}) {
  Trace3D t;
  t.method = method;
  t.centre = centre;
  t.radiusFilter = options.radii;
  TraceSink3D sink{t};
  t.result = query(sink);
  return t;
}

}  // namespace
}  // namespace convexloc::detail
