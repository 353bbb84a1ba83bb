// convexloc-viewer — the windows floating over the scene: the legend (in the scene's lower
// right corner or where dragged), the caption box along the bottom, the error and notice
// toasts.
#pragma once

#include <glm/glm.hpp>

#include "logic/app/model.hpp"
#include "ui/ui_state.hpp"

namespace convexloc::viewer {

// The legend alone, over the scene's lower right corner (above the caption), or where the
// user dragged it; its size is kept for the next fit, which leaves room for it.
void legendOverlay(Model& model, UiState& ui, ScreenRect area, glm::dvec2 window, double now);
// the caption, large, in its box of the slide's layout (ui.layout) along the area's bottom
void captionBox(Model& model, UiState& ui, ScreenRect area);

// A text box of the slide's layout as a window: its lines where the layout puts them, the
// first `large` at the box's scale, the rest at the body size in `rest`'s colour.
void layoutBox(const char* id, const TextBox& t, std::size_t large, Rgba rest);
// the last error (closable) and notice, for a few seconds at the top of the scene area
void toast(Model& model, UiState& ui, ScreenRect area, double now);

}  // namespace convexloc::viewer
