// convexloc-viewer — a base for classes that own a resource (a window, GL objects) and so
// must not be copied.
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
