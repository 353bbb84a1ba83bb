// convexloc-viewer — command-line parsing.
#include "logic/app/options.hpp"

#include <charconv>
#include <cmath>
#include <vector>

#include "logic/teach/figures.hpp"

#include "convexloc/intersect3d.hpp"

namespace convexloc::viewer {
namespace {

// a whole number in [lo, hi]
template <class T>
bool parseInt(std::string_view s, T lo, T hi, T& out) {
  T v{};
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size() || v < lo || v > hi) return false;
  out = v;
  return true;
}

// a finite double
bool parseDouble(std::string_view s, double& out) {
  double v = 0.0;
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size() || !std::isfinite(v)) return false;
  out = v;
  return true;
}

// "X,Y"
bool parsePoint(std::string_view s, Vec2& out) {
  const std::size_t comma = s.find(',');
  if (comma == std::string_view::npos) return false;
  return parseDouble(s.substr(0, comma), out.x) && parseDouble(s.substr(comma + 1), out.y);
}

// "X,Y,Z"
bool parsePoint3(std::string_view s, Vec3& out) {
  const std::size_t a = s.find(','), b = a == std::string_view::npos ? a : s.find(',', a + 1);
  if (b == std::string_view::npos) return false;
  return parseDouble(s.substr(0, a), out.x) && parseDouble(s.substr(a + 1, b - a - 1), out.y) &&
         parseDouble(s.substr(b + 1), out.z);
}

// a count written plainly or as 1e6
bool parseCount(std::string_view s, std::size_t& out) {
  if (parseInt<std::size_t>(s, 0, std::size_t{1} << 26, out)) return true;
  double d = 0.0;
  if (!parseDouble(s, d) || d < 0.0 || d > static_cast<double>(std::size_t{1} << 26) ||
      d != std::floor(d))
    return false;
  out = static_cast<std::size_t>(d);
  return true;
}

// the options that take no value
struct Flag {
  std::string_view name;
  bool Options::*member;
};
constexpr Flag kFlags[] = {
    {"-h", &Options::help},           {"--help", &Options::help},
    {"--version", &Options::version}, {"--near-boundary", &Options::nearBoundary},
    {"--hide-ui", &Options::hideUi},  {"--no-xvfb", &Options::noXvfb},
    {"--animate", &Options::animate}, {"--compare", &Options::compare},
    {"--3d", &Options::solid},       {"--why", &Options::why},
    // lectures and the paper's figures
    {"--y-gap", &Options::yGap},
};

// The arguments, read one at a time: an option's value is the next argument. A step
// returns true when the argument was its option, with `error` set on a bad value.
class ArgReader {
 public:
  explicit ArgReader(std::span<const std::string_view> args) : args_(args) {}
  bool done() const { return next_ >= args_.size(); }
  std::string_view take() { return args_[next_++]; }
  // the value of the option just taken, or false when there is none
  bool value(std::string_view& v) {
    if (done()) return false;
    v = take();
    return true;
  }
  // records why the option just taken is wrong; true (it was matched)
  bool fail(std::string why) {
    error = std::move(why);
    return true;
  }
  std::string error;

 private:
  std::span<const std::string_view> args_;
  std::size_t next_ = 0;
};

// a flag from kFlags
bool flagOption(std::string_view a, Options& o) {
  for (const Flag& f : kFlags)
    if (a == f.name) {
      o.*f.member = true;
      return true;
    }
  return false;
}

// --method, --resolution, --preset, --generate, --n, --seed, --spray, --show
bool sceneOption(std::string_view a, ArgReader& in, Options& o) {
  std::string_view v;
  if (a == "--method") {
    if (!in.value(v)) return in.fail("--method needs a method name");
    o.method = std::string(v);
  } else if (a == "--resolution") {
    std::uint32_t x = 0;
    if (!in.value(v) || !parseInt<std::uint32_t>(v, 0, 1u << 26, x))
      return in.fail("--resolution needs a whole number from 0 (automatic) to 2^26");
    o.resolution = x;
  } else if (a == "--preset") {
    if (!in.value(v)) return in.fail("--preset needs a name");
    o.preset = std::string(v);
  } else if (a == "--generate") {
    if (!in.value(v)) return in.fail("--generate needs a kind (regular, random, ellipse, ...)");
    o.generate = std::string(v);
  } else if (a == "--n") {
    std::size_t x = 0;
    if (!in.value(v) || !parseCount(v, x) || x < 3) return in.fail("--n needs a whole number >= 3");
    o.n = x;
  } else if (a == "--seed") {
    std::uint64_t x = 0;
    if (!in.value(v) || !parseInt<std::uint64_t>(v, 0, ~std::uint64_t{0}, x))
      return in.fail("--seed needs a whole number");
    o.seed = x;
  } else {
    return false;
  }
  return true;
}

