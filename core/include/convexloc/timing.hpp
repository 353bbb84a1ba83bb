// convexloc — the clock build times and the viewer's comparisons are read from.
#pragma once

#include <chrono>

namespace convexloc {

using Clock = std::chrono::steady_clock;

// seconds elapsed since `t0`
inline double secondsSince(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

}  // namespace convexloc
