// convexloc-viewer — a log-log plot laid out in pixels, GL-free and ImGui-free: series of
// positive values become polylines and markers, the axes decade ticks and labels, the
// legend a swatch and a name per series. The Why O(1) panel draws the result with ImGui's
// draw list and the SVG export writes the very same primitives, so both show one picture.
#pragma once

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <glm/glm.hpp>

#include "logic/base/colour.hpp"
#include "logic/base/screen_rect.hpp"
#include "logic/base/text_layout.hpp"
#include "logic/base/xml.hpp"

namespace convexloc::viewer {

// one curve: (x, y) pairs with both > 0, drawn in order
struct PlotSeries {
  std::string name;
  Rgba colour;
  std::vector<glm::dvec2> points;
  bool dashed = false;
};

// what a plot shows
struct LogPlot {
  std::string title, xLabel, yLabel;
  std::string xUnit, yUnit;  // appended to the tick labels ("B"), or empty
  std::vector<PlotSeries> series;
  std::vector<std::string> notes;  // lines under the legend ("halfplane: N <= 262 144")
  bool legend = true;  // its legend under it (false: one shared with its neighbours, elsewhere)
};

// the colours and sizes a layout uses
struct PlotStyle {
  Rgba background, frame, grid, text, textMuted;
  double fontPx = 14.0;
  double charWidth = 7.5;  // the width of an average character at fontPx, for the legend box
  double unit = 1.0;       // line widths, marks and ticks are this many times their pixels
  bool boldTitle = true;   // the title in bold (a slide's is not: the window has no bold)
};

// a straight line or a polyline in pixels (y down)
struct PlotPath {
  std::vector<glm::dvec2> points;
  Rgba colour;
  float width = 1.0f;
  bool dashed = false;
  bool series = false;  // a data series (the SVG writes it as one <polyline>)
};

// a filled disc in pixels
struct PlotMark {
  glm::dvec2 p{0.0};
  Rgba colour;
  float radius = 3.0f;
};

// text in pixels: `anchor` 0 left, 0.5 middle, 1 right of p; p.y is the text's middle
struct PlotText {
  glm::dvec2 p{0.0};
  std::string text;
  Rgba colour;
  float anchor = 0.0f;
  bool bold = false;
};

// a laid-out plot: frame first, then grid, series, markers, texts
struct PlotDrawing {
  ScreenRect rect;  // the whole plot, title and labels included
  Rgba background;
  std::vector<PlotPath> paths;
  std::vector<PlotMark> marks;
  std::vector<PlotText> texts;
};

// Lays `plot` out inside `rect`: axes over the decades covering every positive value,
// a tick and a grid line at each decade, the series, the legend under the x axis' label
// (`legendRoom` high at least: plots side by side keep their axes level).
PlotDrawing layoutLogPlot(const LogPlot& plot, ScreenRect rect, const PlotStyle& style,
                          double legendRoom = 0.0);
// the room left of a plot's axes: its widest y label's
double axesLeft(const LogPlot& plot, const PlotStyle& style);
// the height of `plot`'s legend flowed into rows `width` wide
double legendHeight(const LogPlot& plot, double width, const PlotStyle& style);
// `plot`'s legend alone, flowed from rect's top left into its width (a legend plots side by
// side share, under their x axes' labels)
PlotDrawing layoutLegend(const LogPlot& plot, ScreenRect rect, const PlotStyle& style);

// a decade's label: 1, 10, 100, 1k .. 1T above one, 0.1 .. 1e-9 below
std::string decadeText(int exponent);

// `drawings` as one SVG group, their (0, 0) moved to `origin`, their text's line `fontPx`
// high as the window's (ImGui sizes a font by its line: 1.164 em of DejaVu Sans)
std::string svgPlots(std::span<const PlotDrawing> drawings, glm::dvec2 origin, double fontPx);

// svgPlots with each text where the window draws it: its left edge at its point less its
// anchor's share of its width, rounded as ImGui rounds it, and each word at its advance
// (`advance`: a text's width at fontPx, the window's font), so that an SVG reader's own
// glyph spacing drifts no further than a word, the baseline `ascent` below the line's top
// (the window's font, loaded at another size, scaled to fontPx) (a slide's plots, compared
// with its PNG)
std::string svgPlots(std::span<const PlotDrawing> drawings, glm::dvec2 origin, double fontPx,
                     const MeasureText& advance, double ascent);

// a standalone SVG document `size` pixels large holding `drawings`
std::string svgDocument(std::span<const PlotDrawing> drawings, glm::dvec2 size, Rgba background,
                        double fontPx);

}  // namespace convexloc::viewer
