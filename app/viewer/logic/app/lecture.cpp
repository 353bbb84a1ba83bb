// convexloc-viewer — lecture files: read line by line, each slide checked by the command
// line's parser.
#include "logic/app/lecture.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "logic/app/model.hpp"
#include "logic/app/option_table.hpp"
#include "logic/app/option_values.hpp"
#include "logic/teach/figures.hpp"

namespace convexloc::viewer {
namespace {

// the keys that set a slide's look: the first slide's are the lecture's, a later one's
// its own
// a slide's text scale unless the lecture gives its own (32 px text on the 1080p page, as the
// paper's figures have)
constexpr float kSlideFontScale = 2.0f;
constexpr std::string_view kLookKeys[] = {"theme", "font-scale", "hide-ui", "show-ui", "present"};

// the line without the blanks around it
std::string_view trimmed(std::string_view s) {
  const std::size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string_view::npos) return {};
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

// A line's words: split at blanks, a double-quoted word may hold blanks, a word starting
// with `#` starts a comment to the end of the line. False (and `error`) on a quote that is
// not closed.
bool splitWords(std::string_view s, std::vector<std::string>& words, std::string& error) {
  std::size_t i = 0;
  while (i < s.size()) {
    if (s[i] == ' ' || s[i] == '\t') {
      ++i;
      continue;
    }
    if (s[i] == '#') break;
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

// A file a slide names (a shape, a Why O(1) record): relative to the lecture file where it
// is there, else as written (the working directory); `problem` names every place looked at
// when it is in neither.
std::string filePath(const std::string& path, const std::string& baseDir, std::string& problem) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::exists(path, ec) && (baseDir.empty() || fs::path(path).is_absolute())) return path;
  const fs::path near = fs::path(baseDir) / path;
  if (!baseDir.empty() && !fs::path(path).is_absolute() && fs::exists(near, ec))
    return near.lexically_normal().string();
  if (fs::exists(path, ec)) return path;
  const std::string here = fs::absolute(path, ec).lexically_normal().string();
  problem = "file '" + path + "' not found (looked for ";
  if (!baseDir.empty() && !fs::path(path).is_absolute())
    problem += fs::absolute(near, ec).lexically_normal().string() + " and ";
  problem += here + ")";
  return path;
}

// the keys a lecture line may start with: every option a slide may set, and the lecture's own
std::vector<std::string_view> lectureKeys() {
  std::vector<std::string_view> keys = {"slide", "caption", "notes", "shape"};
  for (const OptionSpec& s : optionTable()) {
    std::string_view names = s.names;
    names = names.substr(names.rfind(',') == std::string_view::npos ? 0 : names.rfind(',') + 1);
    if (!s.run && names.starts_with("--")) keys.push_back(names.substr(2));
  }
  return keys;
}

// the words of a key's line past the values its option takes, blank-separated
std::string leftOver(const std::string& key, const std::vector<std::string>& words) {
  std::size_t takes = 0;
  for (const OptionSpec& s : optionTable())
    if (std::string_view(s.names).ends_with("--" + key)) takes = static_cast<std::size_t>(s.count);
  std::string rest;
  for (std::size_t i = 1 + takes; i < words.size(); ++i)
    rest += (rest.empty() ? "" : " ") + words[i];
  return rest;
}

// "unknown key 'methd' (did you mean method?)"
std::string unknownKey(const std::string& key) {
  const std::vector<std::string_view> keys = lectureKeys();
  const std::string near = nearestWord(key, keys);
  return "unknown key '" + key + "'" + (near.empty() ? "" : " (did you mean " + near + "?)");
}

// Reads the lecture line by line. A problem is kept with the slide it spoils (or the
// lecture, before the first slide) and the reading goes on: the bad line is left out.
class LectureReader {
 public:
  LectureReader(std::string source, std::string baseDir)
      : source_(std::move(source)), baseDir_(std::move(baseDir)) {}

  // one line of the file
  void line(std::string_view raw, std::size_t number) {
    line_ = number;
    const std::string_view s = trimmed(raw);
    if (s.empty() || s.front() == '#') return;
    const std::size_t blank = std::min(s.find_first_of(" \t"), s.size());
    const std::string key(s.substr(0, blank));
    const std::string_view rest = s.substr(blank);
    if (key == "slide") return startSlide(rest);
    if (out_.slides.empty())
      return fail("'" + key + "' comes before any slide (start one with: slide TITLE)");
    slideKey(key, rest);
  }

