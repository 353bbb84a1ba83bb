// convexloc-viewer — the scene shown, written as an SVG file (the picture's GL-free part
// is writers/svg_writer; this gathers the scene view's draw lists, the camera and the text
// measure of the window's font).
#pragma once

#include <string>

#include "gl/scene_view.hpp"
#include "logic/app/model.hpp"
#include "ui/ui_state.hpp"

#include "writers/svg_writer.hpp"

namespace convexloc::viewer {

// Writes the scene as the window shows it (the view synced for this frame, after a frame
// has been drawn: the window's font measures the labels), with the slide's boxes of
// `ui.layout`, the legend where the window put it, to `path` as SVG. Returns false
// and sets `error` (the path and why) when it cannot be written.
bool writeSceneSvg(const Model& model, const SceneView& view, const UiState& ui,
                   const std::string& path, std::string& error);

}  // namespace convexloc::viewer
