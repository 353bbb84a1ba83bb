// convexloc-viewer — the scene as an SVG picture, GL-free: the same draw lists the renderer
// draws (fills, segments with their widths and dashes, markers of each shape, the labels
// placed by logic/view/label_layout), projected by the current camera into window pixels. In
// 3D the fills, segments and points are written back to front (painter's order by
// depth). A spray above `maxPoints` is thinned to every k-th point, and the picture says
// so in a visible note and an XML comment.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "convexloc/geometry.hpp"
#include "logic/app/legend.hpp"
#include "logic/base/colour.hpp"
#include "logic/base/draw_list.hpp"
#include "logic/base/xml.hpp"
#include "logic/teach/slide_layout.hpp"
#include "logic/view/scene_labels.hpp"

namespace convexloc::viewer {

// the sprayed points as the renderer draws them
struct SvgPoints {
  std::vector<glm::dvec3> points;
  std::span<const Location> classes;
  unsigned visibleMask = 7u;  // bit c: class c is drawn
  float size = 4.0f;          // diameter in window pixels; boundary points 1.7 times it
  Rgba colours[3];            // inside, boundary, outside
  Rgba rim;                   // the boundary points' rim
  bool overLines = false;     // 2D: all drawn over the lines (a near-boundary spray's)
};

// the split view: the right half's projection and draw lists over the same points, each
// half clipped to its rectangle, the divider between them and each half's heading
struct SvgSplit {
  ScreenRect left, right;
  ScreenProjection project;  // the right half's
  std::vector<const DrawList*> base, overlay;
  std::vector<TextBox> headings;
};

// everything one picture is written from
struct SvgScene {
  glm::dvec2 size{1.0};  // window pixels: the viewBox
  Rgba background;
  Rgba text;                 // the caption's and the note's colour
  double scale = 1.0;        // line widths, marker sizes and label offsets are multiplied by it
  double fontPixels = 16.0;  // the text's font size (em) in pixels
  bool depthSorted = false;  // 3D: fills, segments and points back to front
  std::optional<glm::dvec3> eye;  // 3D: the headlight, for lit faces
  ScreenProjection project;
  MeasureText measure;  // a label's size in pixels at fontPixels
  MeasureText advance;  // a text's advance unrounded (the next glyph's place); empty: measure
  std::vector<const DrawList*> base;     // drawn first (the renderer's cached layers)
  std::vector<const DrawList*> overlay;  // drawn over everything
  SvgPoints points;
  std::size_t maxPoints = 10000;  // a spray past it is thinned (a slide's is written whole)
  std::optional<SvgSplit> split;  // 2D: the split view's second half
  // core's cells and the shape's edges, as selectable outlines (drawn neither filled nor
  // stroked: the picture itself comes from the draw lists)
  std::vector<std::vector<glm::dvec3>> cells;
  std::vector<std::pair<glm::dvec3, glm::dvec3>> edges;
  // the slide's boxes (logic/teach/slide_layout), in window pixels: the title card, the
  // caption, the Steps window written where the window draws them (writers/svg_slide)
  SlideLayout layout;
  ScreenRect page;        // a slide's letterboxed page: bars beside it (empty: none)
  ScreenRect figureRoom;  // a slide's figure room: the page around it is bare (empty: none)
  Rgba panel;             // the boxes' fill (the window's)
  double rounding = 6.0;
  double layoutPadding = 12.0, layoutSpacing = 6.0;  // the layout's metrics (SlideMetrics)
  double itemSpacingX = 8.0;         // the window's gap between two items on a line (ImGui's)
  double windowPaddingY = 10.0;      // the window's padding above its first line (ImGui's)
  glm::dvec2 cellPadding{4.0, 2.0};  // a table cell's padding (ImGui's): the class rows' gaps
  // the Steps window's colours: each step's line, the current step's highlight and line
  std::vector<Rgba> stepColours;
  Rgba highlight;
  int step = -1;  // the step shown (-1: all)
  // a window over the scene written as it is drawn: its box, opaque, and its SVG inside
  // (the Why O(1) plots); empty: none
  ScreenRect window;
  std::string windowTitle;  // on its title bar, `windowBarHeight` high
  Rgba windowBar;
  double windowBarHeight = 0.0;
  std::string windowSvg;
  // a plots slide's figure (Why O(1) drawn by the slide's layout): written in place of the
  // scene, its labels and the legend; empty: none
  std::string plotsSvg;
  // the legend, in a box whose lower right corner is at `legendCorner` (window pixels)
  std::optional<Legend> legend;
  glm::dvec2 legendCorner{0.0};
  glm::dvec2 legendSize{0.0};     // the window's legend box (zero: sized from its rows)
  double legendScale = 1.0;       // its text, padding and spacing over the body's (a slide's)
  PixelBox labelArea;             // the scene area: labels stay in it
  std::vector<PixelBox> keepOff;  // boxes over the scene the labels keep off where they can
  Rgba textMuted;                 // the legend's counts and subtitle
  // drawn over the labels in window pixels, unprojected (the 3D cube map's zoom inset)
  std::vector<const DrawList*> screen;
};

// the whole SVG document
std::string sceneSvg(const SvgScene& scene);

// writes `text` to `path`; false and `error` (the path and why) on failure
bool writeTextFile(const std::string& path, const std::string& text, std::string& error);

}  // namespace convexloc::viewer