  // the last slide checked as a whole; the lecture with every problem
  ParsedLecture finish() {
    if (!out_.slides.empty()) finishSlide();
    if (out_.slides.empty()) fail("no slides (start one with: slide TITLE)");
    ParsedLecture r;
    r.lecture = std::move(out_);
    r.problems = r.lecture.allProblems();
    return r;
  }

 private:
  // the problem at the current line, kept with the slide being read (the lecture's before one)
  void fail(const std::string& problem) {
    const std::string text = located(source_, line_, problem);
    if (out_.slides.empty())
      out_.problems.push_back(text);
    else
      out_.slides.back().problems.push_back(text);
  }

  void startSlide(std::string_view title) {
    if (!out_.slides.empty()) finishSlide();
    Slide s;
    s.title = std::string(trimmed(title));
    s.line = line_;
    if (s.title.empty()) s.title = "Slide " + std::to_string(out_.slides.size() + 1);
    out_.slides.push_back(std::move(s));
  }

  // the whole slide through the parser: options that exclude each other
  void finishSlide() {
    Slide& s = out_.slides.back();
    const std::vector<std::string_view> args(s.args.begin(), s.args.end());
    ParsedOptions p = parseOptions(args);
    s.options = std::move(p.options);
    if (!p.error.empty()) {
      const std::size_t at = line_;
      line_ = s.line;
      fail("slide '" + s.title + "': " + inLectureWords(p.error));
      line_ = at;
    }
    // a figure's slide without a caption of its own says what the figure shows
    if (s.caption.empty() && s.options.figure) s.caption = figure(*s.options.figure).caption;
  }

  void slideKey(const std::string& key, std::string_view rest) {
    Slide& slide = out_.slides.back();
    if (key == "notes") return notesLine(slide, rest);
    if (setsTheRun(key))
      return fail("'" + key + "' is not a slide key (it sets the window or the run)");
    std::vector<std::string> words{"--" + key};
    std::string problem;
    if (key == "caption") {
      std::string caption;
      if (!captionText(rest, caption, problem)) return fail(problem);
      slide.caption = caption;
      words.push_back(caption);
    } else if (!splitWords(rest, words, problem)) {
      return fail(problem);
    }
    // a file is looked for beside the lecture first; the shape is the command line's SHAPE
    if ((key == "shape" || key == "why-from") && words.size() == 2) {
      words[1] = filePath(words[1], baseDir_, problem);
      if (!problem.empty()) return fail(key + ": " + problem);
      if (key == "shape") words.erase(words.begin());
    }
    // `why PAGE` opens Why O(1) on that page (`why` alone: the scene's)
    if (key == "why" && words.size() > 1) {
      if (words.size() > 2)
        return fail("'why' takes one page, 2d or 3d ('" + leftOver("why-page", words) +
                    "' is left over)");
      words[0] = "--why-page";
    }
    if (!checkLine(key, words)) return;
    slide.keys.push_back(key);
    slide.keyLines.push_back(line_);
    slide.args.insert(slide.args.end(), words.begin(), words.end());
  }

  // a line of the speaker's notes (an empty `notes` line is an empty line of them)
  void notesLine(Slide& slide, std::string_view rest) {
    std::string text, problem;
    rest = trimmed(rest);
    if (!rest.empty() && !captionText(rest, text, problem)) return fail(problem);
    slide.notes.push_back(text);
  }

  // the line alone through the parser: an unknown key, a bad or missing value, extra values
  bool checkLine(const std::string& key, const std::vector<std::string>& words) {
    const std::vector<std::string_view> args(words.begin(), words.end());
    const ParsedOptions p = parseOptions(args);
    if (p.error.starts_with("unknown option")) {
      fail(unknownKey(key));
      return false;
    }
    // a value the option does not take reads as a shape file (two as two shape files)
    if (key != "shape" && (p.error.starts_with("more than one shape given") ||
                           (p.error.empty() && !p.options.shape.empty()))) {
      fail("'" + key + "' was given more values than it takes ('" + leftOver(key, words) +
           "' is left over)");
      return false;
    }
    if (!p.error.empty()) {
      fail(inLectureWords(p.error));
      return false;
    }
    return true;
  }

