// convexloc-viewer — the command line: what to open and how, so that a scene can be set
// up and rendered to a PNG without hands (figures for slides, smoke tests).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <utility>

#include "convexloc/geometry.hpp"
#include "logic/base/colour.hpp"
#include "logic/view/camera3d.hpp"

namespace convexloc::viewer {

struct Options {
  std::string shape;                  // a .txt polygon or an .off/.obj/.stl/.ply polyhedron
  std::optional<std::string> method;  // halfplane..polar (2D), halfspace|walk|cubemap (3D)
  std::optional<std::uint32_t> resolution;
  std::optional<std::string> preset;    // a degenerate-gallery name
  std::optional<std::string> generate;  // a core generator kind
  std::optional<std::size_t> n;         // its size
  std::optional<std::uint64_t> seed;    // its seed, and the spray's
  std::optional<std::size_t> spray;     // how many points to spray
  bool nearBoundary = false;            // spray core's hard cases near the boundary
  std::optional<std::string> show;      // all | inside | outside | boundary
  std::optional<Vec2> probe;            // place a point there (2D world coordinates)
  std::optional<Vec3> probe3;           // place a point there (3D)
  std::optional<SlicePlane> slice;      // 3D: the slicing plane
  std::optional<std::size_t> cell;      // 3D: pin this cube-map cell
  bool solid = false;                   // --3d: the 3D scene
  std::optional<Vec2> hover;            // hover there (2D world coordinates)
  std::optional<AskedView> view;        // 2D: look at (x, y) showing a width w of the world
  AskedCamera camera;                   // 3D: --camera and --look
  // 2D: the Lines mode (the dual problem), with the line through these two points
  std::optional<std::pair<Vec2, Vec2>> line;
  // 3D: the Planes mode (the dual problem in 3D), with the plane through these three points
  std::optional<std::array<Vec3, 3>> plane;
  Theme theme = Theme::Dark;
  float fontScale = 1.0f;
  // --ui-scale: a HiDPI web page's pixel ratio, the panels' text grown by it (a slide's text
  // already grows with its page, which is laid out in the canvas's device pixels)
  float uiScale = 1.0f;
  // a slide's page in units (--page WxH): its aspect is the slides' (default 1920x1080)
  std::optional<std::pair<int, int>> page;
  bool hideUi = false;
  std::string screenshot;          // render, write this PNG and exit
  int frames = 3;                  // frames rendered before the screenshot or exit
  bool framesGiven = false;        // --frames without --screenshot: time and exit
  int width = 1440, height = 900;  // window size
  std::string shaderDir;           // overrides the built-in shader directory
  int samples = -1;                // MSAA samples; 0 none; -1: 4, none in software
  bool noXvfb = false;             // do not re-run under xvfb-run without a display
  bool animate = false;            // move the camera every frame (timing)
  bool compare = false;            // time every method at start (the Method panel)
  bool help = false, version = false;
  // a query, step by step
  int step = -1;       // --step K: the placed point's step K shown, from 1 (0, -1: all steps)
  bool paper = false;  // --paper: traces without the radius filter (the paper's query)
  // presentation and vector figures
  std::string svg;       // render, write the scene as this SVG and exit (with --screenshot too)
  bool present = false;  // presentation mode: panels hidden, caption, legend movable
  bool noLegend = false;
  bool hull = false;    // --hull: mesh files open as the convex hull of their vertices
  std::string caption;  // a caption written large over the scene
  // lectures and the paper's figures
  std::optional<int> figure;              // --figure N: start from the paper's figure N
  std::string lecture;                    // --lecture FILE: a slide show
  int slide = 1;                          // --slide K: the lecture starts at slide K
  std::string exportDir;                  // --export DIR: every slide (or the figure) as PNG
  bool exportFirst = false;               // --export-first: each slide's first frame too
  std::string checkFile;                  // --check FILE: list a lecture's problems and exit
  std::string notesFile;                  // --notes FILE: print a lecture's notes and exit
  bool yGap = false;                      // 2D: mark the smallest y-gap and its slab count
  bool hideSlice = false;                 // 3D: --slice none
  bool cellAuto = false;                  // 3D: --cell auto (a one-face and a crowded cell)
  std::optional<std::size_t> cellSecond;  // 3D: --cell K,L pins L beside K
  // Why O(1), the split view, the build animation
  bool why = false;                  // open the Why O(1) window and start measuring
  std::string whySvg;                // measure without a window, write this SVG, exit
  std::size_t whyMost = 1000000;     // the largest N measured
  std::string whyFrom;               // Why O(1) from this recorded file, not measured
  std::string whyRecord;             // measure without a window, record to this file, exit
  std::string whyPage;               // Why O(1)'s page: "2d" or "3d" (empty: the scene's dimension)
  std::optional<std::string> split;  // 2D: this method beside the current one
  std::optional<std::size_t> buildStep;  // 2D: the build animation at this step
  // a lecture's slide with the panels shown (a table to read); excludes --hide-ui, --present
  bool showUi = false;
  bool noSteps = false;  // the Steps window hidden (the drawing still shows the step)
};

// the result of parsing: options, or the reason they are wrong
struct ParsedOptions {
  Options options;
  std::string error;  // empty when fine
};

// parses argv[1..] (without the program name)
ParsedOptions parseOptions(std::span<const std::string_view> args);

// the --help text, from the options' one declaration (logic/app/option_table.cpp)
std::string usageText();

// true for an option (a lecture key: its name without the dashes) that sets the window or
// the run, which no slide may set; false for a slide's key or an unknown one
bool setsTheRun(std::string_view key);

}  // namespace convexloc::viewer
