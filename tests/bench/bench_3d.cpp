// convexloc-bench, 3D: Locate3D, Batch3D and Build3D on geodesic spheres of about F faces
// (fixtures.hpp). Every figure is reported as items per second.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>
#include <vector>

#include "convexloc/batch.hpp"
#include "convexloc/locate3d.hpp"
#include "fixtures.hpp"

using namespace convexloc;
using namespace bench;

namespace {

const std::int64_t kFaces[] = {100, 1000, 10000, 100000, 1000000};

// one point per call
template <class L>
void locateOne(benchmark::State& state) {
  const std::int64_t f = state.range(0);
  const L loc(polyhedron(f));
  timeEachPoint(state, points<Vec3>(f, kLocatePoints), [&](Vec3 p) { return loc.locate(p); });
  state.counters["faces"] = static_cast<double>(polyhedron(f).faceCount());
}

// the batch path over 10^7 points, on the library's own threads (locateParallel)
template <class L>
void locateBatch(benchmark::State& state) {
  const std::int64_t n = state.range(0);
  const unsigned threads = static_cast<unsigned>(state.range(1));
  const L loc = L(polyhedron(n));
  const std::vector<Vec3>& pts = points<Vec3>(n, kBatchPoints);
  std::vector<Location> out(kBatchPoints);
  for (auto _ : state) {
    locateParallel(loc, std::span(pts), std::span(out), threads);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(kBatchPoints));
}

template <class L>
void build(benchmark::State& state) {
  const ConvexPolyhedron& p = polyhedron(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(L(p));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

template <class L>
void registerMethod(const std::string& name, std::int64_t maxBatchF) {
  for (std::int64_t f : kFaces) {
    benchmark::RegisterBenchmark(("Locate3D/" + name).c_str(), locateOne<L>)->Arg(f);
    benchmark::RegisterBenchmark(("Build3D/" + name).c_str(), build<L>)->Arg(f);
    if (f > maxBatchF) continue;
    for (int t : {1, 2})
      benchmark::RegisterBenchmark(("Batch3D/" + name).c_str(), locateBatch<L>)
          ->Args({f, t})
          ->ArgNames({"", "threads"})
          ->UseRealTime();
  }
}

[[maybe_unused]] const bool registered = [] {
  registerMethod<HalfspaceLocator>("halfspace", 100);
  registerMethod<WalkLocator>("walk", 100);
  registerMethod<CubemapLocator>("cubemap", 1000000);
  return true;
}();

}  // namespace