  std::string source_, baseDir_;
  Lecture out_;
  std::size_t line_ = 0;
};

// A lecture looks like slides unless its first slide says otherwise: the light theme, text
// of 2.2% of the page or more (font-scale 2: 32 px on the 1080p page), no panels. The look
// is the first slide's, so it becomes the whole lecture's.
void giveTheSlideLook(Slide& first) {
  const auto give = [&first](std::string_view key) {
    first.keys.emplace_back(key);
    first.keyLines.push_back(first.line);
  };
  if (!first.gives("theme")) {
    first.options.theme = Theme::Light;
    give("theme");
  }
  if (!first.gives("font-scale")) {
    first.options.fontScale = kSlideFontScale;
    give("font-scale");
  }
  if (!first.gives("hide-ui") && !first.gives("show-ui") && !first.gives("present")) {
    first.options.hideUi = true;
    give("hide-ui");
  }
}

}  // namespace

bool Slide::gives(std::string_view key) const {
  const auto has = [this](std::string_view k) {
    return std::find(keys.begin(), keys.end(), k) != keys.end();
  };
  // a figure brings its own look: the theme, the text size, the panels hidden
  const bool look = key == "theme" || key == "font-scale" || key == "hide-ui";
  return has(key) || (look && has("figure"));
}

std::vector<std::string> Lecture::allProblems() const {
  std::vector<std::string> all = problems;
  for (const Slide& s : slides) all.insert(all.end(), s.problems.begin(), s.problems.end());
  return all;
}

std::size_t Lecture::goodSlides() const {
  return static_cast<std::size_t>(
      std::count_if(slides.begin(), slides.end(), [](const Slide& s) { return s.good(); }));
}

ParsedLecture parseLecture(std::string_view text, const std::string& source,
                           const std::string& baseDir) {
  LectureReader reader(source, baseDir);
  std::size_t number = 0;
  while (!text.empty()) {
    const std::size_t nl = std::min(text.find('\n'), text.size());
    reader.line(text.substr(0, nl), ++number);
    text.remove_prefix(std::min(nl + 1, text.size()));
  }
  ParsedLecture r = reader.finish();
  r.lecture.path = source;
  if (!r.lecture.slides.empty()) giveTheSlideLook(r.lecture.slides.front());
  return r;
}

ParsedLecture loadLecture(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    ParsedLecture r;
    std::error_code ec;
    r.lecture.path = path;
    r.lecture.problems.push_back(path + ": cannot be read (looked for " +
                                 std::filesystem::absolute(path, ec).lexically_normal().string() +
                                 ")");
    r.problems = r.lecture.problems;
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
  if (!lookTaken && current > 0) showSlide(model, lecture, 0);  // the lecture's look
  lookTaken = true;
  if (current > 0 && std::any_of(std::begin(kLookKeys), std::end(kLookKeys),
                                 [this](std::string_view key) { return slide().gives(key); }))
    lookBefore = Look{model.settings.theme, model.settings.fontScale, model.settings.showUi,
                      model.settings.present};
  return showSlide(model, lecture, current);
}

std::size_t SlideShow::target(ActionKind kind) const {
  const std::size_t last = lecture.slides.empty() ? 0 : lecture.slides.size() - 1;
  switch (kind) {
    case ActionKind::NextSlide: return std::min(current + 1, last);
    case ActionKind::PreviousSlide: return current == 0 ? 0 : current - 1;
    case ActionKind::FirstSlide: return 0;
    case ActionKind::LastSlide: return last;
    default: return current;
  }
}

std::vector<std::string> SlideShow::shownProblems() const {
  const std::size_t own = lecture.slides.size();
  const auto put = [this](std::size_t k) { return k < dismissed.size() && dismissed[k]; };
  std::vector<std::string> shown;
  if ((current == 0 || !active()) && !put(own)) shown = lecture.problems;
  if (active() && !put(current))
    shown.insert(shown.end(), slide().problems.begin(), slide().problems.end());
  return shown;
}

void SlideShow::dismiss() {
  dismissed.resize(lecture.slides.size() + 1, false);
  if (current == 0 || !active()) dismissed[lecture.slides.size()] = true;
  if (active()) dismissed[current] = true;
}

std::size_t SlideShow::goodFrom(std::size_t k) const {
  while (k < lecture.slides.size() && !lecture.slides[k].good()) ++k;
  return k;
}

}  // namespace convexloc::viewer
