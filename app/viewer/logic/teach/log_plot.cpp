// convexloc-viewer — the log-log plot's layout and its SVG.
#include "logic/teach/log_plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace convexloc::viewer {
namespace {

// the decades [lo, hi] (powers of ten) that cover every positive value on one axis
struct DecadeRange {
  int lo = 0, hi = 1;
};

DecadeRange decadesOf(const LogPlot& plot, bool y) {
  double lo = 1e300, hi = 0.0;
  for (const PlotSeries& s : plot.series)
    for (const glm::dvec2 p : s.points) {
      const double v = y ? p.y : p.x;
      if (v > 0.0 && std::isfinite(v)) {
        lo = std::min(lo, v);
        hi = std::max(hi, v);
      }
    }
  if (hi <= 0.0) return {};
  DecadeRange r{static_cast<int>(std::floor(std::log10(lo) + 1e-9)),
                static_cast<int>(std::ceil(std::log10(hi) - 1e-9))};
  if (r.hi <= r.lo) r.hi = r.lo + 1;
  return r;
}

// maps data to pixels inside the axes' box
struct Axes {
  ScreenRect box;
  DecadeRange x, y;
  double px(double v) const {
    const double t = (std::log10(v) - x.lo) / (x.hi - x.lo);
    return box.lo.x + t * box.size().x;
  }
  double py(double v) const {
    const double t = (std::log10(v) - y.lo) / (y.hi - y.lo);
    return box.hi.y - t * box.size().y;
  }
};

// at most about `most` labelled decades (at least two): every k-th one
int labelStep(const DecadeRange& r, int most) {
  most = std::max(most, 2);
  return std::max(1, (r.hi - r.lo + most - 1) / most);
}

// the widest of an axis' decade labels, in characters
std::size_t widestLabel(const DecadeRange& r, const std::string& unit) {
  std::size_t w = 0;
  for (int e = r.lo; e <= r.hi; ++e) w = std::max(w, decadeText(e).size() + unit.size());
  return w;
}

// a line `u` nominal pixels wide
float widthOf(double u, const PlotStyle& st) {
  return static_cast<float>(u * st.unit);
}

void axesAndGrid(const LogPlot& plot, const Axes& a, const PlotStyle& st, PlotDrawing& d) {
  const ScreenRect& b = a.box;
  const float thin = widthOf(1.0, st);
  const double tick = 5.0 * st.unit;
  d.paths.push_back({{b.lo, {b.hi.x, b.lo.y}, b.hi, {b.lo.x, b.hi.y}, b.lo}, st.frame, thin});
  // labels a label and a half apart at least: fewer where the axis is short
  const double xLabel = st.charWidth * static_cast<double>(widestLabel(a.x, plot.xUnit));
  const int xs = labelStep(a.x, std::min(8, static_cast<int>(b.size().x / (1.5 * xLabel))));
  const int ys = labelStep(a.y, std::min(7, static_cast<int>(b.size().y / (2.0 * st.fontPx))));
  for (int e = a.x.lo; e <= a.x.hi; ++e) {
    const double x = a.px(std::pow(10.0, e));
    if (e > a.x.lo && e < a.x.hi) d.paths.push_back({{{x, b.lo.y}, {x, b.hi.y}}, st.grid, thin});
    d.paths.push_back({{{x, b.hi.y}, {x, b.hi.y + tick}}, st.frame, thin});
    if ((e - a.x.lo) % xs == 0)
      d.texts.push_back(
          {{x, b.hi.y + tick + 0.7 * st.fontPx}, decadeText(e) + plot.xUnit, st.text, 0.5f});
  }
  for (int e = a.y.lo; e <= a.y.hi; ++e) {
    const double y = a.py(std::pow(10.0, e));
    if (e > a.y.lo && e < a.y.hi) d.paths.push_back({{{b.lo.x, y}, {b.hi.x, y}}, st.grid, thin});
    d.paths.push_back({{{b.lo.x - tick, y}, {b.lo.x, y}}, st.frame, thin});
    if ((e - a.y.lo) % ys == 0)
      d.texts.push_back({{b.lo.x - 1.6 * tick, y}, decadeText(e) + plot.yUnit, st.text, 1.0f});
  }
  d.texts.push_back(
      {{b.middle().x, b.hi.y + tick + 1.9 * st.fontPx}, plot.xLabel, st.textMuted, 0.5f});
}

void seriesPaths(const LogPlot& plot, const Axes& a, const PlotStyle& st, PlotDrawing& d) {
  for (const PlotSeries& s : plot.series) {
    PlotPath path{{}, s.colour, widthOf(2.0, st), s.dashed, true};
    for (const glm::dvec2 p : s.points) {
      if (!(p.x > 0.0 && p.y > 0.0)) continue;
      path.points.push_back({a.px(p.x), a.py(p.y)});
      d.marks.push_back({path.points.back(), s.colour, widthOf(3.0, st)});
    }
    d.paths.push_back(std::move(path));
  }
}

// the legend's entries flowed into rows `width` wide: where each entry starts
struct LegendFlow {
  std::vector<glm::dvec2> at;  // per series, relative to the legend's top left
  double height = 0.0;
};

LegendFlow flowLegend(const LogPlot& plot, const PlotStyle& st, double width) {
  const double line = 1.3 * st.fontPx, swatch = 2.0 * st.fontPx;
  LegendFlow f;
  glm::dvec2 p{0.0, 0.0};
  for (const PlotSeries& s : plot.series) {
    const double w = swatch + 0.5 * st.fontPx + st.charWidth * static_cast<double>(s.name.size()) +
                     1.2 * st.fontPx;
    if (p.x > 0.0 && p.x + w > width) p = {0.0, p.y + line};
    f.at.push_back(p);
    p.x += w;
  }
  f.height =
      (plot.series.empty() ? 0.0 : p.y + line) + line * static_cast<double>(plot.notes.size());
  return f;
}

// the legend under the x axis' label: a swatch and a name per series, then the notes
void legend(const LogPlot& plot, const LegendFlow& flow, glm::dvec2 o, const PlotStyle& st,
            PlotDrawing& d) {
  const double line = 1.3 * st.fontPx, swatch = 2.0 * st.fontPx;
  double y = o.y + 0.5 * line;
  for (std::size_t i = 0; i < plot.series.size(); ++i) {
    const PlotSeries& s = plot.series[i];
    const glm::dvec2 p = o + flow.at[i] + glm::dvec2(0.0, 0.5 * line);
    d.paths.push_back({{p, p + glm::dvec2(swatch, 0.0)}, s.colour, widthOf(2.5, st), s.dashed});
    d.texts.push_back({p + glm::dvec2(swatch + 0.5 * st.fontPx, 0.0), s.name, st.text, 0.0f});
    y = p.y + line;
  }
  for (const std::string& n : plot.notes) {
    d.texts.push_back({{o.x, y}, n, st.textMuted, 0.0f});
    y += line;
  }
}

// an SVG colour and its opacity attribute's value
std::string svgColour(Rgba c) {
  char buf[8];
  auto byte = [](float v) {
    return static_cast<int>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255));
  };
  std::snprintf(buf, sizeof buf, "#%02X%02X%02X", byte(c.r), byte(c.g), byte(c.b));
  return buf;
}

