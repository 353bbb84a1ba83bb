// convexloc-bench: the shapes, the points and the timing loop every benchmark file shares.
//
// Shapes: the regular N-gon (2D) and the geodesic sphere of about F faces (3D). Points:
// uniform in the shape's bounding box enlarged by 10% on each side. Each is built once per
// size and kept for the whole run.
#pragma once

#include <benchmark/benchmark.h>

#include <cstdint>
#include <map>
#include <memory>
#include <utility>
#include <vector>

#include "convexloc/batch.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/polyhedron.hpp"

namespace bench {

using namespace convexloc;

// points cycled through by the one-point-per-call benchmarks (a power of two)
inline constexpr std::size_t kLocatePoints = std::size_t{1} << 20;
// points in one batch
inline constexpr std::size_t kBatchPoints = 10'000'000;

// the regular polygon with n vertices
inline const ConvexPolygon& polygon(std::int64_t n) {
  static std::map<std::int64_t, std::unique_ptr<ConvexPolygon>> cache;
  auto& slot = cache[n];
  if (!slot)
    slot = std::make_unique<ConvexPolygon>(
        generatePolygon(PolygonKind::Regular, static_cast<std::size_t>(n), 1));
  return *slot;
}

// the geodesic sphere with about f faces
inline const ConvexPolyhedron& polyhedron(std::int64_t f) {
  static std::map<std::int64_t, std::unique_ptr<ConvexPolyhedron>> cache;
  auto& slot = cache[f];
  if (!slot)
    slot = std::make_unique<ConvexPolyhedron>(
        generatePolyhedron(PolyhedronKind::Geodesic, static_cast<std::size_t>(f), 1));
  return *slot;
}

// `count` query points for the shape of that size: Vec2 for polygon(size), Vec3 for
// polyhedron(size)
template <class P>
const std::vector<P>& points(std::int64_t size, std::size_t count) {
  static std::map<std::pair<std::int64_t, std::size_t>, std::vector<P>> cache;
  auto& slot = cache[{size, count}];
  if (slot.empty()) {
    if constexpr (sizeof(P) == sizeof(Vec2))
      slot = generatePoints(polygon(size), count, 42, false);
    else
      slot = generatePoints3D(polyhedron(size), count, 42, false);
  }
  return slot;
}

// one point per call, the latency a caller sees in a plain loop
template <class P, class Locate>
void timeEachPoint(benchmark::State& state, const std::vector<P>& pts, Locate&& locate) {
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(locate(pts[i]));
    i = (i + 1) & (kLocatePoints - 1);
  }
  state.SetItemsProcessed(state.iterations());
}

// the shape of that size for points of type P: polygon(size) or polyhedron(size)
template <class P>
const auto& shape(std::int64_t size) {
  if constexpr (sizeof(P) == sizeof(Vec2))
    return polygon(size);
  else
    return polyhedron(size);
}

// locator L, one point per call; range(0) is the size
template <class L, class P>
void locateOne(benchmark::State& state) {
  const L loc(shape<P>(state.range(0)));
  timeEachPoint(state, points<P>(state.range(0), kLocatePoints),
                [&](P p) { return loc.locate(p); });
  if constexpr (sizeof(P) != sizeof(Vec2))
    state.counters["faces"] = static_cast<double>(polyhedron(state.range(0)).faceCount());
}

// locator L's batch path over 10^7 points, on the library's own threads (locateParallel);
// range(0) is the size, range(1) the threads
template <class L, class P>
void locateBatch(benchmark::State& state) {
  const std::int64_t n = state.range(0);
  const unsigned threads = static_cast<unsigned>(state.range(1));
  const L loc(shape<P>(n));
  const std::vector<P>& pts = points<P>(n, kBatchPoints);
  std::vector<Location> out(kBatchPoints);
  for (auto _ : state) {
    locateParallel(loc, std::span(pts), std::span(out), threads);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kBatchPoints));
}

// building locator L on the shape of size range(0)
template <class L, class P>
void build(benchmark::State& state) {
  const auto& s = shape<P>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(L(s));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

}  // namespace bench
