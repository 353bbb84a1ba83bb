// convexloc-viewer — lecture files: read line by line, each slide checked by the command
// line's parser.
#include "logic/app/lecture.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "logic/app/model.hpp"
#include "logic/teach/figures.hpp"

namespace convexloc::viewer {
namespace {

// the keys that set a slide's look: the first slide's are the lecture's, a later one's
// its own
constexpr std::string_view kLookKeys[] = {"theme", "font-scale", "hide-ui", "show-ui", "present"};

// the line without the blanks around it
std::string_view trimmed(std::string_view s) {
  const std::size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string_view::npos) return {};
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

// A line's words: split at blanks, a double-quoted word may hold blanks. False (and
// `error`) on a quote that is not closed.
bool splitWords(std::string_view s, std::vector<std::string>& words, std::string& error) {
  std::size_t i = 0;
  while (i < s.size()) {
    if (s[i] == ' ' || s[i] == '\t') {
      ++i;
      continue;
    }
    if (s[i] == '"') {
      const std::size_t close = s.find('"', i + 1);
      if (close == std::string_view::npos) {
        error = "unterminated quote: a \" opened here is not closed on this line";
        return false;
      }
      words.emplace_back(s.substr(i + 1, close - i - 1));
      i = close + 1;
      continue;
    }
    const std::size_t end = std::min(s.find_first_of(" \t", i), s.size());
    words.emplace_back(s.substr(i, end - i));
    i = end;
  }
  return true;
}

// the rest of a caption line, without the quotes around it if it has them
bool captionText(std::string_view rest, std::string& text, std::string& error) {
  rest = trimmed(rest);
  if (rest.empty()) {
    error = "caption needs text";
    return false;
  }
  if (rest.front() == '"') {
    if (rest.size() < 2 || rest.back() != '"') {
      error = "unterminated quote: the caption's \" is not closed on this line";
      return false;
    }
    rest = rest.substr(1, rest.size() - 2);
  }
  text = std::string(rest);
  return true;
}

// the parser's message in the lecture's words: `key` rather than `--key`
std::string inLectureWords(std::string message) {
  for (std::size_t at = message.find("--"); at != std::string::npos; at = message.find("--", at))
    message.erase(at, 2);
  return message;
}

// a shape path relative to the lecture file where it is there, else as written
std::string shapePath(const std::string& path, const std::string& baseDir) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (baseDir.empty() || fs::path(path).is_absolute()) return path;
  const fs::path near = fs::path(baseDir) / path;
  return fs::exists(near, ec) ? near.lexically_normal().string() : path;
}

// Reads the lecture line by line; `fail` records the first problem with its line.
class LectureReader {
 public:
  LectureReader(std::string source, std::string baseDir)
      : source_(std::move(source)), baseDir_(std::move(baseDir)) {}

  // one line of the file; false once a problem is found
  bool line(std::string_view raw, std::size_t number) {
    line_ = number;
    const std::string_view s = trimmed(raw);
    if (s.empty() || s.front() == '#') return true;
    const std::size_t blank = std::min(s.find_first_of(" \t"), s.size());
    const std::string key(s.substr(0, blank));
    const std::string_view rest = s.substr(blank);
    if (key == "slide") return startSlide(rest);
    if (out_.slides.empty())
      return fail("'" + key + "' comes before any slide (start one with: slide TITLE)");
    return slideKey(key, rest);
  }

  // the last slide checked as a whole; the lecture, or the problem
  ParsedLecture finish() {
    if (error_.empty() && !out_.slides.empty()) finishSlide();
    if (error_.empty() && out_.slides.empty()) fail("no slides (start one with: slide TITLE)");
    ParsedLecture r;
    r.error = error_;
    if (error_.empty()) r.lecture = std::move(out_);
    return r;
  }

 private:
  bool fail(const std::string& problem) {
    if (error_.empty()) error_ = located(source_, line_, problem);
    return false;
  }

  bool startSlide(std::string_view title) {
    if (!out_.slides.empty() && !finishSlide()) return false;
    Slide s;
    s.title = std::string(trimmed(title));
    s.line = line_;
    if (s.title.empty()) s.title = "Slide " + std::to_string(out_.slides.size() + 1);
    out_.slides.push_back(std::move(s));
    return true;
  }

  // the whole slide through the parser: options that exclude each other
  bool finishSlide() {
    Slide& s = out_.slides.back();
    const std::vector<std::string_view> args(s.args.begin(), s.args.end());
    ParsedOptions p = parseOptions(args);
    if (!p.error.empty()) {
      line_ = s.line;
      return fail("slide '" + s.title + "': " + inLectureWords(p.error));
    }
    s.options = std::move(p.options);
    // a figure's slide without a caption of its own says what the figure shows
    if (s.caption.empty() && s.options.figure) s.caption = figure(*s.options.figure).caption;
    return true;
  }

