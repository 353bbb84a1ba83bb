// convexloc-viewer — the 2D Method panel's teaching views: the split view (a second
// method beside the current one), the build animation (Build, play and pause, a step
// slider) and the button that opens Why O(1).
#pragma once

#include "logic/app/model.hpp"
#include "ui/ui_state.hpp"

namespace convexloc::viewer {

// Split view check box and the right half's method
void splitControls(Model& model);
// Build: play or pause, the step slider, "edge k of N"
void buildControls(Model& model);
// the button opening the Why O(1) window
void whyButton(Model& model);
// the split view's divider and each half's caption ("polar: 1 predicate, inside")
void splitDecorations(const Model& model, const UiState& ui);
// the split view's headings this frame (logic/teach/slide_layout's splitHeading), into
// `ui.splitHeadings`: the labels keep off them, the SVG writes them
void splitHeadings(const Model& model, UiState& ui);
// the right half's placed point and its trace, under the inspector (split view only)
void splitInspector(const Model& model);
// moves a playing build animation on by this frame's time
void advanceBuild(Model& model, double seconds);

}  // namespace convexloc::viewer
