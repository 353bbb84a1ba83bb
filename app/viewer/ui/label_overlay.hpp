// convexloc-viewer — the draw lists' labels written on ImGui's background draw list over
// the scene, placed as the SVG places them (logic/view/scene_labels).
#pragma once

#include "gl/scene_view.hpp"
#include "logic/app/model.hpp"
#include "ui/ui_state.hpp"

#include <vector>

namespace convexloc::viewer {

// the boxes over the scene this frame that labels keep off where they can: the floating
// legend, the Steps window, the slide's card and caption, the split view's headings (the
// window's labels and the SVG's keep off the same)
std::vector<PixelBox> labelKeepOffs(const UiState& ui);

// the draw lists' labels, written on ImGui's background draw list over the scene, kept off
// the windows floating over it where they can
void drawLabels(Model& model, const UiState& ui, const SceneView& view);

}  // namespace convexloc::viewer
