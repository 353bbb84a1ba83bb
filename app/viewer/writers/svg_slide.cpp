// convexloc-viewer — a slide's boxes in the SVG.
#include "writers/svg_slide.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "logic/base/xml.hpp"

namespace convexloc::viewer::svg {

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.2f", std::abs(v) < 5e-3 ? 0.0 : v);
  return buf;
}

std::string rgb(Rgba c) {
  auto byte = [](float x) {
    return static_cast<int>(std::lround(std::clamp(x, 0.0f, 1.0f) * 255));
  };
  char buf[8];
  std::snprintf(buf, sizeof buf, "#%02x%02x%02x", byte(c.r), byte(c.g), byte(c.b));
  return buf;
}

std::string paint(const char* name, Rgba c) {
  std::string s = std::string(" ") + name + "=\"" + rgb(c) + "\"";
  if (c.a < 0.999f) s += std::string(" ") + name + "-opacity=\"" + num(c.a) + "\"";
  return s;
}

}  // namespace convexloc::viewer::svg

namespace convexloc::viewer {
namespace {

using svg::num;
using svg::paint;

// ImGui sizes a font by its height from descent to ascent, SVG by its em: DejaVu Sans is
// 1.164 em high, its ascent 0.928 em. The window's body text height in pixels:
double bodyPixels(const SvgScene& s) {
  return 1.164 * s.fontPixels;
}

// a rectangle, filled
std::string rectSvg(const ScreenRect& r, Rgba fill, double rounding = 0.0) {
  const glm::dvec2 size = r.size();
  return "<rect x=\"" + num(r.lo.x) + "\" y=\"" + num(r.lo.y) + "\" width=\"" + num(size.x) +
         "\" height=\"" + num(size.y) + "\"" +
         (rounding > 0.0 ? " rx=\"" + num(rounding) + "\"" : std::string()) + paint("fill", fill) +
         "/>";
}

// a line of text whose top is at `top` (as the window places it), `scale` times the body
std::string lineSvg(double x, double top, double scale, const std::string& text, Rgba colour,
                    const SvgScene& s, const char* cls = "line") {
  const double em = scale * s.fontPixels;
  const glm::dvec2 at = imguiBaseline({x, top}, s.fontPixels, scale);
  return "<text class=\"" + std::string(cls) + "\" x=\"" + num(at.x) + "\" y=\"" + num(at.y) +
         "\" font-size=\"" + num(em) + "\" xml:space=\"preserve\"" + paint("fill", colour) + ">" +
         wordsSvg(at.x, scale, text, s) + "</text>";
}

// a text box of the layout: its box, then its lines (the first `large` at its scale, the
// rest at the body size in `rest`)
void writeTextBox(const SvgScene& s, const char* id, const TextBox& t, std::size_t large, Rgba rest,
                  std::string& out) {
  if (t.lines.empty()) return;
  const double body = bodyPixels(s), pad = t.padding >= 0.0 ? t.padding : s.layoutPadding;
  out += "<g id=\"" + std::string(id) + "\" font-family=\"DejaVu Sans, Verdana, sans-serif\">\n  " +
         rectSvg(t.box, s.panel, s.rounding) + "\n";
  double top = t.box.lo.y + pad;
  for (std::size_t k = 0; k < t.lines.size(); ++k) {
    const double scale = k < large ? t.scale : t.restScale;
    out += "  " +
           lineSvg(t.box.lo.x + pad, top, scale, t.lines[k], k < large ? s.text : rest, s, id) +
           "\n";
    top += scale * body + s.layoutSpacing * t.restScale;
  }
  out += "</g>\n";
}

// a separator a spacing above `y` across the Steps window's inside
std::string separatorSvg(const StepsLayout& l, double y, const SvgScene& s) {
  const double at = y - 0.5 * s.layoutSpacing;
  return "<line x1=\"" + num(l.box.lo.x + s.layoutPadding) + "\" y1=\"" + num(at) + "\" x2=\"" +
         num(l.box.hi.x - s.layoutPadding) + "\" y2=\"" + num(at) + "\"" +
         paint("stroke", withAlpha(s.textMuted, 0.5f)) + " stroke-width=\"1\"/>";
}

// the Steps window: heading, the step shown (its controls' place), steps, pseudo-code
void writeSteps(const SvgScene& s, const StepsLayout& l, std::string& out) {
  out += "<g id=\"steps\" font-family=\"DejaVu Sans, Verdana, sans-serif\">\n  " +
         rectSvg(l.box, s.panel, s.rounding) + "\n";
  for (std::size_t k = 0; k < l.heading.size(); ++k)
    out += "  " +
           lineSvg(l.listLeft, l.headingTop + static_cast<double>(k) * l.lineStep, l.textScale,
                   l.heading[k], s.textMuted, s) +
           "\n";
  if (l.controls && !s.stepColours.empty()) {
    const std::string shown = s.step < 0 ? "all " + std::to_string(s.stepColours.size()) + " steps"
                                         : "step " + std::to_string(s.step + 1) + " of " +
                                               std::to_string(s.stepColours.size());
    out += "  " + lineSvg(l.listLeft, l.controlsTop, l.textScale, shown, s.textMuted, s) + "\n";
  }
  out += "  " + separatorSvg(l, l.listTop, s) + "\n";
  double y = l.listTop;
  for (const StepLines& st : l.shown) {
    const int i = static_cast<int>(st.step);
    Rgba c = st.step < s.stepColours.size() ? s.stepColours[st.step] : s.text;
    if (s.step >= 0 && i > s.step) c = withAlpha(c, 0.35f);
    if (i == s.step) {
      const double h =
          static_cast<double>(st.lines.size()) * l.lineStep - s.layoutSpacing * l.textScale;
      out += "  " +
             rectSvg({{l.listLeft - 3.0, y - 1.0}, {l.listLeft + l.columnWidth, y + h + 1.0}},
                     withAlpha(s.highlight, 0.22f)) +
             "\n";
    }
    for (const std::string& line : st.lines) {
      out += "  " + lineSvg(l.listLeft, y, l.textScale, line, c, s) + "\n";
      y += l.lineStep;
    }
  }
  if (!l.sideBySide && !l.code.empty()) out += "  " + separatorSvg(l, l.codeTop, s) + "\n";
  for (std::size_t i = 0; i < l.code.size(); ++i)
    out += "  " +
           lineSvg(l.codeLeft, l.codeTop + static_cast<double>(i) * l.lineStep, l.textScale,
                   l.code[i], l.codeCurrent[i] ? s.highlight : s.textMuted, s) +
           "\n";
  out += "</g>\n";
}

}  // namespace

std::string wordsSvg(double x, double scale, const std::string& text, const SvgScene& s) {
  if (text.find_first_of(" -") == std::string::npos) return xmlEscape(text);
  std::string out;
  std::size_t start = 0;
  while (start < text.size()) {
    const std::size_t space = std::min(text.find(' ', start), text.size());
    const std::size_t hyphen = text.find('-', start);
    const std::size_t end = hyphen < space ? hyphen + 1 : space;
    if (end > start) {
      const std::string_view before(text.data(), start);
      const double dx = start == 0 ? 0.0 : (s.advance ? s.advance : s.measure)(before).x;
      out += "<tspan x=\"" + num(x + scale * dx) + "\">" +
             xmlEscape(std::string_view(text).substr(start, end - start)) + "</tspan>";
    }
    if (end == space && end < text.size()) out += " ";
    start = end == space ? end + 1 : end;
  }
  return out;
}

void writeScreenList(const SvgScene& s, const DrawList& list, std::string& out) {
  out += "<g class=\"inset\" stroke-linecap=\"butt\">\n";
  const auto pt = [](glm::dvec3 p) { return num(p.x) + "," + num(p.y); };
  for (std::size_t t = 0; t + 2 < list.fills.size(); t += 3)
    out += "  <polygon points=\"" + pt(list.fills[t].p) + " " + pt(list.fills[t + 1].p) + " " +
           pt(list.fills[t + 2].p) + "\"" + paint("fill", list.fills[t].colour) + "/>\n";
  for (const Segment& g : list.segments) {
    out += "  <line x1=\"" + num(g.a.x) + "\" y1=\"" + num(g.a.y) + "\" x2=\"" + num(g.b.x) +
           "\" y2=\"" + num(g.b.y) + "\"" + paint("stroke", g.colour) + " stroke-width=\"" +
           num(g.width) + "\"";
    if (g.dash > 0.0f) out += " stroke-dasharray=\"" + num(g.dash) + "\"";
    out += "/>\n";
  }
  for (const Label& l : list.labels) {
    // centred on its point as the window centres it: its box's top left rounded
    const glm::dvec2 at =
        imguiBaseline(glm::round(glm::dvec2(l.p) - 0.5 * s.measure(l.text)), s.fontPixels);
    out += "  <text x=\"" + num(at.x) + "\" y=\"" + num(at.y) +
           "\" font-family=\"DejaVu Sans, Verdana, sans-serif\" font-size=\"" + num(s.fontPixels) +
           "\"" + paint("fill", readableOn(l.colour, s.background, s.text)) + ">" +
           xmlEscape(l.text) + "</text>\n";
  }
  out += "</g>\n";
}

void writeLetterbox(const SvgScene& s, std::string& out) {
  const ScreenRect& p = s.page;
  if (p.hi.x <= p.lo.x) return;
  std::vector<ScreenRect> bars = barsAround({{0.0, 0.0}, s.size}, p);
  if (s.figureRoom.hi.x > s.figureRoom.lo.x)
    for (const ScreenRect& r : barsAround(p, s.figureRoom)) bars.push_back(r);
  if (bars.empty()) return;
  out += "<g id=\"letterbox\">\n";
  for (const ScreenRect& r : bars) out += "  " + rectSvg(r, s.background) + "\n";
  out += "</g>\n";
}

void writeSlideBoxes(const SvgScene& s, std::string& out) {
  const SlideLayout& l = s.layout;
  if (s.window.hi.x > s.window.lo.x) {
    out += "<g id=\"window\" font-family=\"DejaVu Sans, Verdana, sans-serif\">\n  " +
           rectSvg(s.window, withAlpha(s.panel, 1.0f), s.rounding) + "\n  " +
           rectSvg({s.window.lo, {s.window.hi.x, s.window.lo.y + s.windowBarHeight}}, s.windowBar) +
           "\n  " +
           lineSvg(s.window.lo.x + 2.0 * s.layoutPadding,
                   s.window.lo.y + 0.5 * (s.windowBarHeight - bodyPixels(s)), 1.0, s.windowTitle,
                   s.text, s) +
           "\n" + s.windowSvg + "</g>\n";
  }
  writeTextBox(s, "title", l.title, l.titleLines, s.text, out);
  writeTextBox(s, "caption", l.caption, l.caption.lines.size(), s.text, out);
  if (!l.note.lines.empty()) writeTextBox(s, "note", l.note, l.note.lines.size(), s.text, out);
  if (l.steps) writeSteps(s, *l.steps, out);
}

std::string plotsSlideSvg(const SvgScene& s) {
  std::string out;
  writeLetterbox(s, out);
  out += s.plotsSvg;
  writeSlideBoxes(s, out);
  return out + "</svg>\n";
}

}  // namespace convexloc::viewer
