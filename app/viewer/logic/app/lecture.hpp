// convexloc-viewer — a lecture: a plain-text list of slides, each a set of the viewer's own
// options. A line `slide TITLE` starts a slide; each line inside is `key value...`, where
// the keys are the viewer's long options without their dashes (method, probe, figure, ...);
// `caption` takes the rest of the line, `notes` the rest of the line as a line of the
// speaker's notes (it may repeat). Lines starting with `#` and blank lines are skipped.
// Every slide is checked by the command line's own parser, so every option the viewer has
// is a slide key. Every problem is kept, as `FILE:LINE: problem`, with the slide it spoils:
// the other slides still play. GL-free.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "logic/app/actions.hpp"
#include "logic/app/options.hpp"

namespace convexloc::viewer {

class Model;

// one slide: its title, its options, its caption, its notes and its problems
struct Slide {
  std::string title;
  std::size_t line = 0;               // the line of `slide TITLE`
  std::vector<std::string> args;      // the slide's keys as a command line
  std::vector<std::string> keys;      // the keys the slide itself gives, in order
  std::vector<std::size_t> keyLines;  // the line of each key
  std::string caption;                // free text shown under the title
  std::vector<std::string> notes;     // the speaker's notes, a line each
  std::vector<std::string> problems;  // "FILE:LINE: problem", in line order
  Options options;                    // args (the good lines), parsed
  // whether the slide itself gives `key`
  bool gives(std::string_view key) const;
  // whether the slide can be shown as written
  bool good() const { return problems.empty(); }
};

// a lecture file, read
struct Lecture {
  std::string path;  // where it was read from ("" for a figure or a test text)
  std::vector<Slide> slides;
  // problems of no slide: the file unreadable, no slides, a key before the first slide
  std::vector<std::string> problems;
  // every problem: the lecture's own, then each slide's, in line order
  std::vector<std::string> allProblems() const;
  // the slides that can be shown as written
  std::size_t goodSlides() const;
};

// a lecture as read: its slides, and every problem found (empty when it is clean)
struct ParsedLecture {
  Lecture lecture;
  std::vector<std::string> problems;  // lecture.allProblems()
  bool clean() const { return problems.empty(); }
};

// Reads a lecture from `text`; `source` names it in errors, `baseDir` is where relative
// shape paths are looked for first (the lecture file's directory).
ParsedLecture parseLecture(std::string_view text, const std::string& source,
                           const std::string& baseDir = "");
// reads the lecture file at `path`
ParsedLecture loadLecture(const std::string& path);

// Shows every good slide once on `model`, as the viewer would (without measuring Why O(1)),
// and adds what the scene refuses (a shape file that is not a polygon, a preset, a
// generator) to the slide's problems at the line of the key it comes from; `parsed`'s
// problems become the lecture's again. GL-free: --check, --export and the viewer's start
// run it so that every problem is known before the first slide.
void checkSlides(ParsedLecture& parsed, Model& model);

// --check's report: every problem a line, then "FILE: N slides, K with problems" (or
// "FILE: OK, N slides, M with notes" when clean); the exit code: 0 when clean, else 1
int checkReport(const ParsedLecture& parsed, std::string& out);

// --notes's text: for each slide "N. TITLE", then its notes indented, a blank line between
std::string notesText(const Lecture& lecture);

// --check FILE (the report, every good slide shown on a scratch model) or --notes FILE (the
// notes; the problems in `err`): stdout's text in `out`, the exit code (0 when clean, else 1)
int lectureReport(const Options& options, std::string& out, std::string& err);

// the one-slide lecture of the paper's figure n, with `options` (the command line) as its
// options
Lecture figureLecture(int n, const Options& options);

// The options a slide is shown with: its own, with the viewer's current theme, text size
// and panels kept where the slide gives none of its own; a slide giving `show-ui` shows
// the panels (and leaves presentation mode).
Options slideOptions(const Slide& slide, const Model& model);

// a lecture being shown and its current slide
struct SlideShow {
  // The look a slide after the first found before it set its own theme, text size or
  // panels, given back when the show leaves it: the first slide's look is the lecture's.
  struct Look {
    Theme theme = Theme::Dark;
    float fontScale = 1.0f;
    bool showUi = false;
    bool present = false;
  };
  Lecture lecture;
  std::size_t current = 0;
  std::optional<Look> lookBefore;
  // the first slide's look applied: a show that opens at a later slide (--slide K, a link to
  // a slide, an export whose first slide is bad) takes it first
  bool lookTaken = false;
  // the slides whose problems the lecturer dismissed (index; the lecture's own: slides' size)
  std::vector<bool> dismissed;
  bool blank = false;  // the screen blanked (B), as PowerPoint does
  bool active() const { return !lecture.slides.empty(); }
  const Slide& slide() const { return lecture.slides[current]; }
  // Shows slide k, clamped to the lecture (nothing without slides); the first problem.
  std::string go(Model& model, std::ptrdiff_t k);
  // the slide a slide key asks for from the current one: next, previous, first, last
  std::size_t target(ActionKind kind) const;
  // The problems to show over the current slide (its own, and on the first slide the
  // lecture's), until dismissed; empty when there are none or they were dismissed.
  std::vector<std::string> shownProblems() const;
  // the current slide's problems put away until the lecture is opened again
  void dismiss();
  // the first good slide from k on (k itself when it is good); the slides' count when none
  std::size_t goodFrom(std::size_t k) const;
};

// Shows slide k: the scene reset to the viewer's defaults, then the slide's options applied
// as the command line's are. Returns an empty string, or the first problem.
std::string showSlide(Model& model, const Lecture& lecture, std::size_t k);

}  // namespace convexloc::viewer
