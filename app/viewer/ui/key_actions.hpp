// convexloc-viewer — what the viewer does for each key action (and for the panels' buttons
// that stand for a key).
#pragma once

#include "logic/app/actions.hpp"
#include "logic/app/model.hpp"
#include "ui/ui_state.hpp"

namespace convexloc::viewer {

// carries out a key's action on the scene shown (or asks the frame loop, for a screenshot)
void perform(const Action& action, Model& model, UiState& ui);

}  // namespace convexloc::viewer
