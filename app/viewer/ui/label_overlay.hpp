// convexloc-viewer — the draw lists' labels written on ImGui's background draw list over
// the scene, placed as the SVG places them (logic/view/scene_labels).
#pragma once

#include "gl/scene_view.hpp"
#include "logic/app/model.hpp"
#include "ui/ui_state.hpp"

#include <optional>
#include <vector>

struct ImDrawList;

namespace convexloc::viewer {

// the boxes over the scene this frame that labels keep off where they can: the floating
// legend, the Steps window, the slide's card and caption, the split view's headings (the
// window's labels and the SVG's keep off the same)
std::vector<PixelBox> labelKeepOffs(const UiState& ui);

// the cube map's zoom inset over the 3D scene (logic/draw/cube_inset) in window pixels, its
// lines scaled as the scene's, and the box it takes with its title and zoom; none off the
// cube map, where no cells are refined far below a base cell, or where no corner is free
struct ScreenInset {
  DrawList list;
  PixelBox box;
  PixelBox mark;  // the leader's ring and the face's name there (empty: no leader)
};
std::optional<ScreenInset> cubeInsetOver(const Model& model, const UiState& ui);

// a draw list in window pixels written on ImGui's draw list (fills, segments, labels at
// their text's middle), as the SVG writes it
void paintScreenList(const DrawList& list, ImDrawList* dl, const Palette& palette);

// the draw lists' labels, written on ImGui's background draw list over the scene, kept off
// the windows floating over it where they can
void drawLabels(Model& model, const UiState& ui, const SceneView& view);

}  // namespace convexloc::viewer
