// convexloc-viewer — lectures and the paper's figures in the UI: the slide card over the
// scene (its number, title and caption, shown with the panels hidden too), the Lecture
// panel (the slides, click to go; the paper's figures, one click each), the slide keys, and
// opening --lecture or --figure at start.
#pragma once

#include <cstddef>
#include <string>

#include "logic/app/actions.hpp"
#include "logic/app/model.hpp"
#include "logic/view/camera2d.hpp"
#include "ui/ui_state.hpp"

namespace convexloc::viewer {

// Opens the command line's lecture at its first slide, or makes --figure N a one-slide
// lecture. A bad lecture becomes the model's error (a toast); `headless` runs print it
// and get false (nothing is to be written).
bool startLecture(Model& model, UiState& ui, const Options& options, bool headless);

// Shows slide k of the lecture (clamped), with the method comparison the slide asks for
// (`compare`); the first problem, or an empty string.
std::string showSlideNow(Model& model, UiState& ui, std::ptrdiff_t k);

// shows slide k of the lecture (clamped); a problem becomes the model's error
void goToSlide(Model& model, UiState& ui, std::ptrdiff_t k);

// the next, previous, first or last slide, for the key actions
void moveSlide(ActionKind kind, Model& model, UiState& ui);

// The slide card: "3 / 14: title" and a figure's caption, in its box of the slide's layout
// (ui.layout) over the scene's upper left corner, the scene keeping the band under it; the
// slide's problems over the scene until dismissed; the speaker notes' window where open.
void slideCard(Model& model, UiState& ui, ScreenRect area);

// the slide's speaker notes on stdout (a terminal on the lecturer's screen), where it has any
void printNotes(const SlideShow& show);

// the problems shown over the current slide (a bordered box mid-scene) with a Dismiss button
void problemsBox(SlideShow& show, ScreenRect area);

// the speaker notes' window (movable; N shows and hides it): the slide, its notes, the next
void notesWindow(const SlideShow& show, bool& open);

// the speaker notes filling their own window (platform/notes_window.hpp): the slide, its
// notes, the next slide's title
void notesContents(const SlideShow& show);

// the whole window black while the show is blanked (B)
void blankIfAsked(const SlideShow& show);

// the Lecture panel in the left window: the slides and the paper's figures
void lecturePanel(Model& model, UiState& ui);

}  // namespace convexloc::viewer