std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f", v);
  return buf;
}

// a line or polyline where the window draws it: ImGui's AddLine draws from half a pixel
// right of and below its points, on the pixels' centres
void svgPath(std::ostringstream& out, PlotPath p) {
  for (glm::dvec2& q : p.points) q += glm::dvec2(0.5);
  const std::string stroke = " fill=\"none\" stroke=\"" + svgColour(p.colour) +
                             "\" stroke-opacity=\"" + num(p.colour.a) + "\" stroke-width=\"" +
                             num(p.width) + "\"" + (p.dashed ? " stroke-dasharray=\"6 4\"" : "");
  if (p.series) {
    out << "<polyline class=\"series\" points=\"";
    for (std::size_t i = 0; i < p.points.size(); ++i)
      out << (i ? " " : "") << num(p.points[i].x) << "," << num(p.points[i].y);
    out << "\"" << stroke << "/>\n";
    return;
  }
  for (std::size_t i = 1; i < p.points.size(); ++i)
    out << "<line x1=\"" << num(p.points[i - 1].x) << "\" y1=\"" << num(p.points[i - 1].y)
        << "\" x2=\"" << num(p.points[i].x) << "\" y2=\"" << num(p.points[i].y) << "\"" << stroke
        << "/>\n";
}

// the baseline of a line `fontPx` high (DejaVu Sans' ascent 0.797 of it) centred on y, as
// the window puts it (SVG readers differ on dominant-baseline)
double baselineAt(double y, double fontPx) {
  return std::round(y - 0.5 * fontPx) + std::floor(0.797 * fontPx + 1.0);
}

