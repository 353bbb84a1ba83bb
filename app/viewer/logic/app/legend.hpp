// convexloc-viewer — what the legend lists, GL-free: the window's legend and the SVG's are
// drawn from the same rows, and a row is listed only when what it names is drawn.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "logic/app/model.hpp"
#include "logic/base/colour.hpp"
#include "logic/base/text_layout.hpp"

namespace convexloc::viewer {

// the sample drawn before a row's text
enum class Swatch : std::uint8_t { Disc, Box, Line, DashedLine };

struct LegendRow {
  Swatch swatch = Swatch::Box;
  Rgba colour;         // the disc's, the box's fill or the line's colour
  Rgba edge;           // the box's outline, the disc's rim
  float width = 1.0f;  // a line's width in pixels
  std::string text;
  std::string count, share;  // class rows: how many points, and their share ("" without points)
};

struct Legend {
  std::string title;               // the method ("polar"), or the mode
  std::string subtitle;            // "16 edges, 64 cells"
  std::vector<LegendRow> classes;  // inside, boundary, outside
  std::vector<LegendRow> rows;     // the marks the drawing shows
};

// a row per class (inside, boundary, outside) with its count of `total` (faded when hidden)
std::vector<LegendRow> classLegendRows(const Model& model, const std::array<std::size_t, 3>& counts,
                                       std::size_t total);

// the legend of the scene shown (2D, its Lines mode, or 3D)
Legend legendOf(const Model& model);

// The legend's box as the window draws it and the SVG writes it: a line of title, the class
// rows in columns, a line per mark's line, inside `padding`; `font` is the body text's height
// in pixels (ImGui's: 1.164 em of DejaVu Sans), `spacing` the gap between two lines. A
// slide's layout takes the legend's size from here, before it is drawn.
glm::dvec2 legendBoxSize(const Legend& legend, const MeasureText& measure, double font,
                         double padding, double spacing);

// "41.2%" (empty when `whole` is 0)
std::string percentText(std::size_t part, std::size_t whole);

}  // namespace convexloc::viewer
