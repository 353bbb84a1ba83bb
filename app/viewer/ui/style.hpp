// convexloc-viewer — how the panels look: the ImGui theme and the font.
#pragma once

#include "logic/colour.hpp"

namespace convexloc::viewer {

// ImGui's colours and sizes for a theme at a scale (1 = normal)
void applyStyle(Theme theme, float scale);

// (Re)builds the font atlas at `pixels` pixel height: DejaVu Sans when installed, ImGui's
// own font otherwise. Call outside a frame; with `recreateTexture` (after the first frame)
// the GL backend's font texture is made again.
void loadFont(float pixels, bool recreateTexture);

}  // namespace convexloc::viewer
