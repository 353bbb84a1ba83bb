// convexloc-viewer — the Steps window's layout: its width, its heading, the steps and the
// pseudo-code broken into lines, and where each goes.
#include <algorithm>
#include <cmath>

#include "logic/teach/slide_layout.hpp"

namespace convexloc::viewer {
namespace {

// "3. edge 2: orient2d = +1 (inner side)"
std::string stepText(const StepModel& s, std::size_t i) {
  return std::to_string(i + 1) + ". " + s.steps[i].caption;
}

// the room the window may take: at most half the area, clear of its middle where the split
// view divides it (and 46 em), at least 16 em where the area has them
double stepsRoom(ScreenRect area, const SlideMetrics& m) {
  const double half = area.size().x * 0.5 - 1.25 * m.font;
  return std::max(std::min(half, m.font * 46.0), std::min(m.font * 16.0, half * 1.6));
}

// the width the longest lines need unbroken (the steps, with the code beside them when
// `withCode`), at least 24 em
double neededWidth(const StepModel& s, bool withCode, const SlideMetrics& m) {
  double steps = 0.0, code = 0.0;
  for (std::size_t i = 0; i < s.steps.size(); ++i)
    steps = std::max(steps, m.widthAt(stepText(s, i), 1.0));
  for (const std::string& c : s.code) code = std::max(code, m.widthAt("> " + c, 1.0));
  const double pad = 2.0 * m.padding + 2.0 * m.font;
  return std::max(m.font * 24.0, (withCode ? steps + code + 2.0 * m.font : steps) + pad);
}

// every step broken to `width`, continued lines indented
std::vector<StepLines> allSteps(const StepModel& s, double width, const SlideMetrics& m) {
  std::vector<StepLines> out;
  for (std::size_t i = 0; i < s.steps.size(); ++i)
    out.push_back({i, breakAtSpaces(stepText(s, i), width, m.measure, "    ")});
  return out;
}

// the steps shown: all where their lines fit in `most`, else a run around `current` that does
std::vector<StepLines> aroundCurrent(const std::vector<StepLines>& all, int current,
                                     std::size_t most) {
  std::size_t total = 0;
  for (const StepLines& s : all) total += s.lines.size();
  if (total <= most || all.empty()) return all;
  std::size_t lo =
      static_cast<std::size_t>(std::clamp(current, 0, static_cast<int>(all.size()) - 1));
  std::size_t hi = lo, lines = all[lo].lines.size();
  for (bool grew = true; grew;) {
    grew = false;
    if (hi + 1 < all.size() && lines + all[hi + 1].lines.size() <= most) {
      lines += all[++hi].lines.size();
      grew = true;
    }
    if (lo > 0 && lines + all[lo - 1].lines.size() <= most) {
      lines += all[--lo].lines.size();
      grew = true;
    }
  }
  return {all.begin() + static_cast<std::ptrdiff_t>(lo),
          all.begin() + static_cast<std::ptrdiff_t>(hi) + 1};
}

// "steps 3-8 of 12" ("step 4 of 12" for one)
std::string shownRange(const std::vector<StepLines>& shown, std::size_t total) {
  const std::size_t first = shown.front().step + 1, last = shown.back().step + 1;
  const std::string of = " of " + std::to_string(total);
  return first == last ? "step " + std::to_string(first) + of
                       : "steps " + std::to_string(first) + "-" + std::to_string(last) + of;
}

// the pseudo-code's lines: all (`whole`) or the current step's alone, "> " on the current
void codeLines(const StepsContent& s, bool whole, double width, const SlideMetrics& m,
               StepsLayout& l) {
  const int line = s.step >= 0 ? s.model.steps[static_cast<std::size_t>(s.step)].line : -1;
  for (std::size_t i = 0; i < s.model.code.size(); ++i) {
    const bool on = static_cast<int>(i) == line;
    if (!whole && !on) continue;
    for (std::string& t :
         breakAtSpaces((on ? "> " : "  ") + s.model.code[i], width, m.measure, "    ")) {
      l.code.push_back(std::move(t));
      l.codeCurrent.push_back(on);
    }
  }
}

// the lines of `shown`
std::size_t lineCount(const std::vector<StepLines>& shown) {
  std::size_t n = 0;
  for (const StepLines& s : shown) n += s.lines.size();
  return n;
}

// the window with at most `most` lines of steps, its lower left corner at (x, bottom)
StepsLayout stepsWith(const StepsContent& s, const SlideMetrics& m, double room, double x,
                      double bottom, std::size_t most) {
  StepsLayout l;
  const bool wide = room > m.font * 40.0;
  l.wholeCode = s.codeWanted < 0 ? wide : s.codeWanted == 1;
  l.sideBySide = l.wholeCode && wide;
  const double w =
      std::min({room, neededWidth(s.model, l.sideBySide, m), l.sideBySide ? room : m.font * 34.0});
  const double inner = w - 2.0 * m.padding, gap = m.font;
  l.columnWidth = l.sideBySide ? 0.5 * (inner - gap) : inner;
  l.lineStep = m.font + m.spacing;
  const std::string heading =
      s.model.note.empty() ? s.model.title : s.model.title + "  (" + s.model.note + ")";
  l.heading = breakAtSpaces(heading, inner, m.measure, "  ");
  l.shown = aroundCurrent(allSteps(s.model, l.columnWidth, m), s.step, most);
  // a list cut to a window around the step shown says which steps it shows
  if (!l.shown.empty() && l.shown.size() < s.model.steps.size())
    l.heading.push_back(shownRange(l.shown, s.model.steps.size()));
  codeLines(s, l.wholeCode, l.columnWidth, m, l);
  // top to bottom from 0, moved into place at the end
  double y = m.padding + static_cast<double>(l.heading.size()) * l.lineStep;
  l.controlsTop = y;
  l.controls = s.controls;
  if (s.controls) y += 2.0 * (m.frame + m.spacing);
  y += m.spacing;  // the separator
  l.listTop = y;
  const double list = static_cast<double>(lineCount(l.shown)) * l.lineStep;
  const double code = static_cast<double>(l.code.size()) * l.lineStep;
  l.codeTop = l.sideBySide ? y : y + list + (l.code.empty() ? 0.0 : m.spacing);
  y = l.sideBySide ? y + std::max(list, code) : l.codeTop + code;
  const double height = y - m.spacing + m.padding;
  l.box.lo = {x, bottom - height};
  l.box.hi = {x + w, bottom};
  l.listLeft = l.box.lo.x + m.padding;
  l.codeLeft = l.sideBySide ? l.listLeft + l.columnWidth + gap : l.listLeft;
  for (double* at : {&l.controlsTop, &l.listTop, &l.codeTop}) *at += l.box.lo.y;
  l.headingTop = l.box.lo.y + m.padding;
  return l;
}

}  // namespace

Rgba stepColour(const Step& s, const Palette& pal, Rgba result) {
  switch (s.kind) {
    case TraceLine::Positive: return pal.positive;
    case TraceLine::Negative: return pal.negative;
    case TraceLine::Zero: return readableOn(pal.zero, pal.background, pal.text);
    case TraceLine::Result: return result;
    default: return pal.text;
  }
}

StepsLayout layoutSteps(const StepsContent& s, const SlideMetrics& m, ScreenRect area,
                        double bottom, double top) {
  const double room = stepsRoom(area, m), x = area.lo.x + m.margin;
  const double step = m.font + m.spacing;
  // about a quarter of the area's height (3 to 9 lines) for the list; fewer where the
  // window would reach over `top`
  auto most =
      static_cast<std::size_t>(std::clamp(std::floor(area.size().y * 0.25 / step), 3.0, 9.0));
  StepsLayout l = stepsWith(s, m, room, x, bottom, most);
  while (l.box.lo.y < top && most > 1) l = stepsWith(s, m, room, x, bottom, --most);
  return l;
}

}  // namespace convexloc::viewer

namespace convexloc::viewer {

StepsLayout layoutStepsInColumn(const StepsContent& s, const SlideMetrics& m, ScreenRect column) {
  const double step = m.font + m.spacing, room = column.size().x;
  // as many lines as the column holds (at least one step's)
  auto most = static_cast<std::size_t>(std::max(1.0, std::floor(column.size().y / step) - 3.0));
  StepsLayout l = stepsWith(s, m, room, column.lo.x, column.hi.y, most);
  while (l.box.lo.y < column.lo.y && most > 1)
    l = stepsWith(s, m, room, column.lo.x, column.hi.y, --most);
  // at the column's top, its width the column's
  const double dy = column.lo.y - l.box.lo.y;
  for (double* at :
       {&l.box.lo.y, &l.box.hi.y, &l.controlsTop, &l.listTop, &l.codeTop, &l.headingTop})
    *at += dy;
  l.box.hi.x = column.hi.x;
  return l;
}

}  // namespace convexloc::viewer
