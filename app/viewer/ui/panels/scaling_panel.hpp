// convexloc-viewer — the Why O(1) window: measures every 2D method on regular N-gons in
// a worker thread (a progress bar, Cancel), plots predicates and nanoseconds per query
// against N and the paper's slab memory against convexloc's, and exports them as SVG;
// and --why-svg, the same measurement without a window.
#pragma once

#include "logic/app/model.hpp"
#include "logic/app/options.hpp"
#include "ui/ui_state.hpp"

namespace convexloc::viewer {

// the Why O(1) window, while model.whyOpen
void scalingWindow(Model& model, UiState& ui);

// --why-svg and --why-record: measures in this thread (or reads --why-from), writes the SVG
// and the record asked for, says so; the exit code (0, or 1)
int measureToSvg(const Options& options);

}  // namespace convexloc::viewer
