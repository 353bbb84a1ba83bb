// convexloc-viewer — the frame's windows: the left panel (Shape, Method, Points, View),
// the right panel (legend and inspector) or their floating forms, the overlays, the Steps
// window, the slide card and the teaching views' windows.
#pragma once

#include "gl/renderer.hpp"
#include "logic/app/model.hpp"
#include "ui/ui_state.hpp"

namespace convexloc::viewer {

// the panels of the scene shown
const ScenePanels& panelsOf(const Model& model);

// every window of the frame; `now` in seconds
void drawUi(Model& model, Renderer& renderer, UiState& ui, double now);

}  // namespace convexloc::viewer
