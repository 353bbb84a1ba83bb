// convexloc-viewer — the draw lists' labels placed on the screen: projected by the camera,
// kept off the markers, the drawn segments and the windows over the scene. The window and
// the SVG place them with this one function, so both show the same labels in the same spots.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "logic/base/draw_list.hpp"
#include "logic/view/label_layout.hpp"

namespace convexloc::viewer {

// A world point in window pixels (x, y) and its depth (the clip-space w in 3D, 0 in 2D);
// nothing for a point behind the eye.
using ScreenProjection = std::function<std::optional<glm::dvec3>(glm::dvec3)>;

// the labels of `lists` placed as both the window and the SVG draw them
struct PlacedSceneLabel {
  const Label* label = nullptr;
  glm::dvec2 anchor{0.0};
  LabelPlacement place;
};
// Projects the labels of `lists` (at most `budget`, those far off `area` skipped) and
// places them in `area` around the markers of the same lists, off their segments and off
// the `windows` over the scene where free room allows; overlay labels (`essentialFrom` and
// later lists) are essential.
std::vector<PlacedSceneLabel> layoutSceneLabels(std::span<const DrawList* const> lists,
                                                std::size_t essentialFrom,
                                                const ScreenProjection& project,
                                                const PixelBox& area, const MeasureText& measure,
                                                double scale, std::size_t budget = 400,
                                                std::span<const PixelBox> windows = {});

}  // namespace convexloc::viewer
