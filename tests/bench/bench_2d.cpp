// convexloc-bench, 2D: Locate2D, Batch2D, Build2D and the streaming limits, on regular
// N-gons (fixtures.hpp). Every figure is reported as items per second; the report script
// turns it into ns per point.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <string>
#include <thread>
#include <type_traits>
#include <vector>

#include "convexloc/batch.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/locate2d.hpp"
#include "fixtures.hpp"

using namespace convexloc;
using namespace bench;

namespace {

const std::int64_t kSizes[] = {8, 64, 1024, 16384, 262144, 1048576};

// The streaming limit: read two doubles (three for Stream3D, the size of a 3D point), write
// one byte per point, split over T threads the way locateParallel splits a batch.
inline std::uint8_t streamByte(Vec2 p) { return static_cast<std::uint8_t>(p.x < p.y); }
inline std::uint8_t streamByte(Vec3 p) { return static_cast<std::uint8_t>(p.x < p.y + p.z); }

template <class P>
void stream(benchmark::State& state) {
  const std::size_t count = static_cast<std::size_t>(state.range(0));
  const unsigned threads = static_cast<unsigned>(state.range(1));
  std::vector<P> pts(count);
  Rng rng(7);
  for (P& p : pts) {
    if constexpr (std::is_same_v<P, Vec3>)
      p = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    else
      p = {rng.uniform(-1, 1), rng.uniform(-1, 1)};
  }
  std::vector<std::uint8_t> out(count);
  auto run = [&](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) out[i] = streamByte(pts[i]);
  };
  const std::size_t share = ((count + threads - 1) / threads + 63) / 64 * 64;
  for (auto _ : state) {
    {
      std::vector<std::jthread> helpers;
      for (unsigned k = 1; k < threads; ++k)
        helpers.emplace_back(run, std::min(count, share * k), std::min(count, share * (k + 1)));
      run(0, std::min(count, share));
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

template <class L>
void registerMethod(const std::string& name, std::int64_t maxLocateN, std::int64_t maxBatchN) {
  for (std::int64_t n : kSizes) {
    if (n > maxLocateN) continue;
    benchmark::RegisterBenchmark(("Locate2D/" + name).c_str(), locateOne<L, Vec2>)->Arg(n);
    benchmark::RegisterBenchmark(("Build2D/" + name).c_str(), build<L, Vec2>)->Arg(n);
  }
  for (std::int64_t n : {8, 64, 1024, 4096, 16384, 262144, 1048576}) {
    if (n > maxBatchN) continue;
    for (int t : {1, 2})
      benchmark::RegisterBenchmark(("Batch2D/" + name).c_str(), locateBatch<L, Vec2>)
          ->Args({n, t})
          ->ArgNames({"", "threads"})
          ->UseRealTime();
  }
}

[[maybe_unused]] const bool registered = [] {
  registerMethod<HalfplaneLocator>("halfplane", 16384, 64);
  registerMethod<WedgeLocator>("wedge", 1 << 20, 4096);
  registerMethod<SlabLocator>("slab", 1 << 20, 4096);
  registerMethod<UniformLocator>("uniform", 1 << 20, 1 << 20);
  registerMethod<PolarLocator>("polar", 1 << 20, 1 << 20);
  benchmark::RegisterBenchmark("Stream", stream<Vec2>)
      ->Args({1 << 16, 1})
      ->Args({kBatchPoints, 1})
      ->Args({kBatchPoints, 2})
      ->ArgNames({"", "threads"})
      ->UseRealTime();
  benchmark::RegisterBenchmark("Stream3D", stream<Vec3>)
      ->Args({kBatchPoints, 1})
      ->Args({kBatchPoints, 2})
      ->ArgNames({"", "threads"})
      ->UseRealTime();
  return true;
}();

}  // namespace
