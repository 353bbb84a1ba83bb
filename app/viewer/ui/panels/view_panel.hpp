// convexloc-viewer — the View panel: theme, text size, the scene's view options,
// presentation and legend, Screenshot and SVG and their folder, Fit, the shaders' reload,
// the frame time and the GL driver.
#pragma once

#include "gl/renderer.hpp"
#include "logic/app/model.hpp"
#include "ui/ui_state.hpp"

namespace convexloc::viewer {

// the View panel's widgets, in the left window
void viewPanel(Model& model, Renderer& renderer, UiState& ui);

}  // namespace convexloc::viewer
