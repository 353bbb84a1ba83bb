// convexloc — a batch of queries over several threads.
//
// locateParallel(locator, points, out, threads) cuts the batch into one run per thread and
// lets each run go through the locator's own batch path (locate(points, out)), which
// allocates nothing per point. Locators are immutable after the build, so any number of
// threads may query one at once. The runs are whole multiples of 64 points, so no two
// threads write to one cache line of `out`; a batch too small to gain from threads runs on
// the calling thread alone.
#pragma once

#include <algorithm>
#include <cstddef>
#include <span>
#include <thread>
#include <utility>
#include <vector>

#include "convexloc/geometry.hpp"

namespace convexloc {

// Batches use AVX2 code where the CPU has it, chosen at run time (what ships is built for
// baseline x86-64); the answers are the same either way. Off, every batch runs the scalar
// code (for tests and comparisons).
void setVectorBatches(bool enabled) noexcept;
// whether batches use the AVX2 code: enabled, and the CPU has it
bool vectorBatches() noexcept;

namespace detail {
#if defined(__cpp_lib_jthread)
using BatchThread = std::jthread;
#else
// a thread joined when it goes, where the standard library has no std::jthread (libc++ 14,
// the web build's)
class BatchThread {
 public:
  template <class F>
  explicit BatchThread(F&& f) : thread_(std::forward<F>(f)) {}
  BatchThread(BatchThread&&) noexcept = default;
  BatchThread& operator=(BatchThread&&) = delete;
  ~BatchThread() {
    if (thread_.joinable()) thread_.join();
  }

 private:
  std::thread thread_;
};
#endif
}  // namespace detail

// below this many points per thread, starting a thread costs more than it saves
inline constexpr std::size_t kMinPointsPerThread = std::size_t{1} << 15;

// the threads a batch of `count` points would use when asked for `threads` (0: one per core)
inline unsigned batchThreads(std::size_t count, unsigned threads = 0) noexcept {
  if (threads == 0) threads = std::max(1u, std::thread::hardware_concurrency());
  const std::size_t useful = std::max<std::size_t>(1, count / kMinPointsPerThread);
  return static_cast<unsigned>(std::min<std::size_t>(threads, useful));
}

// Locates points[i] into out[i] for every i below min(points.size(), out.size()), on up to
// `threads` threads (0: one per core), the calling thread among them.
template <class Locator, class Point>
void locateParallel(const Locator& locator, std::span<const Point> points, std::span<Location> out,
                    unsigned threads = 0) {
  const std::size_t n = std::min(points.size(), out.size());
  const unsigned t = batchThreads(n, threads);
  if (t <= 1) {
    locator.locate(points.first(n), out.first(n));
    return;
  }
  constexpr std::size_t kLine = 64;  // points per cache line of answers
  const std::size_t share = ((n + t - 1) / t + kLine - 1) / kLine * kLine;  // t shares cover n
  std::vector<detail::BatchThread> helpers;
  helpers.reserve(t - 1);
  for (unsigned k = 1; k < t; ++k) {
    const std::size_t begin = std::min(n, share * k);
    const std::size_t end = k + 1 == t ? n : std::min(n, begin + share);
    if (begin == end) break;
    helpers.emplace_back([&locator, points, out, begin, end] {
      locator.locate(points.subspan(begin, end - begin), out.subspan(begin, end - begin));
    });
  }
  locator.locate(points.first(std::min(n, share)), out.first(std::min(n, share)));
  // the helpers join as they go
}

}  // namespace convexloc
