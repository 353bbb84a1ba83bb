// convexloc-viewer — a slide's boxes in the SVG, GL-free: the title card, the caption and
// the Steps window written from the slide's layout (logic/teach/slide_layout), where the
// window draws them, and the bars beside a letterboxed page; the SVG's attribute helpers.
#pragma once

#include <cmath>
#include <string>

#include "logic/base/colour.hpp"
#include "writers/svg_writer.hpp"

namespace convexloc::viewer::svg {

// a number for an attribute: two decimals are a hundredth of a pixel
std::string num(double v);
// "#rrggbb"
std::string rgb(Rgba c);
// ` NAME="#rrggbb"`, and its opacity when not opaque
std::string paint(const char* name, Rgba c);

}  // namespace convexloc::viewer::svg

namespace convexloc::viewer {

// Where the window draws a line of text whose top left is `at` (SVG readers differ on
// dominant-baseline, so the SVG gives the baseline): ImGui floors the position and puts the
// baseline its font's ascent below, the ascent (0.928 em of DejaVu Sans) floored up a pixel
// at the font's size `em`, times the window's font `scale`.
inline glm::dvec2 imguiBaseline(glm::dvec2 at, double em, double scale = 1.0) {
  return {std::floor(at.x), std::floor(at.y) + scale * std::floor(0.928 * em + 1.0)};
}

// `text`'s words (and a hyphened word's parts) as tspans where the window draws them: from
// `x`, the advance before each (`scale` times the body's); SVG readers space glyphs their own
// way, a word drifts no further. A single word is written as it is.
std::string wordsSvg(double x, double scale, const std::string& text, const SvgScene& scene);

// the legend's box and rows where the window draws them (writers/svg_legend.cpp)
void writeLegend(const SvgScene& scene, std::string& out);

// the bars beside `scene.page` (none when the page is empty or fills the picture)
void writeLetterbox(const SvgScene& scene, std::string& out);

// a draw list in window pixels, unprojected, as a group: fills, segments (widths as given),
// labels centred at their points
void writeScreenList(const SvgScene& scene, const DrawList& list, std::string& out);
// the layout's title card, caption and Steps window, each a group of a box and its lines
void writeSlideBoxes(const SvgScene& scene, std::string& out);
// a plots slide's picture after its background, to the document's end: the bars, its plots
// (its figure: no scene under them) and its boxes
std::string plotsSlideSvg(const SvgScene& scene);

}  // namespace convexloc::viewer
