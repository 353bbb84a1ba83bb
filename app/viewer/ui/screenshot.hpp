// convexloc-viewer — the window's pixels to a PNG file.
#pragma once

#include <string>

namespace convexloc::viewer {

// Reads the current read buffer (width x height pixels) and writes it to `path` as an RGB
// PNG, top row first. Returns an empty string, or why it failed.
std::string saveScreenshot(const std::string& path, int width, int height);

// a fresh file name in the working directory: convexloc-YYYYMMDD-HHMMSS.png
std::string screenshotName();

}  // namespace convexloc::viewer
