// convexloc-viewer — the draw lists' labels written on ImGui's background draw list over
// the scene, placed as the SVG places them (logic/view/scene_labels).
#pragma once

#include "gl/scene_view.hpp"
#include "logic/app/model.hpp"
#include "logic/draw/cube_inset.hpp"
#include "logic/draw/zoom_inset.hpp"
#include "ui/ui_state.hpp"

#include <optional>
#include <vector>

struct ImDrawList;

namespace convexloc::viewer {

// the boxes over the scene this frame that labels keep off where they can: the floating
// legend, the Steps window, the slide's card and caption, the split view's headings (the
// window's labels and the SVG's keep off the same)
std::vector<PixelBox> labelKeepOffs(const UiState& ui);

// A zoom inset over the scene in window pixels, its lines scaled as the scene's, and the box
// it takes with its text: the cube map's (logic/draw/cube_inset) where cells are refined far
// below a base cell, or a slide's tiny edges magnified (logic/draw/zoom_inset), in the corner
// the slide's layout keeps for it (off a slide, the cube's in a free corner); none elsewhere
struct ScreenInset {
  DrawList list;
  PixelBox box;
  PixelBox mark;                 // the leader's ring and the face's name there (empty: no leader)
  std::vector<PixelBox> leader;  // small boxes along the leader, which labels keep off
  // the boxes the scene's labels keep off: the inset, its mark, its leader
  std::vector<PixelBox> keepOff() const;
};
std::optional<ScreenInset> sceneInsetOver(const Model& model, const UiState& ui);

// the cube map's inset patch (found again only when the cells change); none off the cube map
const std::optional<CubeInset>& cubeInsetFound(const Model& model);
// the tiny edges' inset of the 2D scene; none in the split view and the Lines mode
std::optional<ZoomInset> zoomInsetFound(const Model& model);
// an inset's text line's room over or under its frame, window pixels
double insetTextRoom();

// a draw list in window pixels written on ImGui's draw list (fills, segments, labels at
// their text's middle), as the SVG writes it
void paintScreenList(const DrawList& list, ImDrawList* dl, const Palette& palette);

// the draw lists' labels, written on ImGui's background draw list over the scene, kept off
// the windows floating over it where they can
void drawLabels(Model& model, const UiState& ui, const SceneView& view);

}  // namespace convexloc::viewer
