// convexloc-viewer — who runs the frames: a loop here on the desktop; in the web page the
// browser, which calls back once per animation frame (a page must not block its thread).
#pragma once

#include <memory>

namespace convexloc::viewer {

// what draws one frame after another
class FrameSource {
 public:
  virtual ~FrameSource() = default;
  // draws one frame; false when the run is over
  virtual bool frame() = 0;
  // the program's exit code once the run is over
  virtual int exitCode() const = 0;
};

// Runs `source`'s frames until one returns false and returns its exit code. In the web page
// the browser runs them instead: this never returns and `source` lives on with the page.
int runFrames(std::unique_ptr<FrameSource> source);

}  // namespace convexloc::viewer
