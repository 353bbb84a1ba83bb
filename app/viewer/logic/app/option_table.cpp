// convexloc-viewer — the viewer's options, one row each: names, value, --help group and
// line, what a bad value needs, whether a slide may set it, and how its values are read.
#include "logic/app/option_table.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <initializer_list>
#include <limits>

#include "convexloc/intersect3d.hpp"
#include "convexloc/methods.hpp"
#include "logic/app/option_values.hpp"
#include "logic/teach/figures.hpp"

namespace convexloc::viewer {
namespace {

constexpr const char* kScene = "Scene";
constexpr const char* kSteps = "Step by step";
constexpr const char* kLectures = "Lectures";
constexpr const char* kView = "View";
constexpr const char* kTeaching = "Why O(1), split view, build";
constexpr const char* kBatch = "Without hands";

// a flag: its member set
template <bool Options::*member>
bool setFlag(const Values&, Options& o, std::string&) {
  o.*member = true;
  return true;
}

// a file or directory name: its member set to the value, which must not be empty
template <std::string Options::*member>
bool setText(const Values& v, Options& o, std::string&) {
  if (v[0].empty()) return false;
  o.*member = v[0];
  return true;
}

// a name, checked where it is used (a preset, a generator, a method)
template <std::optional<std::string> Options::*member>
bool setName(const Values& v, Options& o, std::string&) {
  o.*member = v[0];
  return true;
}

// a text scale from 0.5 to 4
template <float Options::*member>
bool setScale(const Values& v, Options& o, std::string&) {
  double x = 0.0;
  if (!parseDouble(v[0], x) || x < 0.5 || x > 4.0) return false;
  o.*member = static_cast<float>(x);
  return true;
}

// a value that must be one of `choices`
bool oneOf(const std::string& v, std::initializer_list<std::string_view> choices) {
  return std::find(choices.begin(), choices.end(), v) != choices.end();
}

// --slice AXIS=V or none
// --camera AZ,EL,DIST or AZ,EL,fit
bool applyCamera(const Values& v, Options& o, std::string& why) {
  const std::string& t = v[0];
  const std::size_t last = t.rfind(',');
  if (last == std::string::npos) return false;
  const std::string tail = t.substr(last + 1);
  Vec3 q;
  if (tail == "fit") {
    if (!parsePoint3(t.substr(0, last) + ",1", q)) return false;
  } else if (!parsePoint3(t, q) || !(q.z > 0.0)) {
    return false;
  }
  if (!(std::abs(q.y) <= 90.0)) {
    why = "camera: the elevation " + t.substr(t.find(',') + 1, last - t.find(',') - 1) +
          " is not within -90 .. 90 degrees";
    return false;
  }
  o.camera.angles = glm::dvec2(q.x, q.y);
  if (tail != "fit") o.camera.distance = q.z;
  return true;
}

bool applySlice(const Values& v, Options& o, std::string&) {
  if (v[0] == "none") {
    o.hideSlice = true;
    return true;
  }
  const std::string_view s = v[0];
  SlicePlane p;
  if (s.size() < 3 || s[1] != '=' || (s[0] != 'x' && s[0] != 'y' && s[0] != 'z') ||
      !parseDouble(s.substr(2), p.offset))
    return false;
  p.axis = s[0] - 'x';
  o.slice = p;
  o.hideSlice = false;
  return true;
}

// --cell K, K,L or auto
bool applyCell(const Values& v, Options& o, std::string&) {
  std::string_view s = v[0];
  o.cellAuto = s == "auto";
  o.cellSecond.reset();
  if (o.cellAuto) {
    o.cell.reset();
    return true;
  }
  // cell numbers up to 2^40, or what a size_t holds (32 bits in the web page)
  constexpr std::size_t kMost = static_cast<std::size_t>(
      std::min<std::uint64_t>(std::uint64_t{1} << 40, std::numeric_limits<std::size_t>::max()));
  std::size_t k = 0, l = 0;
  const std::size_t comma = s.find(',');
  if (comma != std::string_view::npos && parseInt<std::size_t>(s.substr(comma + 1), 0, kMost, l)) {
    o.cellSecond = l;
    s = s.substr(0, comma);
  }
  if (!parseInt<std::size_t>(s, 0, kMost, k)) return false;
  o.cell = k;
  return true;
}

// --method M: a 2D or a 3D method's name
bool applyMethod(const Values& v, Options& o, std::string& why) {
  if (parseMethod2D(v[0]) || parseMethod3D(v[0])) {
    o.method = v[0];
    return true;
  }
  std::vector<std::string_view> names;
  for (Method2D m : kAllMethods2D) names.push_back(toString(m));
  for (Method3D m : kAllMethods3D) names.push_back(toString(m));
  const std::string near = nearestWord(v[0], names);
  why =
      "--method needs halfplane, wedge, slab, uniform or polar (2D), halfspace, walk or "
      "cubemap (3D), not '" +
      v[0] + "'" + (near.empty() ? "" : " (did you mean " + near + "?)");
  return false;
}

// --why-page P: 2d or 3d, which also opens Why O(1)
bool applyWhyPage(const Values& v, Options& o, std::string& why) {
  constexpr std::string_view kPages[] = {"2d", "3d"};
  if (oneOf(v[0], {kPages[0], kPages[1]})) {
    o.whyPage = v[0];
    o.why = true;
    return true;
  }
  const std::string near = nearestWord(v[0], kPages);
  why = "the Why O(1) page is 2d (regular N-gons) or 3d (geodesic spheres), not '" + v[0] + "'" +
        (near.empty() ? "" : " (did you mean " + near + "?)");
  return false;
}

// --line X1 Y1 X2 Y2: two different points
bool applyLine(const Values& v, Options& o, std::string& why) {
  double c[4] = {};
  for (std::size_t i = 0; i < 4; ++i)
    if (!parseDouble(v[i], c[i])) return false;
  if (c[0] == c[2] && c[1] == c[3]) {
    why = "--line needs two different points";
    return false;
  }
  o.line = std::pair<Vec2, Vec2>{{c[0], c[1]}, {c[2], c[3]}};
  return true;
}

// --plane: three points, not on one line (core's exact test)
bool applyPlane(const Values& v, Options& o, std::string& why) {
  double c[9] = {};
  for (std::size_t i = 0; i < 9; ++i)
    if (!parseDouble(v[i], c[i])) return false;
  const std::array<Vec3, 3> q = {Vec3{c[0], c[1], c[2]}, Vec3{c[3], c[4], c[5]},
                                 Vec3{c[6], c[7], c[8]}};
  if (collinear(q[0], q[1], q[2])) {
    why = "--plane needs three points not on one line (these define no plane)";
    return false;
  }
  o.plane = q;
  return true;
}

// --size WxH
bool applySize(const Values& v, Options& o, std::string&) {
  const std::string_view s = v[0];
  const std::size_t x = s.find('x');
  return x != std::string_view::npos && parseInt<int>(s.substr(0, x), 64, 16384, o.width) &&
         parseInt<int>(s.substr(x + 1), 64, 16384, o.height);
}

// --page WxH: a slide's page in units, 160 to 16384 each way
bool applyPage(const Values& v, Options& o, std::string&) {
  const std::string_view s = v[0];
  const std::size_t x = s.find('x');
  int w = 0, h = 0;
  if (x == std::string_view::npos || !parseInt<int>(s.substr(0, x), 160, 16384, w) ||
      !parseInt<int>(s.substr(x + 1), 160, 16384, h))
    return false;
  o.page = std::pair{w, h};
  return true;
}

// --figure N: its options, which later ones override, and its caption unless one was given
bool applyFigure(const Values& v, Options& o, std::string& why) {
  int n = 0;
  if (!parseInt<int>(v[0], 1, kFigureCount, n)) return false;
  const std::vector<std::string> words = figureArgs(n);
  const std::vector<std::string_view> args(words.begin(), words.end());
  if (std::string e = parseInto(args, o); !e.empty()) {
    why = "--figure: " + e;
    return false;
  }
  o.figure = n;
  if (o.caption.empty()) o.caption = std::string(figure(n).caption);
  return true;
}

const OptionSpec kOptions[] = {
    // === Scene
    {"--method", "M", 1, kScene,
     "halfplane | wedge | slab | uniform | polar (2D); halfspace | walk | cubemap (3D)",
     "a method name", false, applyMethod},
    {"--hull", "", 0, kScene,
     "open a mesh file (.off, .obj, .stl, .ply) as the convex hull of its vertices, its faces "
     "ignored (a mesh whose rounded coordinates left faces not exactly planar)",
     "", false, setFlag<&Options::hull>},
    {"--resolution", "R", 1, kScene,
     "uniform slabs, polar slabs per octant, cube grid size (0: automatic)",
     "a whole number from 0 (automatic) to 2^26", false,
     [](const Values& v, Options& o, std::string&) {
       std::uint32_t x = 0;
       if (!parseInt<std::uint32_t>(v[0], 0, 1u << 26, x)) return false;
       o.resolution = x;
       return true;
     }},
    {"--preset", "NAME", 1, kScene,
     "degenerate gallery: sliver, tiny-edges, large-offset, collinear-duplicate, "
     "thin-slab, small-gap, tiny-faces, coplanar-faces",
     "a name", false, setName<&Options::preset>},
    {"--generate", "KIND", 1, kScene,
     "a generated shape (regular, random, ellipse, sliver, ...) of --n N and --seed S",
     "a kind (regular, random, ellipse, ...)", false, setName<&Options::generate>},
    {"--n", "N", 1, kScene, "the generated shape's size", "a whole number >= 3", false,
     [](const Values& v, Options& o, std::string&) {
       std::size_t x = 0;
       if (!parseCount(v[0], x) || x < 3) return false;
       o.n = x;
       return true;
     }},
    {"--seed", "S", 1, kScene, "the generated shape's seed, and the spray's", "a whole number",
     false,
     [](const Values& v, Options& o, std::string&) {
       std::uint64_t x = 0;
       if (!parseInt<std::uint64_t>(v[0], 0, ~std::uint64_t{0}, x)) return false;
       o.seed = x;
       return true;
     }},
    {"--spray", "N", 1, kScene, "spray N points (0 .. 10^7; 1e6 works) classified by the locator",
     "a count from 0 to 10^7 (1000, 1e6, ...)", false,
     [](const Values& v, Options& o, std::string&) {
       std::size_t x = 0;
       if (!parseCount(v[0], x) || x > 10000000) return false;
       o.spray = x;
       return true;
     }},
    {"--near-boundary", "", 0, kScene,
     "spray core's hard cases on and next to the boundary instead", "", false,
     setFlag<&Options::nearBoundary>},
    {"--show", "WHICH", 1, kScene, "all | inside | outside | boundary points",
     "all, inside, outside or boundary", false,
     [](const Values& v, Options& o, std::string&) {
       if (!oneOf(v[0], {"all", "inside", "outside", "boundary"})) return false;
       o.show = v[0];
       return true;
     }},
    {"--compare", "", 0, kScene, "time every method on the spray at start (see the Method panel)",
     "", false, setFlag<&Options::compare>},
    {"--probe", "X,Y[,Z]", 1, kScene, "place a point there and show its trace", "X,Y or X,Y,Z",
     false,
     [](const Values& v, Options& o, std::string&) {
       Vec3 q;
       Vec2 p;
       if (parsePoint3(v[0], q))
         o.probe3 = q;
       else if (parsePoint(v[0], p))
         o.probe = p;
       else
         return false;
       return true;
     }},
    {"--hover", "X,Y", 1, kScene, "2D: hover there (shows the cell under it)", "X,Y", false,
     [](const Values& v, Options& o, std::string&) {
       Vec2 p;
       if (!parsePoint(v[0], p)) return false;
       o.hover = p;
       return true;
     }},
    {"--line", "X1 Y1 X2 Y2", 4, kScene,
     "2D: the Lines mode (the dual problem) with the line through "
     "(X1, Y1) and (X2, Y2)",
     "X1 Y1 X2 Y2", false, applyLine},
    {"--view", "X,Y,W", 1, kScene, "2D: look at (X, Y), the scene W wide (zoom in on tiny things)",
     "X,Y,WIDTH with WIDTH > 0", false,
     [](const Values& v, Options& o, std::string&) {
       Vec3 q;
       if (!parsePoint3(v[0], q) || !(q.z > 0.0)) return false;
       o.view = AskedView{{q.x, q.y}, q.z};
       return true;
     }},
    {"--camera", "AZ,EL,DIST|AZ,EL,fit", 1, kScene,
     "3D: the eye at azimuth AZ and elevation EL (degrees) from the target, DIST away or as "
     "the fit puts it; a slide with a query otherwise looks across its ray",
     "AZ,EL,DIST with DIST > 0, or AZ,EL,fit", false, applyCamera},
    {"--look", "X,Y,Z", 1, kScene, "3D: the camera looks at (X, Y, Z)", "X,Y,Z", false,
     [](const Values& v, Options& o, std::string&) {
       Vec3 q;
       if (!parsePoint3(v[0], q)) return false;
       o.camera.look = glm::dvec3(q.x, q.y, q.z);
       return true;
     }},
    {"--3d", "", 0, kScene, "the 3D scene (a polyhedron with the cube map) without a file", "",
     false, setFlag<&Options::solid>},
    {"--slice", "AXIS=V|none", 1, kScene, "3D: the slicing plane, e.g. z=0.25; none hides it",
     "AXIS=VALUE, e.g. z=0.25, or none", false, applySlice},
    {"--cell", "K[,L]|auto", 1, kScene,
     "3D: pin cube-map cell K (its pyramid and the faces it lists), and L "
     "beside it; auto: a cell listing one face and one listing the most",
     "a cell index, two (K,L) or auto", false, applyCell},
    {"--y-gap", "", 0, kScene,
     "2D: mark the smallest y-gap between vertices and the uniform slab count the "
     "paper's rule (ymax - ymin) / gap needs",
     "", false, setFlag<&Options::yGap>},
    {"--plane", "X1 Y1 Z1 X2 Y2 Z2 X3 Y3 Z3", 9, kScene,
     "3D: the Planes mode (the dual problem) with the "
     "plane through the three points (not on one line); implies --3d",
     "X1 Y1 Z1 X2 Y2 Z2 X3 Y3 Z3", false, applyPlane},
    // === Step by step
    {"--step", "K", 1, kSteps,
     "show step K (1 = the first) of the placed point's query, highlighted in the "
     "drawing and the Steps window (beyond the last: the last; 0 or -1: all steps)",
     "a step number from 1 (0 or -1: all steps)", false,
     [](const Values& v, Options& o, std::string&) {
       return parseInt<int>(v[0], -1, 1000000, o.step);
     }},
    {"--paper", "", 0, kSteps,
     "paper-faithful mode: polar and cubemap queries without the radius filter, so "
     "the cell's edges (faces) decide (key R toggles it)",
     "", false, setFlag<&Options::paper>},
    // === Lectures
    {"--figure", "N", 1, kLectures,
     "the paper's figure N (1..7) as a slide; later options override it",
     "a figure number from 1 to 7", false, applyFigure},
    {"--lecture", "FILE", 1, kLectures,
     "a slide show (.lecture, see docs/viewer.md): PageDown / PageUp, "
     "Home / End move through it",
     "a .lecture file", true, setText<&Options::lecture>},
    {"--slide", "K", 1, kLectures,
     "with --lecture: start at slide K (1 = the first; beyond the last: the last)",
     "a slide number from 1", false,
     [](const Values& v, Options& o, std::string&) {
       return parseInt<int>(v[0], 1, 1000000, o.slide);
     }},
    {"--export", "DIR", 1, kLectures,
     "with --lecture or --figure: write every slide as DIR/slide-NN.png "
     "and DIR/slide-NN.svg (PNG and SVG), and exit; a slide with problems is reported and "
     "left out, the exit code then 1",
     "a directory", true, setText<&Options::exportDir>},
    {"--export-first", "", 0, kLectures,
     "with --export: also write each slide's first frame after it is shown, as "
     "DIR/slide-NN-first.png (a slide's layout and camera are final on it)",
     "", true, setFlag<&Options::exportFirst>},
    {"--check", "FILE", 1, kLectures,
     "list every problem of the lecture FILE as FILE:LINE: problem and exit 1 (0 and a "
     "one-line summary when it has none); needs no display",
     "a .lecture file", true, setText<&Options::checkFile>},
    {"--notes", "FILE", 1, kLectures,
     "print the lecture FILE's speaker notes (slide number, title, notes) and exit",
     "a .lecture file", true, setText<&Options::notesFile>},
    // === View
    {"--theme", "dark|light", 1, kView, "colours (default dark)", "dark or light", false,
     [](const Values& v, Options& o, std::string&) {
       if (!oneOf(v[0], {"dark", "light"})) return false;
       o.theme = v[0] == "dark" ? Theme::Dark : Theme::Light;
       return true;
     }},
    {"--ui-scale", "F", 1, kView,
     "the panels' text scale on a HiDPI web page (its pixel ratio; the page passes it): "
     "slides already scale with their page",
     "a number from 0.5 to 4", false, setScale<&Options::uiScale>},
    {"--font-scale", "F", 1, kView,
     "text size, 0.5 .. 4 (default 1); with --lecture, a zoom over the slides' own",
     "a number from 0.5 to 4", false, setScale<&Options::fontScale>},
    {"--page", "WxH", 1, kView,
     "a slide's page in units (default 1920x1080): slides keep its aspect, letterboxed, "
     "at any window size",
     "WIDTHxHEIGHT, e.g. 1600x1200", false, applyPage},
    {"--hide-ui", "", 0, kView, "only the scene and its legend", "", false,
     setFlag<&Options::hideUi>},
    {"--show-ui", "", 0, kView,
     "the panels shown (the default; a lecture's slide with a table to read shows "
     "them, over a figure's own --hide-ui)",
     "", false,
     [](const Values&, Options& o, std::string&) {
       o.showUi = true;
       o.hideUi = false;
       return true;
     }},
    {"--present", "", 0, kView,
     "presentation mode (P): panels hidden, lines and labels sized with the text, "
     "the legend movable (drag it)",
     "", false, setFlag<&Options::present>},
    {"--caption", "TEXT", 1, kView, "a caption written large under the scene", "a text", false,
     [](const Values& v, Options& o, std::string&) {
       o.caption = v[0];
       return true;
     }},
    {"--no-legend", "", 0, kView, "hide the legend (G)", "", false, setFlag<&Options::noLegend>},
    {"--no-steps", "", 0, kView, "hide the Steps window (the drawing still shows the step)", "",
     false, setFlag<&Options::noSteps>},
    {"--size", "WxH", 1, kView, "window size in pixels (default 1440x900)",
     "WIDTHxHEIGHT, e.g. 1024x768", true, applySize},
    {"--shaders", "DIR", 1, kView, "load the GLSL shaders from DIR", "a directory", true,
     [](const Values& v, Options& o, std::string&) {
       o.shaderDir = v[0];
       return true;
     }},
    {"--samples", "N", 1, kView,
     "multisampling (default 4 on a GPU, 0 on a software renderer, where lines and "
     "points are anti-aliased by the shaders alone)",
     "a whole number from 0 (no anti-aliasing) to 16", true,
     [](const Values& v, Options& o, std::string&) {
       return parseInt<int>(v[0], 0, 16, o.samples);
     }},
    // === Why O(1), split view, build
    {"--why", "", 0, kTeaching,
     "open the Why O(1) window and measure every method on regular N-gons", "", false,
     setFlag<&Options::why>},
    {"--why-page", "PAGE", 1, kTeaching,
     "open Why O(1) on its page PAGE: 2d (regular N-gons) or 3d (geodesic spheres); a "
     "lecture's slide says `why 2d` or `why 3d`",
     "2d or 3d", false, applyWhyPage},
    {"--why-max", "N", 1, kTeaching, "the largest N measured (8 .. 10^6, default 10^6)",
     "a whole number from 8 to 10^6", false,
     [](const Values& v, Options& o, std::string&) {
       return parseCount(v[0], o.whyMost) && o.whyMost >= 8 && o.whyMost <= 1000000;
     }},
    {"--why-svg", "FILE", 1, kTeaching, "measure without a window, write the plots as SVG and exit",
     "a file name", false, setText<&Options::whySvg>},
    {"--why-record", "FILE", 1, kTeaching,
     "measure without a window, write the timings to FILE (text, see docs/viewer.md) and exit",
     "a file name", true, setText<&Options::whyRecord>},
    {"--why-from", "FILE", 1, kTeaching,
     "Why O(1) from timings recorded by --why-record, not measured (a slide that does not "
     "depend on the machine's load); with --why-svg, the plots of that file",
     "a file written by --why-record", false,
     [](const Values& v, Options& o, std::string&) {
       if (v[0].empty()) return false;
       o.whyFrom = v[0];
       o.why = true;
       return true;
     }},
    {"--split", "M", 1, kTeaching, "2D: the scene twice, method M in the right half, one camera",
     "a 2D method name", false, setName<&Options::split>},
    {"--build-step", "K", 1, kTeaching,
     "the cells after receiving edges (3D: faces) 0 .. K-1 (build "
     "animation)",
     "a whole number", false,
     [](const Values& v, Options& o, std::string&) {
       std::size_t k = 0;
       if (!parseCount(v[0], k)) return false;
       o.buildStep = k;
       return true;
     }},
    // === Without hands
    {"--screenshot", "FILE", 1, kBatch,
     "render --frames frames (default 3), write FILE (PNG) and exit", "a file name", true,
     setText<&Options::screenshot>},
    {"--svg", "FILE", 1, kBatch, "the same, writing the scene as SVG (vector; both may be given)",
     "a file name", true, setText<&Options::svg>},
    {"--frames", "N", 1, kBatch, "render N frames, print the mean frame time and exit",
     "a whole number from 1 to 100000", true,
     [](const Values& v, Options& o, std::string&) {
       return o.framesGiven = parseInt<int>(v[0], 1, 100000, o.frames);
     }},
    {"--animate", "", 0, kBatch, "move the camera every frame (to time frames under a hand)", "",
     true, setFlag<&Options::animate>},
    {"--no-xvfb", "", 0, kBatch, "without a display, fail instead of re-running under xvfb-run", "",
     true, setFlag<&Options::noXvfb>},
    {"-h,--help", "", 0, kBatch, "this text", "", true, setFlag<&Options::help>},
    {"--version", "", 0, kBatch, "the version", "", true, setFlag<&Options::version>},
};

}  // namespace

std::span<const OptionSpec> optionTable() {
  return kOptions;
}

}  // namespace convexloc::viewer
