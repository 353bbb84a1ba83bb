// convexloc-viewer — frame timing: the smoothed frame time the View panel shows, and the
// mean over the frames after the first (which uploads everything) for --frames runs.
#pragma once

#include "convexloc/timing.hpp"

namespace convexloc::viewer {

class FrameStats {
 public:
  FrameStats() : start_(Clock::now()), last_(start_), frameStart_(start_) {}

  // a frame begins
  void begin() { frameStart_ = Clock::now(); }
  // the frame's picture is complete (counts it)
  void count() { ++frames_; }
  // the frame is over: its time joins the smoothed and the mean frame time
  void end();

  // frames counted so far
  int frames() const { return frames_; }
  // seconds since the program started
  double seconds() const { return secondsSince(start_); }
  // milliseconds per frame, smoothed over the last few
  double smoothedMs() const { return smoothedMs_; }
  // the mean milliseconds per frame after the first, 0 before there is one
  double meanMs() const { return timedFrames_ ? timedMs_ / timedFrames_ : 0.0; }

 private:
  Clock::time_point start_, last_, frameStart_;
  int frames_ = 0;
  double smoothedMs_ = 0.0;
  double timedMs_ = 0.0;
  int timedFrames_ = 0;
};

}  // namespace convexloc::viewer