// `t` where the window draws it: its line centred on t.p, anchored as asked
void svgText(std::ostringstream& out, const PlotText& t, double fontPx) {
  const char* anchor = t.anchor < 0.25f ? "start" : t.anchor > 0.75f ? "end" : "middle";
  out << "<text x=\"" << num(t.p.x) << "\" y=\"" << num(baselineAt(t.p.y, fontPx))
      << "\" text-anchor=\"" << anchor << "\" fill=\"" << svgColour(t.colour) << "\""
      << (t.bold ? " font-weight=\"bold\"" : "") << ">" << xmlEscape(t.text) << "</text>\n";
}

// `t` from its left edge as the window draws it, each word at its advance
void svgTextPlaced(std::ostringstream& out, const PlotText& t, double fontPx,
                   const MeasureText& advance, double ascent) {
  const double left = std::round(t.p.x - t.anchor * advance(t.text).x);
  const double baseline = std::round(t.p.y - 0.5 * fontPx) + ascent;
  out << "<text y=\"" << num(baseline) << "\" xml:space=\"preserve\" fill=\"" << svgColour(t.colour)
      << "\"" << (t.bold ? " font-weight=\"bold\"" : "") << ">";
  std::size_t start = 0;
  const std::string& s = t.text;
  while (start < s.size()) {
    const std::size_t end = std::min(s.find(' ', start), s.size());
    if (end > start)
      out << "<tspan x=\"" << num(left + advance(std::string_view(s).substr(0, start)).x) << "\">"
          << xmlEscape(std::string_view(s).substr(start, end - start)) << "</tspan>";
    start = end + 1;
  }
  out << "</text>\n";
}

// the plots' SVG; their texts placed word by word where `advance` is given
std::string plotsSvg(std::span<const PlotDrawing> drawings, glm::dvec2 origin, double fontPx,
                     const MeasureText* advance, double ascent) {
  std::ostringstream out;
  out << "<g transform=\"translate(" << num(origin.x) << " " << num(origin.y)
      << ")\" font-family=\"DejaVu Sans, Helvetica, Arial, sans-serif\" font-size=\""
      << num(fontPx / 1.164) << "\">\n";
  for (const PlotDrawing& d : drawings) {
    out << "<g>\n";
    for (const PlotPath& p : d.paths) svgPath(out, p);
    for (const PlotMark& m : d.marks)
      out << "<circle cx=\"" << num(m.p.x) << "\" cy=\"" << num(m.p.y) << "\" r=\"" << num(m.radius)
          << "\" fill=\"" << svgColour(m.colour) << "\"/>\n";
    for (const PlotText& t : d.texts) {
      if (advance)
        svgTextPlaced(out, t, fontPx, *advance, ascent);
      else
        svgText(out, t, fontPx);
    }
    out << "</g>\n";
  }
  out << "</g>\n";
  return out.str();
}

}  // namespace