  bool slideKey(const std::string& key, std::string_view rest) {
    if (setsTheRun(key))
      return fail("'" + key + "' is not a slide key (it sets the window or the run)");
    Slide& slide = out_.slides.back();
    std::vector<std::string> words{"--" + key};
    std::string problem;
    if (key == "caption") {
      if (!captionText(rest, slide.caption, problem)) return fail(problem);
      words.push_back(slide.caption);
      // a viewer without --caption keeps the caption in the slide alone
      const std::vector<std::string_view> probe(words.begin(), words.end());
      if (!parseOptions(probe).error.empty()) return true;
    } else if (!splitWords(rest, words, problem)) {
      return fail(problem);
    }
    if (key == "shape" && words.size() == 2) words = {shapePath(words[1], baseDir_)};
    if (!checkLine(key, words)) return false;
    slide.keys.push_back(key);
    slide.args.insert(slide.args.end(), words.begin(), words.end());
    return true;
  }

  // the line alone through the parser: an unknown key, a bad or missing value, extra values
  bool checkLine(const std::string& key, const std::vector<std::string>& words) {
    const std::vector<std::string_view> args(words.begin(), words.end());
    const ParsedOptions p = parseOptions(args);
    if (p.error.starts_with("unknown option")) return fail("unknown key '" + key + "'");
    if (!p.error.empty()) return fail(inLectureWords(p.error));
    if (key != "shape" && !p.options.shape.empty())
      return fail("'" + key + "' was given more values than it takes ('" + p.options.shape +
                  "' is left over)");
    return true;
  }

  std::string source_, baseDir_;
  Lecture out_;
  std::size_t line_ = 0;
  std::string error_;
};

}  // namespace

bool Slide::gives(std::string_view key) const {
  const auto has = [this](std::string_view k) {
    return std::find(keys.begin(), keys.end(), k) != keys.end();
  };
  // a figure brings its own look: the theme, the text size, the panels hidden
  const bool look = key == "theme" || key == "font-scale" || key == "hide-ui";
  return has(key) || (look && has("figure"));
}

ParsedLecture parseLecture(std::string_view text, const std::string& source,
                           const std::string& baseDir) {
  LectureReader reader(source, baseDir);
  std::size_t number = 0;
  while (!text.empty()) {
    const std::size_t nl = std::min(text.find('\n'), text.size());
    if (!reader.line(text.substr(0, nl), ++number)) break;
    text.remove_prefix(std::min(nl + 1, text.size()));
  }
  ParsedLecture r = reader.finish();
  r.lecture.path = source;
  return r;
}

ParsedLecture loadLecture(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    ParsedLecture r;
    r.error = path + ": cannot be read";
    return r;
  }
  std::ostringstream text;
  text << in.rdbuf();
  return parseLecture(text.str(), path, std::filesystem::path(path).parent_path().string());
}

Lecture figureLecture(int n, const Options& options) {
  Slide s;
  s.title = std::string(figure(n).title);
  s.caption = std::string(figure(n).caption);
  s.line = 1;
  s.options = options;
  s.keys = {"figure", "theme", "font-scale", "hide-ui"};
  Lecture l;
  l.slides.push_back(std::move(s));
  return l;
}

Options slideOptions(const Slide& slide, const Model& model) {
  Options o = slide.options;
  if (!slide.gives("theme")) o.theme = model.settings.theme;
  if (!slide.gives("font-scale")) o.fontScale = model.settings.fontScale;
  if (!slide.gives("hide-ui")) o.hideUi = !model.settings.showUi;
  if (!slide.gives("present")) o.present = model.settings.present;
  // a slide with a table to read shows the panels, whatever the lecture hides
  if (slide.gives("show-ui")) {
    o.hideUi = false;
    o.present = false;
  }
  return o;
}

std::string showSlide(Model& model, const Lecture& lecture, std::size_t k) {
  if (k >= lecture.slides.size()) return "no slide " + std::to_string(k + 1);
  const Options o = slideOptions(lecture.slides[k], model);
  model.reset();
  return model.apply(o);
}

std::string SlideShow::go(Model& model, std::ptrdiff_t k) {
  if (!active()) return {};
  // the look as it was before a slide that set its own
  if (lookBefore) {
    model.settings.theme = lookBefore->theme;
    model.settings.fontScale = lookBefore->fontScale;
    model.settings.showUi = lookBefore->showUi;
    model.settings.present = lookBefore->present;
    lookBefore.reset();
  }
  const std::ptrdiff_t last = static_cast<std::ptrdiff_t>(lecture.slides.size()) - 1;
  current = static_cast<std::size_t>(std::clamp<std::ptrdiff_t>(k, 0, last));
  if (current > 0 && std::any_of(std::begin(kLookKeys), std::end(kLookKeys),
                                 [this](std::string_view key) { return slide().gives(key); }))
    lookBefore = Look{model.settings.theme, model.settings.fontScale, model.settings.showUi,
                      model.settings.present};
  return showSlide(model, lecture, current);
}

}  // namespace convexloc::viewer
