// convexloc-bench, 2D: Locate2D, Batch2D, Build2D and the streaming limit.
//
// Points: uniform in the polygon's bounding box enlarged by 10% on each side, generated
// once per size. Polygons: the regular N-gon. Every figure is reported as items per second;
// the report script turns it into ns per point.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "convexloc/generate2d.hpp"
#include "convexloc/locate2d.hpp"

using namespace convexloc;

namespace {

constexpr std::size_t kLocatePoints = 1 << 20;
constexpr std::size_t kBatchPoints = 10'000'000;
const std::int64_t kSizes[] = {8, 64, 1024, 16384, 262144, 1048576};

// the regular polygon with about n vertices, built once
const ConvexPolygon& polygon(std::int64_t n) {
  static std::map<std::int64_t, std::unique_ptr<ConvexPolygon>> cache;
  auto& slot = cache[n];
  if (!slot)
    slot = std::make_unique<ConvexPolygon>(generatePolygon(PolygonKind::Regular, static_cast<std::size_t>(n), 1));
  return *slot;
}

// `count` uniform points for the size-n polygon, built once
const std::vector<Vec2>& points(std::int64_t n, std::size_t count) {
  static std::map<std::pair<std::int64_t, std::size_t>, std::vector<Vec2>> cache;
  auto& slot = cache[{n, count}];
  if (slot.empty()) slot = generatePoints(polygon(n), count, 42, false);
  return slot;
}

template <class L>
L make(const ConvexPolygon& p) {
  return L(p);
}

// one point per call, the latency a caller sees in a plain loop
template <class L>
void locateOne(benchmark::State& state) {
  const std::int64_t n = state.range(0);
  const L loc = make<L>(polygon(n));
  const auto& pts = points(n, kLocatePoints);
  std::size_t i = 0;
  for (auto _ : state) {
    benchmark::DoNotOptimize(loc.locate(pts[i]));
    i = (i + 1) & (kLocatePoints - 1);
  }
  state.SetItemsProcessed(state.iterations());
}

// the batch path over 10^7 points, each benchmark thread taking its share
template <class L>
void locateBatch(benchmark::State& state) {
  // thread 0 prepares; the others read only inside the loop, after benchmark's start barrier
  static std::unique_ptr<L> loc;
  static const std::vector<Vec2>* pts = nullptr;
  static std::vector<Location> out;
  if (state.thread_index() == 0) {
    loc = std::make_unique<L>(polygon(state.range(0)));
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
  const ConvexPolygon& p = polygon(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(make<L>(p));
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

// the streaming limit: read two doubles, write one byte per point
void stream(benchmark::State& state) {
  const std::size_t count = static_cast<std::size_t>(state.range(0));
  std::vector<Vec2> pts(count);
  Rng rng(7);
  for (Vec2& p : pts) p = {rng.uniform(-1, 1), rng.uniform(-1, 1)};
  std::vector<std::uint8_t> out(count);
  for (auto _ : state) {
    for (std::size_t i = 0; i < count; ++i) out[i] = static_cast<std::uint8_t>(pts[i].x < pts[i].y);
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

template <class L>
void registerMethod(const std::string& name, std::int64_t maxLocateN, std::int64_t maxBatchN) {
  for (std::int64_t n : kSizes) {
    if (n > maxLocateN) continue;
    benchmark::RegisterBenchmark(("Locate2D/" + name).c_str(), locateOne<L>)->Arg(n);
    benchmark::RegisterBenchmark(("Build2D/" + name).c_str(), build<L>)->Arg(n);
  }
  for (std::int64_t n : {8, 64, 1024, 4096, 16384, 262144, 1048576}) {
    if (n > maxBatchN) continue;
    for (int t : {1, 2})
      benchmark::RegisterBenchmark(("Batch2D/" + name).c_str(), locateBatch<L>)
          ->Arg(n)
          ->Threads(t)
          ->UseRealTime();
  }
}

[[maybe_unused]] const bool registered = [] {
  registerMethod<HalfplaneLocator>("halfplane", 16384, 64);
  registerMethod<WedgeLocator>("wedge", 1 << 20, 4096);
  registerMethod<SlabLocator>("slab", 1 << 20, 4096);
  registerMethod<UniformLocator>("uniform", 1 << 20, 1 << 20);
  registerMethod<PolarLocator>("polar", 1 << 20, 1 << 20);
  benchmark::RegisterBenchmark("Stream", stream)->Arg(1 << 16)->Arg(kBatchPoints);
  return true;
}();

}  // namespace
