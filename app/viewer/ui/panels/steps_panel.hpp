// convexloc-viewer — the Steps window: the placed point's query told step by step (core's
// trace, as logic/narration/steps.hpp tells it), the current step highlighted in the list and its
// line marked in the method's pseudo-code, Previous / Next, Play / Pause at a speed.
#pragma once

#include "logic/app/model.hpp"
#include "ui/ui_state.hpp"

namespace convexloc::viewer {

// Advances the steps' player (Play) to `now` (seconds), before the frame's layout.
void tickStepPlayer(Model& model, double now);

// The Steps window in its box of the slide's layout (ui.layout.steps: over the lower left
// corner of the scene's area, above the caption), its heading, controls (not on a slide:
// its keys step), steps and pseudo-code where the layout puts their lines. Its rectangle
// goes to `ui.stepsRect`, for the labels to keep off.
void stepsWindow(Model& model, UiState& ui, double now);

}  // namespace convexloc::viewer
