// convexloc-viewer — the 3D panels: the polyhedron (Shape), the method with its statistics
// (Method), the slicing plane, the View panel's 3D options, the legend and the inspector.
#pragma once

#include "ui/ui_state.hpp"

namespace convexloc::viewer {

// the 3D scene's panels
const ScenePanels& panels3D();

}  // namespace convexloc::viewer
