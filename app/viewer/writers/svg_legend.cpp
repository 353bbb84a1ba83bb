// convexloc-viewer — the legend in the SVG, where the window's legend draws it: its box, its
// class rows with their counts, its swatches and texts.
#include <algorithm>
#include <cmath>

#include "logic/app/legend.hpp"
#include "logic/base/text_layout.hpp"
#include "logic/base/xml.hpp"
#include "writers/svg_slide.hpp"

namespace convexloc::viewer {
namespace {

using svg::num;
using svg::paint;

// a legend row's swatch where the window draws it: in a row `h` high (the text's line) whose
// top left is (x, top)
std::string swatchSvg(const LegendRow& r, double x, double top, double h) {
  const double w = 0.7 * h, y = top + 0.5 * h, radius = 0.27 * h;
  auto line = [&](double x0, double x1) {
    return "<line x1=\"" + num(x0) + "\" y1=\"" + num(y) + "\" x2=\"" + num(x1) + "\" y2=\"" +
           num(y) + "\"" + paint("stroke", r.colour) + " stroke-width=\"" + num(r.width) + "\"/>";
  };
  switch (r.swatch) {
    case Swatch::Disc:  // a rim a pixel wide round the disc
      return "<circle cx=\"" + num(x + radius + 1.0) + "\" cy=\"" + num(y) + "\" r=\"" +
             num(radius + 0.5) + "\"" + paint("fill", r.colour) + paint("stroke", r.edge) +
             " stroke-width=\"1\"/>";
    case Swatch::Box:
      return "<rect x=\"" + num(x + 1.5) + "\" y=\"" + num(top + 0.15 * h + 0.5) + "\" width=\"" +
             num(w - 1.0) + "\" height=\"" + num(0.7 * h - 1.0) + "\"" + paint("fill", r.colour) +
             paint("stroke", r.edge) + " stroke-width=\"1\"/>";
    case Swatch::Line: return line(x + 1.0, x + w + 1.0);
    case Swatch::DashedLine: return line(x + 1.0, x + 0.3 * w) + line(x + 0.6 * w, x + w + 1.0);
  }
  return "";
}

// from a swatch's left to its row's text: the swatch, its margin and the window's item gap
double swatchAdvance(const LegendRow& r, double h, double gap) {
  return (r.swatch == Swatch::Disc ? 0.54 * h : 0.7 * h) + 4.0 + gap;
}

// `text` with its baseline at (x, y), anchored at its start or end
std::string legendText(double x, double y, std::string_view text, Rgba c, bool end = false) {
  return "<text x=\"" + num(end ? x : std::floor(x)) + "\" y=\"" + num(y) +
         "\" xml:space=\"preserve\"" + paint("fill", c) + (end ? " text-anchor=\"end\"" : "") +
         ">" + xmlEscape(text) + "</text>";
}

// the legend box's paint: the window's own (its panel colour at the legend's 0.82, no
// border) where the window drew it, else a framed box of the background
std::string legendBoxPaint(const SvgScene& s) {
  if (s.legendSize.x > 0.0) return paint("fill", withAlpha(s.panel, 0.82f));
  return paint("fill", withAlpha(s.background, 0.9f)) + paint("stroke", withAlpha(s.text, 0.2f)) +
         " stroke-width=\"1\"";
}

// the legend's metrics as the window lays it out (ImGui: a line is `h` high, lines
// `gap` apart; the class rows a table whose rows have `cell` padding above and below, its
// columns `2 cell.x` apart)
struct LegendMetrics {
  double k, f, h, gap, itemGap, pad, padY;
  glm::dvec2 cell;
  MeasureText measure;
  double width(const std::string& t) const { return t.empty() ? 0.0 : measure(t).x; }
  // the next line's top after an item `high` from `top` (ImGui floors it to a pixel)
  double next(double top, double high) const { return std::floor(top + high + gap); }
  double em;  // the window's font, before its scale k
  // a line's baseline from its top, as the window draws it
  double baseline(double top) const { return imguiBaseline({0.0, top}, em, k).y; }
};

// the class rows from `top` as the window's table: disc and name, count right-aligned, share
double writeClassRows(const SvgScene& s, const LegendMetrics& m, double x, double top,
                      std::string& out) {
  const Legend& g = *s.legend;
  double first = 0.0, count = 0.0;
  for (const LegendRow& r : g.classes) {
    first = std::max(first, swatchAdvance(r, m.h, m.itemGap) + m.width(r.text));
    count = std::max(count, m.width(r.count));
  }
  const double countEnd = x + first + 2.0 * m.cell.x + count;
  for (const LegendRow& r : g.classes) {
    const double t = top + m.cell.y, y = m.baseline(t);
    out += "  " + swatchSvg(r, x, t, m.h) +
           legendText(x + swatchAdvance(r, m.h, m.itemGap), y, r.text, s.text);
    if (!r.count.empty())
      out += legendText(countEnd, y, r.count, s.text, true) +
             legendText(countEnd + 2.0 * m.cell.x, y, r.share, s.textMuted);
    out += "\n";
    top += m.h + 2.0 * m.cell.y;
  }
  return top;
}

}  // namespace

// the legend as the window shows it: title, class rows in columns, a row per mark
void writeLegend(const SvgScene& s, std::string& out) {
  const Legend& g = *s.legend;
  const double k = s.legendScale;
  LegendMetrics m{k,
                  k * s.fontPixels,
                  1.164 * k * s.fontPixels,
                  k * s.layoutSpacing,
                  k * s.itemSpacingX,
                  k * s.layoutPadding,
                  k * s.windowPaddingY,
                  s.cellPadding,
                  [&](std::string_view t) { return k * s.measure(t); },
                  s.fontPixels};
  const glm::dvec2 box = legendBoxSize(g, m.measure, m.h, m.pad, m.gap);
  double w = box.x, h = box.y;
  if (s.legendSize.x > 0.0) w = s.legendSize.x, h = s.legendSize.y;  // the window's own box
  const glm::dvec2 lo = s.legendCorner - glm::dvec2(w, h);
  out += "<g id=\"legend\" font-family=\"DejaVu Sans, Verdana, sans-serif\" font-size=\"" +
         num(m.f) + "\">\n  <rect x=\"" + num(lo.x) + "\" y=\"" + num(lo.y) + "\" width=\"" +
         num(w) + "\" height=\"" + num(h) + "\" rx=\"" + num(0.4 * m.f) + "\"" + legendBoxPaint(s) +
         "/>\n";
  const double x = lo.x + m.pad;
  double top = lo.y + m.padY;
  out += "  " + legendText(x, m.baseline(top), g.title, s.text) + "\n";
  if (!g.subtitle.empty())
    out += "  " +
           legendText(x + m.width(g.title) + m.itemGap, m.baseline(top), g.subtitle, s.textMuted) +
           "\n";
  top = m.next(top, m.h);
  // the lines under the first start at the padding floored (ImGui's)
  const double row = std::floor(x);
  if (!g.classes.empty()) top = m.next(writeClassRows(s, m, row, top, out), 0.0);
  // a row per mark, its swatch at its first line; a mark's lines as one text's, unspaced
  for (const LegendRow& r : g.rows) {
    out += "  " + swatchSvg(r, row, top, m.h);
    const double first = top;
    for (const std::string& t : breakAtSpaces(r.text, 1e300, s.measure)) {
      out += legendText(row + swatchAdvance(r, m.h, m.itemGap), m.baseline(top), t, s.text);
      top += m.h;
    }
    top = m.next(first, top - first);
    out += "\n";
  }
  out += "</g>\n";
}

}  // namespace convexloc::viewer
