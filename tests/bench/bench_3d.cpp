// convexloc-bench, 3D: Locate3D, Batch3D and Build3D on geodesic spheres of about F faces.
//
// Points: uniform in the polyhedron's bounding box enlarged by 10% on each side, generated
// once per size. Every figure is reported as items per second.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "convexloc/generate3d.hpp"
#include "convexloc/locate3d.hpp"
#include "convexloc/polyhedron.hpp"

using namespace convexloc;

namespace {

constexpr std::size_t kLocatePoints = 1 << 20;
constexpr std::size_t kBatchPoints = 10'000'000;
const std::int64_t kFaces[] = {100, 1000, 10000, 100000, 1000000};

// the geodesic sphere with about f faces, built once
const ConvexPolyhedron& polyhedron(std::int64_t f) {
  static std::map<std::int64_t, std::unique_ptr<ConvexPolyhedron>> cache;
  auto& slot = cache[f];
  if (!slot)
    slot = std::make_unique<ConvexPolyhedron>(
        generatePolyhedron(PolyhedronKind::Geodesic, static_cast<std::size_t>(f), 1));
  return *slot;
}

// `count` uniform points for the size-f polyhedron, built once
const std::vector<Vec3>& points(std::int64_t f, std::size_t count) {
  static std::map<std::pair<std::int64_t, std::size_t>, std::vector<Vec3>> cache;
  auto& slot = cache[{f, count}];
  if (slot.empty()) slot = generatePoints3D(polyhedron(f), count, 42, false);
  return slot;
}

// one point per call
template <class L>
void locateOne(benchmark::State& state) {
  const std::int64_t f = state.range(0);
  const L loc(polyhedron(f));
  const auto& pts = points(f, kLocatePoints);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(loc.locate(pts[i]));
    i = (i + 1) & (kLocatePoints - 1);
  }
  state.counters["faces"] = static_cast<double>(polyhedron(f).faceCount());
  state.SetItemsProcessed(state.iterations());
}

// the batch path over 10^7 points, each benchmark thread taking its share
template <class L>
void locateBatch(benchmark::State& state) {
  // thread 0 prepares; the others read only inside the loop, after benchmark's start barrier
  static std::unique_ptr<L> loc;
  static const std::vector<Vec3>* pts = nullptr;
  static std::vector<Location> out;
  if (state.thread_index() == 0) {
    loc = std::make_unique<L>(polyhedron(state.range(0)));
    pts = &points(state.range(0), kBatchPoints);
    out.resize(kBatchPoints);
  }
  const std::size_t share = kBatchPoints / static_cast<std::size_t>(state.threads());
  const std::size_t begin = share * static_cast<std::size_t>(state.thread_index());
  for (auto _ : state) {
    loc->locate(std::span(*pts).subspan(begin, share), std::span(out).subspan(begin, share));
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(share));
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
          ->Arg(f)
          ->Threads(t)
          ->UseRealTime();
  }
}

[[maybe_unused]] const bool registered = [] {
  registerMethod<HalfspaceLocator>("halfspace", 100);
  registerMethod<WalkLocator>("walk", 10000);
  registerMethod<CubemapLocator>("cubemap", 1000000);
  return true;
}();

}  // namespace