// --spray, --show
bool sprayOption(std::string_view a, ArgReader& in, Options& o) {
  std::string_view v;
  if (a == "--spray") {
    std::size_t x = 0;
    if (!in.value(v) || !parseCount(v, x) || x > 10000000)
      return in.fail("--spray needs a count from 0 to 10^7 (1000, 1e6, ...)");
    o.spray = x;
  } else if (a == "--show") {
    if (!in.value(v) || (v != "all" && v != "inside" && v != "outside" && v != "boundary"))
      return in.fail("--show needs all, inside, outside or boundary");
    o.show = std::string(v);
  } else {
    return false;
  }
  return true;
}

// --probe, --hover, --line, --view: places in the scene
bool placeOption(std::string_view a, ArgReader& in, Options& o) {
  std::string_view v;
  Vec2 p;
  Vec3 q;
  if (a == "--probe") {
    if (!in.value(v)) return in.fail("--probe needs X,Y or X,Y,Z");
    if (parsePoint3(v, q))
      o.probe3 = q;
    else if (parsePoint(v, p))
      o.probe = p;
    else
      return in.fail("--probe needs X,Y or X,Y,Z");
  } else if (a == "--hover") {
    if (!in.value(v) || !parsePoint(v, p)) return in.fail("--hover needs X,Y");
    o.hover = p;
  } else if (a == "--line") {
    double c[4] = {};
    for (double& x : c)
      if (!in.value(v) || !parseDouble(v, x)) return in.fail("--line needs X1 Y1 X2 Y2");
    if (c[0] == c[2] && c[1] == c[3]) return in.fail("--line needs two different points");
    o.line = std::pair<Vec2, Vec2>{{c[0], c[1]}, {c[2], c[3]}};
  } else if (a == "--view") {
    if (!in.value(v) || !parsePoint3(v, q) || !(q.z > 0.0))
      return in.fail("--view needs X,Y,WIDTH with WIDTH > 0");
    o.view = q;
  } else {
    return false;
  }
  return true;
}

// --slice, --cell: the 3D scene's plane and pinned cell
bool solidOption(std::string_view a, ArgReader& in, Options& o) {
  std::string_view v;
  if (a == "--slice") {
    // AXIS=VALUE, e.g. z=0.25
    SlicePlane s;
    if (in.value(v) && v == "none") {
      o.hideSlice = true;
      return true;
    }
    if (v.size() < 3 || v[1] != '=' || (v[0] != 'x' && v[0] != 'y' && v[0] != 'z') ||
        !parseDouble(v.substr(2), s.offset))
      return in.fail("--slice needs AXIS=VALUE, e.g. z=0.25, or none");
    s.axis = v[0] - 'x';
    o.slice = s;
    o.hideSlice = false;
  } else if (a == "--cell") {
    std::size_t k = 0, l = 0;
    const bool given = in.value(v);
    const std::size_t comma = given ? v.find(',') : std::string_view::npos;
    o.cellAuto = given && v == "auto";
    o.cellSecond.reset();
    if (o.cellAuto) {
      o.cell.reset();
      return true;
    }
    if (comma != std::string_view::npos &&
        parseInt<std::size_t>(v.substr(comma + 1), 0, std::size_t{1} << 40, l)) {
      o.cellSecond = l;
      v = v.substr(0, comma);
    }
    if (!given || !parseInt<std::size_t>(v, 0, std::size_t{1} << 40, k))
      return in.fail("--cell needs a cell index, two (K,L) or auto");
    o.cell = k;
  } else if (a == "--plane") {
    // the Planes mode: three points, not on one line (core's exact test)
    double c[9] = {};
    for (double& x : c)
      if (!in.value(v) || !parseDouble(v, x))
        return in.fail("--plane needs X1 Y1 Z1 X2 Y2 Z2 X3 Y3 Z3");
    const std::array<Vec3, 3> q = {Vec3{c[0], c[1], c[2]}, Vec3{c[3], c[4], c[5]},
                                   Vec3{c[6], c[7], c[8]}};
    if (collinear(q[0], q[1], q[2]))
      return in.fail("--plane needs three points not on one line (these define no plane)");
    o.plane = q;
  } else {
    return false;
  }
  return true;
}

