// convexloc-bench, hulls: ConvexPolyhedron::hullOf on clouds of N points, the validation of
// the result included: points on the unit sphere (every point a vertex), points uniform in a
// cube (few vertices), and points on the unit sphere moved by 10^15 (coordinates on a grid
// of 1/8, many exactly coplanar). Reported as points per second.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include "convexloc/generate2d.hpp"
#include "convexloc/polyhedron.hpp"

using namespace convexloc;

namespace {

enum class Cloud : std::uint8_t { Sphere, Cube, FarSphere };

// n points of that cloud, made once per size
const std::vector<Vec3>& cloud(Cloud kind, std::int64_t n) {
  static std::map<std::pair<Cloud, std::int64_t>, std::vector<Vec3>> cache;
  auto& slot = cache[{kind, n}];
  if (!slot.empty()) return slot;
  Rng rng(7);
  slot.resize(static_cast<std::size_t>(n));
  for (Vec3& p : slot) {
    if (kind == Cloud::Cube) {
      p = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
      continue;
    }
    const double z = rng.uniform(-1, 1), a = rng.uniform(0, 2 * std::numbers::pi);
    const double r = std::sqrt(1 - z * z), shift = kind == Cloud::FarSphere ? 1e15 : 0.0;
    p = {shift + r * std::cos(a), shift + r * std::sin(a), shift + z};
  }
  return slot;
}

void hull(benchmark::State& state, Cloud kind) {
  const std::vector<Vec3>& points = cloud(kind, state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(ConvexPolyhedron::hullOf(points).faceCount());
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

[[maybe_unused]] const bool registered = [] {
  benchmark::RegisterBenchmark("Hull3D/sphere", hull, Cloud::Sphere)
      ->Arg(10'000)
      ->Arg(1'000'000)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("Hull3D/cube", hull, Cloud::Cube)
      ->Arg(100'000)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("Hull3D/sphere_at_1e15", hull, Cloud::FarSphere)
      ->Arg(20'000)
      ->Unit(benchmark::kMillisecond);
  return true;
}();

}  // namespace
