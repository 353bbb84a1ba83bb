// convexloc-viewer — screenshots through glReadPixels and png_write.
#include "ui/screenshot.hpp"

#include <cerrno>
#include <cstring>
#include <ctime>
#include <vector>

#include "gl/gl.hpp"
#include "ui/png_write.hpp"

namespace convexloc::viewer {

std::string saveScreenshot(const std::string& path, int width, int height) {
  if (width <= 0 || height <= 0) return "nothing to capture: the window has no pixels";
  std::vector<unsigned char> rgb(static_cast<std::size_t>(width) *
                                 static_cast<std::size_t>(height) * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, rgb.data());
  if (GLenum e = glGetError(); e != GL_NO_ERROR)
    return "glReadPixels failed (GL error " + std::to_string(e) + ")";
  // GL's rows start at the bottom; PNG's at the top
  if (!writePngRgb(path.c_str(), width, height, rgb.data(), true))
    return path + ": cannot be written (" + std::strerror(errno) + ")";
  return {};
}

std::string screenshotName() {
  std::time_t t = std::time(nullptr);
  std::tm tm{};
  localtime_r(&t, &tm);
  char buf[64];
  std::strftime(buf, sizeof buf, "convexloc-%Y%m%d-%H%M%S.png", &tm);
  return buf;
}

}  // namespace convexloc::viewer
