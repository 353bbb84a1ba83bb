// convexloc-viewer — Why O(1) as a slide's figure: three plots side by side at the slide's
// text size, short names, the measurement in one line under them.
#include <algorithm>

#include "logic/base/format.hpp"
#include "logic/teach/scaling.hpp"

namespace convexloc::viewer {
namespace {

// the plots a slide shows: predicates, time, memory
constexpr std::size_t kSlidePlots = 3;

// `p` for a slide: its notes left out (the caption and the notes speak for them), the y axis'
// label and the series' names where given shorter
LogPlot forSlide(LogPlot p, std::string yLabel, const std::vector<std::string>& names = {}) {
  p.notes.clear();
  p.yLabel = std::move(yLabel);
  for (std::size_t i = 0; i < names.size() && i < p.series.size(); ++i)
    if (!names[i].empty()) p.series[i].name = names[i];
  return p;
}

// the 2D page's plots
std::vector<LogPlot> plots2D(const ScalingResult& r, const ScalingConfig& c) {
  LogPlot predicates = forSlide(predicatesPlot(r, c), "edge + ray tests");
  if (!predicates.series.empty()) predicates.series.back().name = "polar: edges in its cell";
  LogPlot memory = forSlide(memoryPlot(r), "bytes",
                            {"paper: 8 B per slab", "convexloc uniform", "convexloc polar"});
  memory.title = "Memory against the y-gap";
  memory.xLabel = "smallest gap between vertex y";
  return {predicates, forSlide(timePlot(r, c), "ns per query"), memory};
}

// the 3D page's plots
std::vector<LogPlot> plots3D(const ScalingResult& r, const ScalingConfig& c) {
  LogPlot predicates = forSlide(predicatesPlot3D(r, c), "plane + walk-edge tests");
  LogPlot time = forSlide(timePlot3D(r, c), "ns per query");
  predicates.title = "Predicates per query";
  time.title = "Time per query";
  return {predicates, time, forSlide(memoryPlot3D(r, c), "bytes")};
}

// what was measured, in a line of at most `columns` characters where a shorter one fits
std::string measuredLine(const ScalingConfig& c, bool solid, double columns) {
  const std::vector<std::size_t>& sizes = solid ? c.faces : c.sizes;
  std::string shapes;
  if (!sizes.empty())
    shapes = (solid ? "geodesic spheres, F = 20 .. " : "regular N-gons, N = 8 .. ") +
             grouped(sizes.back()) + "; ";
  const std::string line = "What was measured: " + shapes + grouped(c.tracedPoints) +
                           " random points traced, " + grouped(c.timedPoints) +
                           " located in batches";
  if (static_cast<double>(line.size()) <= columns) return line;
  return shapes + grouped(c.tracedPoints) + " traced, " + grouped(c.timedPoints) + " timed";
}

// plots side by side that share one legend: the first's series name every later one's (plots
// stacked keep their own)
struct LegendGroup {
  std::size_t first = 0, last = 0;
  double width = 0.0;  // the legend's width: from the first plot's axes across the last plot
};

// whether every series of `b` is named in `a`'s legend
bool namedIn(const LogPlot& b, const LogPlot& a) {
  return std::all_of(b.series.begin(), b.series.end(), [&a](const PlotSeries& s) {
    return std::any_of(a.series.begin(), a.series.end(),
                       [&s](const PlotSeries& t) { return t.name == s.name; });
  });
}

std::vector<LegendGroup> legendGroups(const std::vector<LogPlot>& plots, const PlotsLayout& l,
                                      const PlotStyle& style) {
  std::vector<LegendGroup> groups;
  for (std::size_t i = 0; i < plots.size(); ++i) {
    // (plots stacked on an upright page keep their own legends)
    if (groups.empty() || !namedIn(plots[i], plots[groups.back().first]) ||
        l.plots[i].lo.y != l.plots[groups.back().first].lo.y)
      groups.push_back({i, i, 0.0});
    LegendGroup& g = groups.back();
    g.last = i;
    g.width = l.plots[i].hi.x - l.plots[g.first].lo.x - axesLeft(plots[g.first], style);
  }
  return groups;
}

}  // namespace

std::size_t slidePlotCount() {
  return kSlidePlots;
}

PlotStyle slidePlotStyle(Theme theme, double fontPx) {
  PlotStyle s = plotStyle(theme, fontPx);
  s.unit = std::max(1.0, fontPx / 16.0);
  s.boldTitle = false;
  return s;
}

std::vector<PlotDrawing> slideDrawings(const ScalingResult& r, const ScalingConfig& c,
                                       const PlotStyle& style, const PlotsLayout& l, bool solid,
                                       const std::string& status) {
  std::vector<LogPlot> plots = solid ? plots3D(r, c) : plots2D(r, c);
  plots.resize(std::min(plots.size(), l.plots.size()));
  const std::vector<LegendGroup> groups = legendGroups(plots, l, style);
  // the legends' room the tallest one's, so that the axes stand level
  double room = 0.0;
  for (const LegendGroup& g : groups)
    room = std::max(room, legendHeight(plots[g.first], g.width, style));
  std::vector<PlotDrawing> out;
  for (const LegendGroup& g : groups) {
    const LogPlot shared = plots[g.first];
    for (std::size_t i = g.first; i <= g.last; ++i) {
      plots[i].legend = g.first == g.last;
      out.push_back(layoutLogPlot(plots[i], l.plots[i], style, room));
    }
    if (g.first == g.last) continue;
    // under the group's x labels, from the first plot's axes across the last plot
    const double top = l.plots[g.first].hi.y - 0.3 * style.fontPx - room;
    out.push_back(layoutLegend(
        shared, {{l.plots[g.last].hi.x - g.width, top}, {l.plots[g.last].hi.x, top + room}},
        style));
  }
  PlotDrawing note;
  note.rect = l.note;
  note.background = style.background;
  note.texts.push_back(
      {{l.note.lo.x + 4.0, l.note.middle().y},
       status.empty() ? measuredLine(c, solid, l.note.size().x / style.charWidth) : status,
       style.textMuted,
       0.0f,
       false});
  out.push_back(std::move(note));
  return out;
}

}  // namespace convexloc::viewer
