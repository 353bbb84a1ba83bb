// convexloc-viewer — the window's pixels to a PNG file.
#pragma once

#include <string>

#include "logic/model.hpp"
#include "ui/ui_state.hpp"

namespace convexloc::viewer {

// Reads the window's back buffer (width x height pixels) and writes it to `path` as an RGB
// PNG, top row first. Returns an empty string, or why it failed.
std::string saveScreenshot(const std::string& path, int width, int height);

// a fresh file name in the working directory: convexloc-YYYYMMDD-HHMMSS.png
std::string screenshotName();

// Writes the screenshot this frame asks for: to `finalPath` when it is not empty (the last
// frame of a --screenshot run), else to a fresh name when the UI asked for one. A failure
// becomes the model's error; the written path becomes a notice until `now` + 4 s. Returns
// false when a screenshot to `finalPath` failed.
bool screenshotIfAsked(Model& model, UiState& ui, const std::string& finalPath, int width,
                       int height, double now);

}  // namespace convexloc::viewer
