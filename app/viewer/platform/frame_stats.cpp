// convexloc-viewer — frame timing.
#include "platform/frame_stats.hpp"

namespace convexloc::viewer {

void FrameStats::end() {
  const auto now = Clock::now();
  const double ms = 1e3 * std::chrono::duration<double>(now - frameStart_).count();
  const double sinceLast = 1e3 * std::chrono::duration<double>(now - last_).count();
  smoothedMs_ = smoothedMs_ == 0.0 ? ms : 0.9 * smoothedMs_ + 0.1 * sinceLast;
  last_ = now;
  if (frames_ > 1) {  // the first frame uploads everything; time the steady state
    timedMs_ += ms;
    ++timedFrames_;
  }
}

}  // namespace convexloc::viewer
