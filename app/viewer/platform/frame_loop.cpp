// convexloc-viewer — the frame loop, or the browser's animation frames.
#include "platform/frame_loop.hpp"

#ifdef __EMSCRIPTEN__
#include <emscripten/emscripten.h>
#endif

namespace convexloc::viewer {

#ifdef __EMSCRIPTEN__

namespace {
// one animation frame; the loop stops when the source's run is over
void browserFrame(void* source) {
  if (!static_cast<FrameSource*>(source)->frame()) emscripten_cancel_main_loop();
}
}  // namespace

int runFrames(std::unique_ptr<FrameSource> source) {
  // fps 0: the browser's requestAnimationFrame; true: main's stack is unwound here, never
  // returned to, so the source is handed over and lives on with the page
  emscripten_set_main_loop_arg(browserFrame, source.release(), 0, true);
  return 0;  // not reached
}

#else

int runFrames(std::unique_ptr<FrameSource> source) {
  while (source->frame()) {
  }
  return source->exitCode();
}

#endif

}  // namespace convexloc::viewer
