// convexloc-viewer — a lecture checked whole: every good slide shown once on a scratch
// model, --check's report and --notes's text.
#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "convexloc/error.hpp"
#include "logic/app/lecture.hpp"
#include "logic/app/model.hpp"

namespace convexloc::viewer {
namespace {

// The line of the key a scene's problem comes from: the key the model names, else the slide's
// own line (a key the slide does not give, such as a shape a preset chose).
std::size_t lineOfKey(const Slide& s, std::string_view key) {
  const auto at = std::find(s.keys.begin(), s.keys.end(), key);
  return at == s.keys.end() ? s.line : s.keyLines[static_cast<std::size_t>(at - s.keys.begin())];
}

}  // namespace

void checkSlides(ParsedLecture& parsed, Model& model) {
  Lecture& lecture = parsed.lecture;
  for (Slide& s : lecture.slides) {
    if (!s.good()) continue;
    Options o = s.options;
    o.why = false;  // what is measured cannot be wrong; a recorded file can
    model.reset();
    model.apply(o);
    std::vector<std::pair<std::size_t, std::string>> found;
    for (const ApplyProblem& p : model.applyProblems())
      found.emplace_back(lineOfKey(s, p.key), "slide '" + s.title + "': " + p.text);
    std::stable_sort(found.begin(), found.end(),
                     [](const auto& a, const auto& b) { return a.first < b.first; });
    for (const auto& [line, text] : found) s.problems.push_back(located(lecture.path, line, text));
  }
  model.reset();
  parsed.problems = lecture.allProblems();
}

int checkReport(const ParsedLecture& parsed, std::string& out) {
  const Lecture& l = parsed.lecture;
  for (const std::string& p : parsed.problems) out += p + "\n";
  const std::size_t slides = l.slides.size();
  const std::string count = std::to_string(slides) + (slides == 1 ? " slide" : " slides");
  if (parsed.clean()) {
    const auto withNotes = std::count_if(l.slides.begin(), l.slides.end(),
                                         [](const Slide& s) { return !s.notes.empty(); });
    out += l.path + ": OK, " + count + ", " + std::to_string(withNotes) + " with notes\n";
    return 0;
  }
  const std::size_t bad = slides - l.goodSlides();
  const std::size_t n = parsed.problems.size();
  out += l.path + ": " + std::to_string(n) + (n == 1 ? " problem" : " problems") + "; " + count +
         ", " + std::to_string(bad) + " of them not shown as written\n";
  return 1;
}

std::string notesText(const Lecture& lecture) {
  std::string out;
  for (std::size_t k = 0; k < lecture.slides.size(); ++k) {
    const Slide& s = lecture.slides[k];
    if (k > 0) out += "\n";
    out += std::to_string(k + 1) + ". " + s.title + "\n";
    for (const std::string& line : s.notes) out += line.empty() ? "\n" : "   " + line + "\n";
  }
  return out;
}

int lectureReport(const Options& options, std::string& out, std::string& err) {
  if (!options.checkFile.empty()) {
    ParsedLecture parsed = loadLecture(options.checkFile);
    Model scratch;
    checkSlides(parsed, scratch);
    return checkReport(parsed, out);
  }
  const ParsedLecture parsed = loadLecture(options.notesFile);
  out = notesText(parsed.lecture);
  for (const std::string& p : parsed.problems) err += p + "\n";
  return parsed.clean() ? 0 : 1;
}

}  // namespace convexloc::viewer