std::string decadeText(int e) {
  static const char* const kSuffix[] = {"", "k", "M", "G", "T", "P"};
  if (e < 0) return e == -1 ? "0.1" : "1e" + std::to_string(e);
  const int group = std::min(e / 3, 5);
  std::string s = "1";
  for (int i = 0; i < e - 3 * group; ++i) s += '0';
  return s + kSuffix[group];
}

double axesLeft(const LogPlot& plot, const PlotStyle& st) {
  const std::size_t widest = widestLabel(decadesOf(plot, true), plot.yUnit);
  return st.charWidth * static_cast<double>(std::max<std::size_t>(widest, 5)) + 14.0 * st.unit;
}

double legendHeight(const LogPlot& plot, double width, const PlotStyle& st) {
  return flowLegend(plot, st, width).height;
}

PlotDrawing layoutLegend(const LogPlot& plot, ScreenRect rect, const PlotStyle& st) {
  PlotDrawing d;
  d.rect = rect;
  d.background = st.background;
  legend(plot, flowLegend(plot, st, rect.size().x), rect.lo, st, d);
  return d;
}

PlotDrawing layoutLogPlot(const LogPlot& plot, ScreenRect rect, const PlotStyle& st,
                          double legendRoom) {
  PlotDrawing d;
  d.rect = rect;
  d.background = st.background;
  Axes a;
  a.x = decadesOf(plot, false);
  a.y = decadesOf(plot, true);
  const double left = axesLeft(plot, st);
  const LegendFlow flow = plot.legend ? flowLegend(plot, st, rect.size().x - left) : LegendFlow{};
  // room for half the last x label right of the axes
  const double right =
      std::max(0.8 * st.fontPx,
               0.5 * st.charWidth * static_cast<double>(widestLabel(a.x, plot.xUnit)) + 2.0);
  a.box = {{rect.lo.x + left, rect.lo.y + 2.9 * st.fontPx},
           {rect.hi.x - right, rect.hi.y - 3.2 * st.fontPx - std::max(flow.height, legendRoom)}};
  d.texts.push_back(
      {{rect.lo.x + 4.0, rect.lo.y + 0.8 * st.fontPx}, plot.title, st.text, 0.0f, st.boldTitle});
  d.texts.push_back({{a.box.lo.x, rect.lo.y + 1.85 * st.fontPx}, plot.yLabel, st.textMuted, 0.0f});
  axesAndGrid(plot, a, st, d);
  seriesPaths(plot, a, st, d);
  if (plot.legend) legend(plot, flow, {a.box.lo.x, a.box.hi.y + 2.9 * st.fontPx}, st, d);
  return d;
}

std::string svgPlots(std::span<const PlotDrawing> drawings, glm::dvec2 origin, double fontPx) {
  return plotsSvg(drawings, origin, fontPx, nullptr, 0.0);
}

std::string svgPlots(std::span<const PlotDrawing> drawings, glm::dvec2 origin, double fontPx,
                     const MeasureText& advance, double ascent) {
  return plotsSvg(drawings, origin, fontPx, &advance, ascent);
}

std::string svgDocument(std::span<const PlotDrawing> drawings, glm::dvec2 size, Rgba background,
                        double fontPx) {
  std::ostringstream out;
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
      << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << num(size.x) << "\" height=\""
      << num(size.y) << "\" viewBox=\"0 0 " << num(size.x) << " " << num(size.y)
      << "\">\n<rect width=\"100%\" height=\"100%\" fill=\"" << svgColour(background) << "\"/>\n"
      << svgPlots(drawings, {0.0, 0.0}, fontPx) << "</svg>\n";
  return out.str();
}

}  // namespace convexloc::viewer
