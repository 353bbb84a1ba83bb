// convexloc-viewer — the draw lists' labels written on ImGui's background draw list over
// the scene, placed as the SVG places them (logic/view/scene_labels).
#pragma once

#include "gl/scene_view.hpp"
#include "logic/app/model.hpp"
#include "ui/ui_state.hpp"

namespace convexloc::viewer {

// the draw lists' labels, written on ImGui's background draw list over the scene, kept off
// the windows floating over it where they can
void drawLabels(Model& model, const UiState& ui, const SceneView& view);

}  // namespace convexloc::viewer
