// convexloc-viewer — screenshots: the window's pixels (gl/context) through png_write.
#include "ui/screenshot.hpp"

#include <cerrno>
#include <cstring>
#include <ctime>
#include <vector>

#include "gl/context.hpp"
#include "ui/png_write.hpp"

namespace convexloc::viewer {

std::string saveScreenshot(const std::string& path, int width, int height) {
  if (width <= 0 || height <= 0) return "nothing to capture: the window has no pixels";
  std::string problem;
  const std::vector<unsigned char> rgb = readWindowRgb(width, height, problem);
  if (rgb.empty()) return problem;
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

bool screenshotIfAsked(Model& model, UiState& ui, const std::string& finalPath, int width,
                       int height, double now) {
  if (!ui.screenshotRequested && finalPath.empty()) return true;
  ui.screenshotRequested = false;
  const std::string path = finalPath.empty() ? screenshotName() : finalPath;
  const std::string problem = saveScreenshot(path, width, height);
  if (!problem.empty()) {
    model.fail("screenshot: " + problem);
    return finalPath.empty();
  }
  ui.notice = "screenshot written: " + path;
  ui.noticeUntil = now + 4.0;
  return true;
}

}  // namespace convexloc::viewer
