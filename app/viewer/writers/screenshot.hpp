// convexloc-viewer — the window's pixels to a PNG file, the scene to an SVG file.
#pragma once

#include <string>

#include "gl/scene_view.hpp"
#include "logic/app/model.hpp"
#include "ui/ui_state.hpp"

namespace convexloc::viewer {

// Reads the window's back buffer (width x height pixels) and writes it to `path` as an RGB
// PNG, top row first. Returns an empty string, or why it failed.
std::string saveScreenshot(const std::string& path, int width, int height);

// a fresh file name: convexloc-YYYYMMDD-HHMMSS.EXT
std::string screenshotName(const char* extension = "png");

// a fresh file in the export directory (`dir`, or the working directory when empty), as an
// absolute path
std::string exportPath(const std::string& dir, const char* extension);

// Writes the screenshot this frame asks for: to `finalPath` when it is not empty (the last
// frame of a --screenshot run), else to a fresh name in the export directory when the UI
// asked for one. A failure becomes the model's error; the written file's absolute path
// becomes a notice until `now` + 4 s. Returns false when a screenshot to `finalPath` failed.
bool screenshotIfAsked(Model& model, UiState& ui, const std::string& finalPath, int width,
                       int height, double now);

// the same for the SVG of the scene (`view` synced this frame): --svg or V / Shift+F12
bool svgIfAsked(Model& model, const SceneView& view, UiState& ui, const std::string& finalPath,
                double now);

}  // namespace convexloc::viewer
