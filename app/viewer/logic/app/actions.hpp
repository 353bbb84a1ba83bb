// convexloc-viewer — what a key asks the viewer to do, in the viewer's own words: the
// platform layer turns key presses into these, the UI carries them out.
#pragma once

#include <cstdint>

namespace convexloc::viewer {

enum class ActionKind : std::uint8_t {
  Screenshot,    // a PNG of the window in the export directory
  Fit,           // the camera fitted to the shape
  ToggleUi,      // the panels hidden or shown
  ToggleTheme,   // dark and light swapped
  ClearPoint,    // the placed point (and in 3D the pinned cell) cleared
  NewSpray,      // a spray with the next seed
  ToggleLines,   // the 2D Lines mode (the dual problem) on or off
  ChooseMethod,  // the method numbered `method` (0 = the first) in the scene's list
  // the placed point's query step by step
  PrevStep,     // the previous step (from all shown: the last)
  NextStep,     // the next step (from all shown: the first)
  ToggleRadii,  // the radius filter off (paper-faithful mode) or on
  // presentation and vector figures
  SaveSvg,        // the scene as an SVG file in the export directory
  TogglePresent,  // presentation mode on or off
  ToggleLegend,   // the legend shown or hidden
  TextLarger,     // the text zoom up a step (+)
  TextSmaller,    // the text zoom down a step (-)
  // a lecture's slides
  NextSlide,
  PreviousSlide,
  FirstSlide,
  LastSlide,
  ToggleBlank,      // the screen black (B), again or a slide key: back
  ToggleNotes,      // the speaker notes' window shown or hidden
  DismissProblems,  // the problems shown over the slide put away
};

struct Action {
  ActionKind kind = ActionKind::Fit;
  int method = 0;  // ChooseMethod only
};

}  // namespace convexloc::viewer
