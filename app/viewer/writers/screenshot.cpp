// convexloc-viewer — screenshots: the window's pixels (gl/context) through png_write; SVG
// figures through svg_export.
#include "writers/screenshot.hpp"

#include <cerrno>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <vector>

#include "gl/context.hpp"
#include "writers/png_write.hpp"
#include "writers/svg_export.hpp"

namespace convexloc::viewer {
namespace {

// the absolute form of a path, for notices the user can find the file by
std::string absolute(const std::string& path) {
  std::error_code ec;
  const std::filesystem::path p = std::filesystem::absolute(path, ec);
  return ec ? path : p.lexically_normal().string();
}

// a file the UI asked for (fresh, in the export directory) or the command line's
std::string targetOf(const UiState& ui, const std::string& finalPath, const char* extension) {
  return finalPath.empty() ? exportPath(ui.exportDir, extension) : finalPath;
}

// the notice of a written file, or the model's error
bool report(Model& model, UiState& ui, const char* what, const std::string& path,
            const std::string& problem, bool final, double now) {
  if (!problem.empty()) {
    model.fail(std::string(what) + ": " + problem);
    return !final;
  }
  ui.notice = std::string(what) + " written: " + absolute(path);
  ui.noticeUntil = now + 6.0;
  return true;
}

}  // namespace

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

std::string screenshotName(const char* extension) {
  std::time_t t = std::time(nullptr);
  std::tm tm{};
  localtime_r(&t, &tm);
  char buf[64];
  std::strftime(buf, sizeof buf, "convexloc-%Y%m%d-%H%M%S.", &tm);
  return buf + std::string(extension);
}

std::string exportPath(const std::string& dir, const char* extension) {
  const std::filesystem::path base(dir.empty() ? std::string(".") : dir);
  return absolute((base / screenshotName(extension)).string());
}

bool screenshotIfAsked(Model& model, UiState& ui, const std::string& finalPath, int width,
                       int height, double now) {
  if (!ui.screenshotRequested && finalPath.empty()) return true;
  ui.screenshotRequested = false;
  const std::string path = targetOf(ui, finalPath, "png");
  return report(model, ui, "screenshot", path, saveScreenshot(path, width, height),
                !finalPath.empty(), now);
}

bool svgIfAsked(Model& model, const SceneView& view, UiState& ui, const std::string& finalPath,
                double now) {
  if (!ui.svgRequested && finalPath.empty()) return true;
  ui.svgRequested = false;
  const std::string path = targetOf(ui, finalPath, "svg");
  std::string problem;
  writeSceneSvg(model, view, ui, path, problem);
  return report(model, ui, "SVG", path, problem, !finalPath.empty(), now);
}

}  // namespace convexloc::viewer
