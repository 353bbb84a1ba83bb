// convexloc-viewer — a lecture: a plain-text list of slides, each a set of the viewer's own
// options. A line `slide TITLE` starts a slide; each line inside is `key value...`, where
// the keys are the viewer's long options without their dashes (method, probe, figure, ...)
// and `caption` takes the rest of the line. Lines starting with `#` and blank lines are
// skipped. Every slide is checked by the command line's own parser, so every option the
// viewer has is a slide key, and a problem is reported as `FILE:LINE: problem`. GL-free.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "logic/app/options.hpp"

namespace convexloc::viewer {

class Model;

// one slide: its title, its options and its caption
struct Slide {
  std::string title;
  std::size_t line = 0;           // the line of `slide TITLE`
  std::vector<std::string> args;  // the slide's keys as a command line
  std::vector<std::string> keys;  // the keys the slide itself gives, in order
  std::string caption;            // free text shown under the title
  Options options;                // args, parsed
  // whether the slide itself gives `key`
  bool gives(std::string_view key) const;
};

// a lecture file, read
struct Lecture {
  std::string path;  // where it was read from ("" for a figure or a test text)
  std::vector<Slide> slides;
};

// a lecture, or why it cannot be used ("FILE:LINE: problem")
struct ParsedLecture {
  Lecture lecture;
  std::string error;  // empty when fine
};

// Reads a lecture from `text`; `source` names it in errors, `baseDir` is where relative
// shape paths are looked for first (the lecture file's directory).
ParsedLecture parseLecture(std::string_view text, const std::string& source,
                           const std::string& baseDir = "");
// reads the lecture file at `path`
ParsedLecture loadLecture(const std::string& path);

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
  bool active() const { return !lecture.slides.empty(); }
  const Slide& slide() const { return lecture.slides[current]; }
  // Shows slide k, clamped to the lecture (nothing without slides); the first problem.
  std::string go(Model& model, std::ptrdiff_t k);
};

// Shows slide k: the scene reset to the viewer's defaults, then the slide's options applied
// as the command line's are. Returns an empty string, or the first problem.
std::string showSlide(Model& model, const Lecture& lecture, std::size_t k);

}  // namespace convexloc::viewer
