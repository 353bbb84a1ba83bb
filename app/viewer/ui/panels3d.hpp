// convexloc-viewer — the 3D panels: the polyhedron (Shape), the method with its statistics
// (Method), the slicing plane, the View panel's 3D options, the legend and the inspector.
#pragma once

#include "logic/model.hpp"
#include "ui/ui_state.hpp"

namespace convexloc::viewer {

// the polyhedron: its label and counts, files, generators, the degenerate gallery
void shapePanel3D(Model& model, UiState& ui);
// the method, the cube map's grid, statistics, histogram and Compare all methods
void methodPanel3D(Model& model, UiState& ui);
// the slicing plane's axis and offset, and whether it shows
void slicePanel3D(Model& model);
// what the 3D scene draws (faces, see-through, wireframe, cube grid, tints, labels)
void viewOptions3D(Model& model);
// what each colour and line means, with the counts
void legend3D(Model& model);
// the hovered and the pinned cell, the placed point's trace; with `hints`, what to do
void inspector3D(Model& model, bool hints);

}  // namespace convexloc::viewer
