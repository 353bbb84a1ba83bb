// convexloc-viewer — what the 2D Lines mode draws, from what core reports: in the primal
// frame the line, its two points, the extreme vertices, entry and exit, the clipped
// segment and the vertices the dual cell proposed; in the inset the dual polygon P*, its
// polar slabs, the point b and its cell. GL-free; world coordinates (the inset's mapping).
#pragma once

#include "logic/base/colour.hpp"
#include "logic/base/draw_list.hpp"
#include "logic/dual/lines2d.hpp"

namespace convexloc::viewer {

// the Lines mode's overlay; nothing when the mode is off
void buildLines2D(const Lines2D& lines, const Palette& palette, bool labels, DrawList& out);

}  // namespace convexloc::viewer
