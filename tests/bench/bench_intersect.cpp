// convexloc-bench, the dual problems: Intersect2D/<method>/<N> (a line against the regular
// N-gon) and Intersect3D/<method>/<F> (a plane against the geodesic sphere with about F
// faces), one query per call, lines and planes through random points of the shape's
// bounding box enlarged by 10% (fixtures.hpp); IntersectBatch2D and IntersectBatch3D give the
// same queries to the batch classify, 2^16 per call. Reported as items per second.
#include <benchmark/benchmark.h>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "convexloc/intersect2d.hpp"
#include "convexloc/intersect3d.hpp"
#include "fixtures.hpp"

using namespace convexloc;
using namespace bench;

namespace {

// queries cycled through (a power of two)
constexpr std::size_t kQueries = std::size_t{1} << 16;

// The intersector of `method` on shape `size`, built once for the one-per-call and the batch
// benchmark that run one after the other (the 3D dual takes seconds per 10^5 faces to build).
template <class Intersector, class Method, class Shape>
const Intersector& built(Method method, std::int64_t size, const Shape& shape) {
  static std::unique_ptr<Intersector> last;
  static std::pair<Method, std::int64_t> key{};
  if (!last || key != std::pair{method, size}) {
    last.reset();
    last = std::make_unique<Intersector>(shape, method);
    key = {method, size};
  }
  return *last;
}

// one line per call: through points 2i and 2i + 1 of the enlarged box
void intersect2D(benchmark::State& state, LineMethod method) {
  const LineIntersector& li =
      built<LineIntersector>(method, state.range(0), polygon(state.range(0)));
  const std::vector<Vec2>& pts = points<Vec2>(state.range(0), 2 * kQueries);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(li.classify(pts[2 * i], pts[2 * i + 1]));
    i = (i + 1) & (kQueries - 1);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["bytes"] = static_cast<double>(li.stats().bytes);
}

// the batch: every line of the set per call
void intersectBatch2D(benchmark::State& state, LineMethod method) {
  const LineIntersector& li =
      built<LineIntersector>(method, state.range(0), polygon(state.range(0)));
  const std::vector<Vec2>& pts = points<Vec2>(state.range(0), 2 * kQueries);
  std::vector<Crossing> out(kQueries);
  for (auto _ : state) {
    li.classify(std::span(pts), std::span(out));
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kQueries));
}

// one plane per call: through points 3i, 3i + 1, 3i + 2 of the enlarged box
void intersect3D(benchmark::State& state, PlaneMethod method) {
  const PlaneIntersector& pi =
      built<PlaneIntersector>(method, state.range(0), polyhedron(state.range(0)));
  const std::vector<Vec3>& pts = points<Vec3>(state.range(0), 3 * kQueries);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(pi.classify(pts[3 * i], pts[3 * i + 1], pts[3 * i + 2]));
    i = (i + 1) & (kQueries - 1);
  }
  state.SetItemsProcessed(state.iterations());
  state.counters["bytes"] = static_cast<double>(pi.stats().bytes);
  state.counters["faces"] = static_cast<double>(polyhedron(state.range(0)).faceCount());
}

// the batch: every plane of the set per call
void intersectBatch3D(benchmark::State& state, PlaneMethod method) {
  const PlaneIntersector& pi =
      built<PlaneIntersector>(method, state.range(0), polyhedron(state.range(0)));
  const std::vector<Vec3>& pts = points<Vec3>(state.range(0), 3 * kQueries);
  std::vector<Crossing> out(kQueries);
  for (auto _ : state) {
    pi.classify(std::span(pts), std::span(out));
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kQueries));
  state.counters["faces"] = static_cast<double>(polyhedron(state.range(0)).faceCount());
}

[[maybe_unused]] const bool registered = [] {
  for (LineMethod m : kAllLineMethods)
    for (std::int64_t n : {8, 64, 1024, 16384, 262144, 1048576}) {
      if (m == LineMethod::Vertices && n > 16384) continue;
      benchmark::RegisterBenchmark(("Intersect2D/" + std::string(toString(m))).c_str(), intersect2D,
                                   m)
          ->Arg(n);
      benchmark::RegisterBenchmark(("IntersectBatch2D/" + std::string(toString(m))).c_str(),
                                   intersectBatch2D, m)
          ->Arg(n);
    }
  for (PlaneMethod m : kAllPlaneMethods)
    for (std::int64_t f : {100, 1000, 10000, 100000, 1000000}) {
      if (m == PlaneMethod::Vertices && f > 10000) continue;
      benchmark::RegisterBenchmark(("Intersect3D/" + std::string(toString(m))).c_str(), intersect3D,
                                   m)
          ->Arg(f);
      benchmark::RegisterBenchmark(("IntersectBatch3D/" + std::string(toString(m))).c_str(),
                                   intersectBatch3D, m)
          ->Arg(f);
    }
  return true;
}();

}  // namespace
