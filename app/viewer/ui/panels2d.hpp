// convexloc-viewer — the 2D panels: the polygon (Shape), the method with its statistics
// (Method), the View panel's 2D options, the legend and the inspector.
#pragma once

#include "logic/model.hpp"
#include "ui/ui_state.hpp"

namespace convexloc::viewer {

// the polygon: its label and counts, files, generators, the degenerate gallery
void shapePanel2D(Model& model, UiState& ui);
// the method, its resolution, statistics, histogram and Compare all methods
void methodPanel2D(Model& model, UiState& ui);
// what the 2D scene draws (structure, tints, box, octants, labels, handles)
void viewOptions2D(Model& model);
// what each colour and line means, with the counts
void legend2D(Model& model);
// the hovered cell and the placed point's trace; with `hints`, what to do for them
void inspector2D(Model& model, bool hints);

}  // namespace convexloc::viewer
