// convexloc-viewer — the frame's slide: whether one is shown, the page it sits on in the
// window (letterboxed), and its layout (logic/teach/slide_layout) with the window's font
// metrics. The window's boxes, the camera's fit, the screenshot and the SVG take it from here.
#pragma once

#include <glm/glm.hpp>

#include "logic/app/model.hpp"
#include "logic/teach/slide_layout.hpp"
#include "ui/ui_state.hpp"

namespace convexloc::viewer {

// a slide is shown: a lecture's, a paper figure's, or the presentation mode's
bool onSlide(const Model& model, const UiState& ui);

// a lecture's slide showing Why O(1): its plots are the slide's figure, drawn by the slide's
// layout without the window, its widgets or the scene (the window stays for live use)
bool plotsSlide(const Model& model, const UiState& ui);

// the page in the window: the slide's fixed page (Settings::page, 1920x1080 unless --page
// gives another) letterboxed on a slide, else the whole window at scale 1
PageFit pageOf(const Model& model, const UiState& ui, glm::dvec2 window);

// the text's metrics in the window's current font (call outside a window that scales it)
SlideMetrics windowMetrics();

// The slide's layout this frame: the card, the caption, the Steps window, the legend and
// the scene's room in the page less the panels. `withSteps` false leaves the Steps window
// out of the scene's room (the split view's halves share the whole area under it).
SlideLayout frameLayout(const Model& model, const UiState& ui, glm::dvec2 window,
                        bool withSteps = true);

// What a slide draws apart from the live window: its tiny edges' zoom inset in the corner
// its layout keeps (not beside the polygon), the name of only the cube face its query is on
// (none without one: a cube inset names its face at its leader's end). Set before the fit
// and each frame's drawing.
void slideDrawOptions(Model& model, const UiState& ui);

// the split view's headings' text over the body size: a slide's kSplitHeadingShare of the
// page's height where that is smaller, else 1
double splitHeadingScale(const Model& model, const UiState& ui, glm::dvec2 window);

// a slide's figure room, which its scene, labels, insets or plots keep to (empty: not a slide
// with one, as the split view and the Why O(1) window in presentation mode)
ScreenRect figureRoomOf(const Model& model, const UiState& ui);

// the bars beside a letterboxed page, and on a slide around its figure room, in the theme's
// background, under every window
void drawLetterbox(const Model& model, const UiState& ui, glm::dvec2 window);

}  // namespace convexloc::viewer
