// convexloc-viewer — the room a fit leaves the scene beside the windows that float over its
// lower corners (the legend on the right, the Steps window on the left). GL-free, so that
// the choice of strips is tested without a window.
#pragma once

#include <glm/glm.hpp>

#include "logic/base/screen_rect.hpp"

namespace convexloc::viewer {

// what floats over the scene area's lower corners, in pixels (zero: nothing there)
struct CornerBoxes {
  glm::dvec2 legend{0.0};  // the legend's strip size where the fit gave it one (box + margin)
  glm::dvec2 steps{0.0};   // the Steps window's size
  double margin = 10.0;    // the gap between a window and the area's edges
};

// The part of `full` (the scene area less the caption) to fit a scene `aspect` times as
// wide as high into: the Steps window over the lower left corner costs a strip, the
// bottom one up to its top or the left one up to its right edge, and the legend's strip
// (right or bottom) is chosen with it, the pair leaving the largest drawing. `fitted` (what
// the fit had before) is kept where the Steps window leaves it clear, or where no pair of
// strips keeps 40% of its drawing (the window then floats over the scene).
ScreenRect roomBesideCorners(ScreenRect fitted, ScreenRect full, const CornerBoxes& boxes,
                             double aspect);

}  // namespace convexloc::viewer