// --theme, --font-scale, --size, --samples, --shaders: how the window looks
bool viewOption(std::string_view a, ArgReader& in, Options& o) {
  std::string_view v;
  if (a == "--theme") {
    if (!in.value(v) || (v != "dark" && v != "light"))
      return in.fail("--theme needs dark or light");
    o.theme = v == "dark" ? Theme::Dark : Theme::Light;
  } else if (a == "--font-scale") {
    double x = 0.0;
    if (!in.value(v) || !parseDouble(v, x) || x < 0.5 || x > 4.0)
      return in.fail("--font-scale needs a number from 0.5 to 4");
    o.fontScale = static_cast<float>(x);
  } else if (a == "--size") {
    const std::size_t x = in.value(v) ? v.find('x') : std::string_view::npos;
    if (x == std::string_view::npos || !parseInt<int>(v.substr(0, x), 64, 16384, o.width) ||
        !parseInt<int>(v.substr(x + 1), 64, 16384, o.height))
      return in.fail("--size needs WIDTHxHEIGHT, e.g. 1024x768");
  } else if (a == "--samples") {
    if (!in.value(v) || !parseInt<int>(v, 0, 16, o.samples))
      return in.fail("--samples needs a whole number from 0 (no anti-aliasing) to 16");
  } else if (a == "--shaders") {
    if (!in.value(v)) return in.fail("--shaders needs a directory");
    o.shaderDir = std::string(v);
  } else {
    return false;
  }
  return true;
}

// --screenshot, --frames: rendering without hands
bool batchOption(std::string_view a, ArgReader& in, Options& o) {
  std::string_view v;
  if (a == "--screenshot") {
    if (!in.value(v) || v.empty()) return in.fail("--screenshot needs a file name");
    o.screenshot = std::string(v);
  } else if (a == "--frames") {
    if (!in.value(v) || !parseInt<int>(v, 1, 100000, o.frames))
      return in.fail("--frames needs a whole number from 1 to 100000");
    o.framesGiven = true;
  } else {
    return false;
  }
  return true;
}

// --step, --paper: the placed point's query step by step
bool stepOption(std::string_view a, ArgReader& in, Options& o) {
  std::string_view v;
  if (a == "--step") {
    if (!in.value(v) || !parseInt<int>(v, -1, 1000000, o.step))
      return in.fail("--step needs a step number from 1 (0 or -1: all steps)");
  } else if (a == "--paper") {
    o.paper = true;
  } else {
    return false;
  }
  return true;
}

// --svg, --present, --caption, --no-legend: slides and vector figures
bool presentOption(std::string_view a, ArgReader& in, Options& o) {
  std::string_view v;
  if (a == "--svg") {
    if (!in.value(v) || v.empty()) return in.fail("--svg needs a file name");
    o.svg = std::string(v);
  } else if (a == "--caption") {
    if (!in.value(v)) return in.fail("--caption needs a text");
    o.caption = std::string(v);
  } else if (a == "--present") {
    o.present = true;
  } else if (a == "--no-legend") {
    o.noLegend = true;
  } else if (a == "--show-ui") {
    // the panels shown, over a figure's own --hide-ui given before it
    o.showUi = true;
    o.hideUi = false;
  } else if (a == "--no-steps") {
    o.noSteps = true;
  } else {
    return false;
  }
  return true;
}

// --why-svg, --why-max, --split, --build-step: Why O(1), the split view, the build animation
bool teachingOption(std::string_view a, ArgReader& in, Options& o) {
  std::string_view v;
  if (a == "--why-svg") {
    if (!in.value(v) || v.empty()) return in.fail("--why-svg needs a file name");
    o.whySvg = std::string(v);
  } else if (a == "--why-max") {
    if (!in.value(v) || !parseCount(v, o.whyMost) || o.whyMost < 8 || o.whyMost > 1000000)
      return in.fail("--why-max needs a whole number from 8 to 10^6");
  } else if (a == "--split") {
    if (!in.value(v)) return in.fail("--split needs a 2D method name");
    o.split = std::string(v);
  } else if (a == "--build-step") {
    std::size_t k = 0;
    if (!in.value(v) || !parseCount(v, k)) return in.fail("--build-step needs a whole number");
    o.buildStep = k;
  } else {
    return false;
  }
  return true;
}

