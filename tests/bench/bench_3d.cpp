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

template <class L>
void registerMethod(const std::string& name, std::int64_t maxBatchF) {
  for (std::int64_t f : kFaces) {
    benchmark::RegisterBenchmark(("Locate3D/" + name).c_str(), locateOne<L, Vec3>)->Arg(f);
    benchmark::RegisterBenchmark(("Build3D/" + name).c_str(), build<L, Vec3>)->Arg(f);
    if (f > maxBatchF) continue;
    for (int t : {1, 2})
      benchmark::RegisterBenchmark(("Batch3D/" + name).c_str(), locateBatch<L, Vec3>)
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
