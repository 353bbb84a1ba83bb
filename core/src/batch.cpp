// convexloc — the switch between the batches' AVX2 and scalar code (see batch.hpp), shared
// by the 2D and 3D locators.
#include "convexloc/batch.hpp"

#include <atomic>

namespace convexloc {
namespace {

std::atomic<bool> gVectorBatches{true};

bool cpuHasAvx2() noexcept {
#if defined(__x86_64__)
  static const bool yes = __builtin_cpu_supports("avx2");
  return yes;
#else
  return false;
#endif
}

}  // namespace

void setVectorBatches(bool enabled) noexcept {
  gVectorBatches.store(enabled);
}

bool vectorBatches() noexcept {
  return gVectorBatches.load(std::memory_order_relaxed) && cpuHasAvx2();
}

}  // namespace convexloc