// an unknown option, or the shape file (only one)
std::string shapeArgument(std::string_view a, Options& o) {
  if (!a.empty() && a[0] == '-' && a != "-")
    return "unknown option " + std::string(a) + " (see --help)";
  if (!o.shape.empty()) return "more than one shape given: " + o.shape + " and " + std::string(a);
  o.shape = std::string(a);
  return {};
}

// options that exclude each other
std::string conflicts(const Options& o) {
  if (!o.shape.empty() && (o.preset || o.generate))
    return "give a shape file, --preset or --generate, not several";
  if (o.preset && o.generate) return "give --preset or --generate, not both";
  if (!o.exportDir.empty() && o.lecture.empty() && !o.figure)
    return "--export needs --lecture FILE or --figure N";
  if (o.showUi && (o.hideUi || o.present))
    return "--show-ui shows the panels: give it or --hide-ui / --present, not both";
  return {};
}

bool lectureOption(std::string_view a, ArgReader& in, Options& o);

// every argument into `o`, in order; the first problem, or an empty string
std::string parseInto(std::span<const std::string_view> args, Options& o) {
  ArgReader in(args);
  while (!in.done() && in.error.empty()) {
    const std::string_view a = in.take();
    if (!flagOption(a, o) && !sceneOption(a, in, o) && !sprayOption(a, in, o) &&
        !placeOption(a, in, o) && !solidOption(a, in, o) && !viewOption(a, in, o) &&
        !batchOption(a, in, o) && !stepOption(a, in, o) && !presentOption(a, in, o) &&
        !lectureOption(a, in, o) && !teachingOption(a, in, o))
      in.error = shapeArgument(a, o);
  }
  return in.error;
}

// --figure N (its options, which later ones override), --lecture, --export
bool lectureOption(std::string_view a, ArgReader& in, Options& o) {
  std::string_view v;
  if (a == "--figure") {
    int n = 0;
    if (!in.value(v) || !parseInt<int>(v, 1, kFigureCount, n))
      return in.fail("--figure needs a figure number from 1 to " + std::to_string(kFigureCount));
    const std::vector<std::string> words = figureArgs(n);
    const std::vector<std::string_view> args(words.begin(), words.end());
    if (std::string e = parseInto(args, o); !e.empty()) return in.fail("--figure: " + e);
    o.figure = n;
    // the figure's caption, unless one was given: a --caption before or after wins
    if (o.caption.empty()) o.caption = std::string(figure(n).caption);
  } else if (a == "--lecture") {
    if (!in.value(v) || v.empty()) return in.fail("--lecture needs a .lecture file");
    o.lecture = std::string(v);
  } else if (a == "--export") {
    if (!in.value(v) || v.empty()) return in.fail("--export needs a directory");
    o.exportDir = std::string(v);
  } else {
    return false;
  }
  return true;
}

}  // namespace

ParsedOptions parseOptions(std::span<const std::string_view> args) {
  ParsedOptions r;
  r.error = parseInto(args, r.options);
  if (r.error.empty()) r.error = conflicts(r.options);
  return r;
}

