// convexloc-viewer — the part of the window the scene has: the panels' widths, the area
// right of them, and the camera fitted into it beside the caption, the legend and the Steps
// window. The window, the screenshot and the SVG all take the scene's area from here.
#pragma once

#include <glm/glm.hpp>

#include "logic/app/model.hpp"
#include "ui/ui_state.hpp"

namespace convexloc::viewer {

// the panel widths in window pixels, at the current font scale
float leftPanelWidth(const Model& model, glm::dvec2 window);
float rightPanelWidth(const Model& model, glm::dvec2 window);
// the page (ui/slide_frame: a slide's letterboxed page, else the window) less the panels
ScreenRect pageArea(const Model& model, const UiState& ui, glm::dvec2 window);
// the part of the page the scene has to itself: right of the panel when it shows, below a
// lecture's slide card
ScreenRect sceneArea(const Model& model, const UiState& ui, glm::dvec2 window);

// the room the camera fits the shape into: the slide layout's (ui/slide_frame), or in the
// split view the whole area below the halves' headings; `thisFrame`, when given, is the
// layout already made for this frame and window (not laid out again)
ScreenRect fitRoom(const Model& model, const UiState& ui, glm::dvec2 window,
                   const SlideLayout* thisFrame = nullptr);

// fits the camera to the shape in the slide layout's room for the scene (beside the card,
// the caption, the legend and the Steps window); for `now` + 1.5 s a change of the
// layout's room (the legend took its size) fits again
void fitScene(Model& model, UiState& ui, glm::dvec2 window, double now);
// true while the camera is as the last fitScene left it (not panned, zoomed or turned since)
bool viewAsFitted(const Model& model, const UiState& ui);

}  // namespace convexloc::viewer
