// convexloc-viewer — a base for the classes that own a resource of the window or the GL
// context (the window, shader programs, the renderer's buffers) and so must not be copied.
#pragma once

namespace convexloc::viewer {

class NoCopy {
 public:
  NoCopy(const NoCopy&) = delete;
  NoCopy& operator=(const NoCopy&) = delete;

 protected:
  NoCopy() = default;
  ~NoCopy() = default;
};

}  // namespace convexloc::viewer