std::string usageText() {
  return R"(convexloc-viewer: see how point location in a convex polygon or polyhedron works

Usage: convexloc-viewer [SHAPE] [options]

  SHAPE                 a polygon (.txt, one vertex 'x y' per line) or a polyhedron (.off, .obj);
                        without one, a random polygon with the paper's polar slabs
Scene:
  --method M            halfplane | wedge | slab | uniform | polar (2D);
                        halfspace | walk | cubemap (3D)
  --resolution R        uniform slabs, polar slabs per octant, cube grid size (0: automatic)
  --preset NAME         degenerate gallery: sliver, tiny-edges, large-offset,
                        collinear-duplicate, thin-slab, small-gap, tiny-faces,
                        coplanar-faces
  --generate KIND       a generated shape (regular, random, ellipse, sliver, ...) with
  --n N --seed S        its size and seed
  --spray N             spray N points (0 .. 10^7; 1e6 works) classified by the locator
  --near-boundary       spray core's hard cases on and next to the boundary instead
  --show WHICH          all | inside | outside | boundary points
  --compare             time every method on the spray at start (see the Method panel)
  --probe X,Y[,Z]       place a point there and show its trace
  --hover X,Y           2D: hover there (shows the cell under it)
  --line X1 Y1 X2 Y2    2D: the Lines mode (the dual problem) with the line through
                        (X1, Y1) and (X2, Y2)
  --view X,Y,W          2D: look at (X, Y), the scene W wide (zoom in on tiny things)
  --3d                  the 3D scene (a polyhedron with the cube map) without a file
  --slice AXIS=V|none   3D: the slicing plane, e.g. z=0.25; none hides it
  --cell K[,L]|auto     3D: pin cube-map cell K (its pyramid and the faces it lists), and L
                        beside it; auto: a cell listing one face and one listing the most
  --y-gap               2D: mark the smallest y-gap between vertices and the uniform slab
                        count the paper's rule (ymax - ymin) / gap needs
  --plane X1 Y1 Z1 X2 Y2 Z2 X3 Y3 Z3
                        3D: the Planes mode (the dual problem) with the plane through the
                        three points (not on one line); implies --3d
Step by step:
  --step K              show step K (1 = the first) of the placed point's query, highlighted
                        in the drawing and the Steps window (beyond the last: the last;
                        0 or -1: all steps)
  --paper               paper-faithful mode: polar and cubemap queries without the radius
                        filter, so the cell's edges (faces) decide (key R toggles it)
Lectures:
  --figure N            the paper's figure N (1..7) as a slide; later options override it
  --lecture FILE        a slide show (.lecture, see docs/viewer.md): PageDown / PageUp,
                        Home / End move through it
  --export DIR          with --lecture or --figure: write every slide as DIR/slide-NN.png
                        and exit
View:
  --theme dark|light    colours (default dark)
  --font-scale F        text size, 0.5 .. 4 (default 1)
  --hide-ui             only the scene and its legend
  --show-ui             the panels shown (the default; a lecture's slide with a table to
                        read shows them, over a figure's own --hide-ui)
  --present             presentation mode (P): panels hidden, lines and labels sized
                        with the text, the legend movable (drag it)
  --caption TEXT        a caption written large under the scene
  --no-legend           hide the legend (G)
  --no-steps            hide the Steps window (the drawing still shows the step)
  --size WxH            window size in pixels (default 1440x900)
  --shaders DIR         load the GLSL shaders from DIR
  --samples N           multisampling (default 4 on a GPU, 0 on a software renderer,
                        where lines and points are anti-aliased by the shaders alone)
Why O(1), split view, build:
  --why                 open the Why O(1) window and measure every method on regular N-gons
  --why-max N           the largest N measured (8 .. 10^6, default 10^6)
  --why-svg FILE        measure without a window, write the plots as SVG and exit
  --split M             2D: the scene twice, method M in the right half, one camera
  --build-step K        the cells after receiving edges (3D: faces) 0 .. K-1 (build animation)
Without hands:
  --screenshot FILE     render --frames frames (default 3), write FILE (PNG) and exit
  --svg FILE            the same, writing the scene as SVG (vector; both may be given)
  --frames N            render N frames, print the mean frame time and exit
  --animate             move the camera every frame (to time frames under a hand)
  --no-xvfb             without a display, fail instead of re-running under xvfb-run

Mouse: drag to pan (3D: orbit; right drag pans), wheel to zoom at the cursor, click to
place a point (3D: on the slicing plane; Shift-click pins the cell under the cursor),
drag a vertex handle to edit the polygon; in the Lines mode (L) a drag places a line.
In the 3D Planes mode (L) the panel's sliders move the plane.
Keys: F fit, H hide panels, T theme (dark/light), 1..5 method, L lines mode (3D: planes
mode), Space new spray, Esc clear the point, F12 screenshot, V (or Shift+F12) SVG, P
presentation mode, G legend, Left/Right previous/next step of the placed point's query, R
the radius filter on/off (paper-faithful mode); in a lecture PageDown / PageUp next and
previous slide, Home / End first and last.
)";
}

}  // namespace convexloc::viewer
