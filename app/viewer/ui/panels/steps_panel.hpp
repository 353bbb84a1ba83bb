// convexloc-viewer — the Steps window: the placed point's query told step by step (core's
// trace, as logic/narration/steps.hpp tells it), the current step highlighted in the list and its
// line marked in the method's pseudo-code, Previous / Next, Play / Pause at a speed.
#pragma once

#include "logic/app/model.hpp"
#include "ui/ui_state.hpp"

namespace convexloc::viewer {

// The Steps window over the lower left corner of `area` (the scene's part of the window),
// above the caption, while Settings::stepBoxVisible and a point is placed, with the panels
// shown or hidden; plays the steps at `now` (seconds). Compact: at most half the scene's
// width, the list scrolling past a quarter of its height, the pseudo-code foldable to the
// current line. Its size goes to `ui.stepsSize`, for the fit to leave it room.
void stepsWindow(Model& model, UiState& ui, ScreenRect area, double now);

}  // namespace convexloc::viewer
