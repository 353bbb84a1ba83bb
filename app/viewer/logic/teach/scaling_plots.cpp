// convexloc-viewer — Why O(1): the plots of a measurement, and their SVG.
#include "logic/teach/scaling.hpp"

#include <cstdint>
#include <fstream>
#include <iterator>

#include "logic/base/format.hpp"

namespace convexloc::viewer {
namespace {

// the predicates plot's floor: a mean below it is drawn on it
constexpr double kPredicateFloor = 0.01;

// the series of one quantity of every method against N (F)
template <class Method, class Value>
LogPlot methodPlot(const std::vector<SeriesOf<Method>>& series, Value value) {
  LogPlot p;
  for (const SeriesOf<Method>& s : series) {
    PlotSeries ps{std::string(toString(s.method)), methodColour(s.method), {}, false};
    ps.name.append("  ").append(methodInfo(s.method).cost);
    for (const ScalingSample& x : s.samples)
      ps.points.push_back(glm::dvec2(static_cast<double>(x.n), value(x)));
    p.series.push_back(std::move(ps));
  }
  return p;
}

// the sizes measured, their axis and the O(N) method that stops early, of one dimension
struct Axis {
  const char* label;       // the x axis
  const char* linearName;  // the method that stops early
  const char* symbol;      // "N" or "F"
  const std::vector<std::size_t>& sizes;
  std::size_t linearLimit;
};

// a plot of one quantity against the axis' sizes, and what it leaves out
template <class Method, class Value>
LogPlot plotOf(const std::vector<SeriesOf<Method>>& series, const Axis& axis, Value value) {
  LogPlot p = methodPlot(series, value);
  p.xLabel = axis.label;
  if (!axis.sizes.empty() && axis.sizes.back() > axis.linearLimit)
    p.notes.push_back(std::string(axis.linearName)
                          .append(" stops at ")
                          .append(axis.symbol)
                          .append(" = ")
                          .append(grouped(axis.linearLimit))
                          .append(" (O(")
                          .append(axis.symbol)
                          .append(") per query)"));
  return p;
}

// the 2D methods against N
// `p` with its title, its y axis' label and the unit of its ticks
LogPlot titled(LogPlot p, const char* title, const char* yLabel, const char* yUnit = "") {
  p.title = title;
  p.yLabel = yLabel;
  p.yUnit = yUnit;
  return p;
}

// a sample's mean predicates per query: a query deciding before any predicate (outside the
// box, by the radii) counts 0, and the mean is kept above the axis' floor (kPredicateFloor)
// so that it still shows
double predicatesOf(const ScalingSample& s) {
  return std::max(s.predicates, kPredicateFloor);
}

// a sample's time per query
double nsOf(const ScalingSample& s) {
  return s.nsPerQuery;
}

template <class Value>
LogPlot plot2D(const ScalingResult& r, const ScalingConfig& c, Value value) {
  return plotOf(r.series,
                Axis{"N, edges of a regular N-gon", "halfplane", "N", c.sizes, c.linearLimit},
                value);
}

// the 3D methods against F
template <class Value>
LogPlot plot3D(const ScalingResult& r, const ScalingConfig& c, Value value) {
  return plotOf(r.series3d,
                Axis{"F, faces of a geodesic sphere", "halfspace", "F", c.faces, c.linearLimit3d},
                value);
}

// the measurement in words, in the page's fourth quarter
PlotDrawing summaryDrawing(const ScalingResult& r, const ScalingConfig& c, ScreenRect rect,
                           const PlotStyle& st, bool solid) {
  PlotDrawing d;
  d.rect = rect;
  d.background = st.background;
  double y = rect.lo.y + 0.8 * st.fontPx;
  const auto line = [&](std::string text, Rgba colour, bool bold = false) {
    d.texts.push_back({{rect.lo.x + 4.0, y}, std::move(text), colour, 0.0f, bold});
    y += 1.5 * st.fontPx;
  };
  line("What was measured", st.text, true);
  if (!solid && !c.sizes.empty())
    line("regular N-gons, N = 8 .. " + grouped(c.sizes.back()) + ", " + grouped(c.tracedPoints) +
             " random points traced,",
         st.textMuted);
  if (solid && !c.faces.empty())
    line("geodesic spheres, F = 20 .. " + grouped(c.faces.back()) + ", " + grouped(c.tracedPoints) +
             " random points traced,",
         st.textMuted);
  line(grouped(c.timedPoints) + " located in batches (each timing at least " +
           approx(c.minSeconds * 1e3, 2) + " ms)",
       st.textMuted);
  y += 0.5 * st.fontPx;
  const auto methodLines = [&](const auto& series, const char* size) {
    for (const auto& s : series) {
      if (s.samples.empty()) continue;
      const ScalingSample& x = s.samples.back();
      std::string text = std::string(toString(s.method)) + ": " + approx(x.predicates, 3) +
                         " predicates, " + nsText(x.nsPerQuery) + " ns per query at " + size +
                         grouped(x.n);
      if (x.cellEdges > 0.0) text += " (cells list " + approx(x.cellEdges, 3) + " edges)";
      line(text, methodColour(s.method));
    }
  };
  if (solid) {
    methodLines(r.series3d, "F = ");
    return d;
  }
  methodLines(r.series, "N = ");
  if (!r.memory.empty()) {
    const MemorySample& m = r.memory.back();
    y += 0.5 * st.fontPx;
    line("smallest gap " + approx(m.gap, 2) + ": the paper's slabs take " +
             binarySize(m.paperBytes) + ",",
         st.text);
    line("convexloc's polar " + binarySize(m.polarBytes) + ", uniform " +
             binarySize(m.uniformBytes) + " (bounded by O(N))",
         st.text);
  }
  return d;
}

}  // namespace

Rgba methodColour(Method3D m) {
  // halfspace, walk, cubemap
  constexpr std::uint32_t kColours[] = {0x9A9A9A, 0x56B4E9, 0xD55E00};
  const auto i = static_cast<std::size_t>(m);
  return hex(i < std::size(kColours) ? kColours[i] : 0x999999);
}

LogPlot predicatesPlot3D(const ScalingResult& r, const ScalingConfig& c) {
  LogPlot p = titled(plot3D(r, c, predicatesOf), "Predicates per query (3D)",
                     "mean plane + walk-edge tests (core's trace)");
  p.notes.insert(p.notes.begin(), "cubemap: its radii decide most queries before any plane test");
  return p;
}

LogPlot timePlot3D(const ScalingResult& r, const ScalingConfig& c) {
  return titled(plot3D(r, c, nsOf), "Time per query (3D)", "ns per query (batch locate)", " ns");
}

LogPlot memoryPlot3D(const ScalingResult& r, const ScalingConfig& c) {
  LogPlot p =
      titled(plot3D(r, c, [](const ScalingSample& x) { return static_cast<double>(x.bytes); }),
             "Memory against F", "bytes (the locator's tables)", "B");
  return p;
}

Rgba methodColour(Method2D m) {
  // halfplane, wedge, slab, uniform, polar
  constexpr std::uint32_t kColours[] = {0x9A9A9A, 0x56B4E9, 0x009E73, 0xCC79A7, 0xD55E00};
  const auto i = static_cast<std::size_t>(m);
  return hex(i < std::size(kColours) ? kColours[i] : 0x999999);
}

LogPlot predicatesPlot(const ScalingResult& r, const ScalingConfig& c) {
  LogPlot p = titled(plot2D(r, c, predicatesOf), "Predicates per query",
                     "mean edge + ray tests (core's trace)");
  PlotSeries paper{
      "polar, the paper's (edges in the cell)", methodColour(Method2D::Polar), {}, true};
  for (const ScalingSeries& s : r.series)
    for (const ScalingSample& x : s.samples)
      if (s.method == Method2D::Polar)
        paper.points.push_back(glm::dvec2(static_cast<double>(x.n), x.cellEdges));
  p.series.push_back(std::move(paper));
  p.notes.insert(p.notes.begin(), "polar: its radii decide most queries before any edge test");
  return p;
}

LogPlot timePlot(const ScalingResult& r, const ScalingConfig& c) {
  return titled(plot2D(r, c, nsOf), "Time per query", "ns per query (batch locate)", " ns");
}

LogPlot memoryPlot(const ScalingResult& r) {
  LogPlot p;
  p.title = "Memory against the smallest y-gap";
  p.xLabel = "smallest gap between vertex y (octagon + 1 vertex)";
  p.yLabel = "bytes";
  p.yUnit = std::string(1, 'B');
  PlotSeries paper{"paper: (ymax - ymin) / gap uniform slabs", hex(0xE69F00), {}, true};
  PlotSeries uniform{
      "convexloc uniform (core's slab count)", methodColour(Method2D::Uniform), {}, false};
  PlotSeries polar{"convexloc polar (core's slab count)", methodColour(Method2D::Polar), {}, false};
  for (const MemorySample& m : r.memory) {
    paper.points.push_back({m.gap, m.paperBytes});
    uniform.points.push_back({m.gap, static_cast<double>(m.uniformBytes)});
    polar.points.push_back({m.gap, static_cast<double>(m.polarBytes)});
  }
  p.series = {paper, uniform, polar};
  p.notes.push_back("paper: 8 B per slab (its 2 edges, 4 B each)");
  return p;
}

PlotStyle plotStyle(Theme theme, double fontPx) {
  const Palette& pal = paletteFor(theme);
  PlotStyle s;
  s.background = pal.background;
  s.text = pal.text;
  s.textMuted = pal.textMuted;
  s.frame = withAlpha(pal.text, 0.7f);
  s.grid = withAlpha(pal.text, 0.15f);
  s.fontPx = fontPx;
  s.charWidth = 0.56 * fontPx;
  return s;
}

std::vector<PlotDrawing> scalingDrawings(const ScalingResult& r, const ScalingConfig& c,
                                         const PlotStyle& style, glm::dvec2 size, bool solid) {
  // predicates and time side by side above, memory below on the left half
  const double gap = 2.0 * style.fontPx;
  const double w = 0.5 * (size.x - 3.0 * gap), h = 0.5 * (size.y - 3.0 * gap);
  const ScreenRect a{{gap, gap}, {gap + w, gap + h}};
  const ScreenRect b{{2.0 * gap + w, gap}, {2.0 * gap + 2.0 * w, gap + h}};
  const ScreenRect m{{gap, 2.0 * gap + h}, {gap + w, 2.0 * gap + 2.0 * h}};
  const ScreenRect t{{2.0 * gap + w, 2.0 * gap + h}, {2.0 * gap + 2.0 * w, 2.0 * gap + 2.0 * h}};
  if (solid)
    return {layoutLogPlot(predicatesPlot3D(r, c), a, style),
            layoutLogPlot(timePlot3D(r, c), b, style), layoutLogPlot(memoryPlot3D(r, c), m, style),
            summaryDrawing(r, c, t, style, true)};
  return {layoutLogPlot(predicatesPlot(r, c), a, style), layoutLogPlot(timePlot(r, c), b, style),
          layoutLogPlot(memoryPlot(r), m, style), summaryDrawing(r, c, t, style, false)};
}

std::string scalingSvg(const ScalingResult& r, const ScalingConfig& c, Theme theme, bool solid) {
  const glm::dvec2 size{1600.0, 1000.0};
  const PlotStyle style = plotStyle(theme, 16.0);
  const std::vector<PlotDrawing> d = scalingDrawings(r, c, style, size, solid);
  return svgDocument(d, size, style.background, style.fontPx);
}

std::string solidSvgPath(const std::string& path) {
  const bool svg = path.size() >= 4 && path.compare(path.size() - 4, 4, ".svg") == 0;
  return (svg ? path.substr(0, path.size() - 4) : path) + "-3d.svg";
}

bool writeScalingSvg(const std::string& path, const ScalingResult& r, const ScalingConfig& c,
                     Theme theme, std::string& error, bool solid) {
  std::ofstream out(path, std::ios::binary);
  out << scalingSvg(r, c, theme, solid);
  out.close();
  if (out) return true;
  error = "cannot write " + path;
  return false;
}

}  // namespace convexloc::viewer
