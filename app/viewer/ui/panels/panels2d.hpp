// convexloc-viewer — the 2D panels: the polygon (Shape), the method with its statistics
// (Method), the View panel's 2D options, the legend and the inspector.
#pragma once

#include "ui/ui_state.hpp"

namespace convexloc::viewer {

// the 2D scene's panels
const ScenePanels& panels2D();

}  // namespace convexloc::viewer
