// convexloc-viewer — the 2D queries told step by step, and the step cursor.
#include "logic/narration/steps.hpp"

#include <algorithm>
#include <cmath>
#include <string_view>

namespace convexloc::viewer {
namespace {

// "+1", "0", "-1"
std::string signWord(int s) {
  return s > 0 ? "+1" : (s < 0 ? "-1" : "0");
}

TraceLine::Kind kindOf(int s) {
  return s > 0 ? TraceLine::Positive : (s < 0 ? TraceLine::Negative : TraceLine::Zero);
}

// the steps of a model, added one by one
struct StepList {
  StepModel& m;
  void add(std::string caption, int line, StepFocus focus = StepFocus::None, std::int64_t item = -1,
           int sign = 0, TraceLine::Kind kind = TraceLine::Step) {
    m.steps.push_back({std::move(caption), line, focus, item, 0, sign, kind});
  }
  // a predicate's step: its sign decides its colour
  void test(std::string caption, int line, StepFocus focus, std::int64_t item, int sign) {
    add(std::move(caption), line, focus, item, sign, kindOf(sign));
  }
  void result(Location r, int line) {
    std::string s(toString(r));
    for (char& c : s) c = static_cast<char>(c >= 'a' && c <= 'z' ? c - 'a' + 'A' : c);
    add("result: " + s, line, StepFocus::Result, -1, 0, TraceLine::Result);
  }
};

// the lines of `text`, split at its newlines (the pseudo-code)
std::vector<std::string> linesOf(std::string_view text) {
  std::vector<std::string> out;
  for (std::size_t start = 0; start <= text.size();) {
    const std::size_t end = std::min(text.find('\n', start), text.size());
    out.emplace_back(text.substr(start, end - start));
    start = end + 1;
  }
  return out;
}

// edge e tested: its sign and what it means
std::string captionOf(const EdgeTest& e) {
  const char* side = e.sign > 0 ? "inner side" : (e.sign < 0 ? "outer side" : "on its line");
  return "edge " + std::to_string(e.edge) + ": orient2d = " + signWord(e.sign) + " (" + side + ")";
}

// face f's plane tested
std::string captionOf(const FaceTest& f) {
  const char* side = f.sign > 0 ? "inner side" : (f.sign < 0 ? "outer side" : "on its plane");
  return "face " + std::to_string(f.face) + ": orient3d = " + signWord(f.sign) + " (" + side + ")";
}

std::int64_t itemOf(const EdgeTest& e) {
  return e.edge;
}
std::int64_t itemOf(const FaceTest& f) {
  return f.face;
}

// each test its own step on `line`
template <class Tests>
void testSteps(const Tests& tests, StepList& l, int line, StepFocus focus) {
  for (const auto& x : tests) l.test(captionOf(x), line, focus, itemOf(x), x.sign);
}

// the line the answer is returned on: `outside` when a test came out negative
template <class Tests>
int resultLine(const Tests& tests, int outside, int otherwise) {
  const bool negative =
      std::any_of(tests.begin(), tests.end(), [](const auto& x) { return x.sign < 0; });
  return negative ? outside : otherwise;
}

// halfplane, halfspace: every edge (face) in order, until an outer side
template <class Tests>
void everyTestSteps(const Tests& tests, Location result, StepFocus focus, const char* each,
                    const char* predicate, StepModel& m) {
  m.code = {std::string("for each ") + each + ":", std::string("  s = ") + predicate,
            "  if s < 0: return OUTSIDE", "return BOUNDARY if some s = 0, else INSIDE"};
  StepList l{m};
  testSteps(tests, l, 1, focus);
  l.result(result, resultLine(tests, 2, 3));
}

// polar, cube map: the radius filter's step (or that it is off), on code line 2
template <class Trace>
void radiusStep(const Trace& t, StepList& l, const char* noun) {
  if (!t.radiusFilter) {
    l.add(std::string("radius filter off: the cell's ") + noun + "s decide", 2);
    return;
  }
  if (!(t.outerRadius > 0)) return;
  bool slab = false;  // the cube map's slab decides after the radii (its own step)
  if constexpr (requires { t.bySlab; }) slab = t.bySlab;
  const std::string verdict =
      slab ? std::string(": between")
      : t.distance < t.innerRadius
          ? std::string(": inside with no test")
          : (t.distance > t.outerRadius ? std::string(": outside with no test")
                                        : std::string(": between, the ") + noun + "s decide");
  l.add("|d| = " + compact(t.distance) + "; cell radii " + compact(t.innerRadius) + ".." +
            compact(t.outerRadius) + verdict,
        2, t.byRadius ? StepFocus::Radii : StepFocus::None, -1);  // drawn where they decide
}

// polar, cube map: the pseudo-code, its radius line struck in paper-faithful mode
void filteredCode(bool radiusFilter, std::vector<std::string> code, StepModel& m) {
  m.code = std::move(code);
  if (radiusFilter) return;
  m.code[2] = "(radius filter off: the paper's query)";
  m.note = "paper mode: no radius filter";
}

// ray apex -> vertex v tested
std::string rayCaption(const RayTest& r, const char* apex) {
  const char* side = r.sign > 0 ? "counter-clockwise" : (r.sign < 0 ? "clockwise" : "on it");
  return std::string("ray ") + apex + "->v" + std::to_string(r.vertex) + ": " + signWord(r.sign) +
         " (" + side + ")";
}

void halfplaneSteps(const Trace2D& t, StepModel& m) {
  everyTestSteps(t.edges, t.result, StepFocus::Edge, "edge e = 0 .. n-1",
                 "orient2d(v[e], v[e+1], x)", m);
}

// the fan from vertex 0 (wedge, and polar without a cell): the outer rays, the bisection,
// the one edge; `first` is the code line of the outer rays
void fanSteps(const Trace2D& t, StepList& l, int first) {
  for (std::size_t k = 0; k < t.rays.size(); ++k)
    l.test(rayCaption(t.rays[k], "v0"), k < 2 ? first : first + 1, StepFocus::Ray, t.rays[k].vertex,
           t.rays[k].sign);
  testSteps(t.edges, l, first + 2, StepFocus::Edge);
}

void wedgeSteps(const Trace2D& t, const ConvexPolygon& poly, StepModel& m) {
  m.code = {"o = v[0]: the fan of rays o->v[i]",
            "if x is clockwise of o->v[1] or ccw of o->v[n-1]: OUTSIDE",
            "bisect: the side of ray o->v[mid] keeps [lo,mid] or [mid,hi]",
            "s = orient2d(v[lo], v[lo+1], x): one edge decides"};
  StepList l{m};
  l.add("fan from v0 = " + compact(poly.vertex(0)), 0);
  fanSteps(t, l, 1);
  l.result(t.result, t.edges.empty() ? 1 : 3);
}

// slab, uniform: a point outside the box needs no slab; true when it was
bool outsideTheBox(const Trace2D& t, StepList& l) {
  if (!t.outsideBox) return false;
  l.add("outside the bounding box: no slab is needed", 0, StepFocus::Box);
  l.result(t.result, 0);
  return true;
}

void slabSteps(const Trace2D& t, StepModel& m) {
  m.code = {"if x is outside the bounding box: OUTSIDE",
            "binary search of x.y among the sorted vertex y: y(0) < y(1) < ...",
            "slab s: its two edges, rising and falling", "s = orient2d for each of the two edges",
            "OUTSIDE if one s < 0, else BOUNDARY if one s = 0, else INSIDE"};
  StepList l{m};
  if (outsideTheBox(t, l)) return;
  for (std::size_t k = 0; k < t.probes.size(); ++k) {
    const SlabProbe& p = t.probes[k];
    l.add("probe " + std::to_string(k + 1) + ": " + sortedY(p.rank) + " = " + compact(p.y) +
              (p.above ? " <= x.y: go up" : " > x.y: go down"),
          1, StepFocus::Search, p.rank);
  }
  l.add("slab " + std::to_string(t.cell) + " (between " + sortedY(t.cell) + " and " +
            sortedY(t.cell + 1) + ")",
        2, StepFocus::Cell, t.cell);
  testSteps(t.edges, l, 3, StepFocus::Edge);
  l.result(t.result, 4);
}

void uniformSteps(const Trace2D& t, double y, StepModel& m) {
  m.code = {"if x is outside the bounding box: OUTSIDE",
            "slab = floor((x.y - ymin) / dy)   (eq. 4)",
            "test the edges the slab lists (bisection where crowded)",
            "OUTSIDE if one s < 0, else BOUNDARY if one s = 0, else INSIDE"};
  StepList l{m};
  if (outsideTheBox(t, l)) return;
  const UniformIndex& u = t.uniform;
  l.add("eq. (4): floor((" + compact(y) + " - " + compact(u.yMin) + ") / " + compact(u.height) +
            ") = floor(" + compact(u.value) + ")",
        1, StepFocus::Index, t.cell);
  l.add("slab " + std::to_string(t.cell) + " of " + std::to_string(u.slabs) +
            (t.crowded ? ": crowded, bisection" : ""),
        1, StepFocus::Cell, t.cell);
  testSteps(t.edges, l, 2, StepFocus::Edge);
  l.result(t.result, 3);
}

// the polar cell's steps: octant, ratio, radii, the edges
void polarCellSteps(const Trace2D& t, StepList& l) {
  const PolarIndexTrace& n = t.polar;
  l.add("octant " + std::to_string(t.octant) + ": d = x - x_T = " + compact(n.direction), 0,
        StepFocus::Octant, t.octant);
  l.add(std::string("ratio ") + (n.steep ? "|dx|/|dy|" : "|dy|/|dx|") + " = " + compact(n.ratio) +
            ": k = floor(" + std::to_string(n.slabs) + "*" + compact(n.ratio) +
            ") = " + std::to_string(n.slab) + " -> cell " + std::to_string(t.cell),
        1, StepFocus::Cell, t.cell);
  radiusStep(t, l, "edge");
  for (const RayTest& r : t.rays) l.test(rayCaption(r, "x_T"), 3, StepFocus::Ray, r.vertex, r.sign);
  testSteps(t.edges, l, 3, StepFocus::Edge);
}

void polarSteps(const Trace2D& t, StepModel& m) {
  filteredCode(t.radiusFilter,
               {"d = x - x_T; octant from the signs of dx, dy and |dx| < |dy|",
                "k = floor(q * min(|dx|,|dy|) / max(|dx|,|dy|)): slab k of the octant",
                "radius filter: |d| < r_in: INSIDE; |d| > r_out: OUTSIDE",
                "test the cell's edges (bisection where crowded)",
                "OUTSIDE if one s < 0, else BOUNDARY if one s = 0, else INSIDE"},
               m);
  StepList l{m};
  if (t.atCentre) {
    l.add("the point is the centre x_T itself", 0);
    l.result(t.result, 0);
    return;
  }
  if (t.cell < 0) {
    l.add("no polar cell (no centre strictly inside, or too far): fan from v0", 0);
    fanSteps(t, l, 3);
    l.result(t.result, 4);
    return;
  }
  polarCellSteps(t, l);
  l.result(t.result, t.byRadius ? 2 : 4);
}

// === 3D

// the walk's edge tests: cross where the direction lies beyond the edge
void walkSteps(const Trace3D& t, StepList& l, int line) {
  for (const WalkTest& w : t.steps) {
    l.test("face " + std::to_string(w.face) + ", edge " + std::to_string(w.edge) +
               ": orient3d(x_T,a,b,x) = " + signWord(w.sign) +
               (w.sign > 0 ? " (cross)" : " (stay)"),
           line, StepFocus::Walk, w.face, w.sign);
    l.m.steps.back().sub = w.edge;
  }
}

void halfspaceSteps(const Trace3D& t, StepModel& m) {
  everyTestSteps(t.faces, t.result, StepFocus::Face, "face f = (a, b, c)", "orient3d(a, b, c, x)",
                 m);
}

void walkMethodSteps(const Trace3D& t, double scale, StepModel& m) {
  m.code = linesOf(
      "start at the face whose direction from x_T is nearest x's\n"
      "cross an edge (a, b) while orient3d(x_T, a, b, x) > 0\n"
      "at the face x's ray leaves by: s = orient3d(a, b, c, x)\n"
      "OUTSIDE if s < 0, BOUNDARY if s = 0, else INSIDE");
  StepList l{m};
  if (t.centre) l.add("centre x_T = " + compact(*t.centre, scale), 0);
  if (t.fallback) l.add("no walk (no centre, or it ran too long): every face is tested", 2);
  walkSteps(t, l, 1);
  testSteps(t.faces, l, 2, StepFocus::Face);
  l.result(t.result, 3);
}

// the cube map's cell: the cube face, (s, t), the cell, the radii
void cubeCellSteps(const Trace3D& t, double scale, StepList& l) {
  l.add("d = x - x_T = " + compact(t.direction, scale) + ": cube face " +
            std::string(kCubeFaceNames[static_cast<std::size_t>(t.cubeFace)]),
        0, StepFocus::Octant, t.cubeFace);
  // s and t lie in [-1, 1]: below 1e-12 they are rounding of a d coordinate shown as 0 above
  std::string cell = "(s,t) = " + compact(Vec2{t.s, t.t}, 1.0) + " -> cell (" +
                     std::to_string(t.cellI) + "," + std::to_string(t.cellJ) + ") of " +
                     std::to_string(t.cellsPerSide) + "x" + std::to_string(t.cellsPerSide);
  if (t.level > 0) cell += ", level " + std::to_string(t.level);
  l.add(cell, 1, StepFocus::Cell, -1);
  radiusStep(t, l, "face");
  // between the radii, the cell's slab (a plane's two bounds over where its rays leave the
  // shape) can still decide before any face test
  if (t.bySlab)
    l.add(std::string("the cell's slab: n . d beyond its bounds: ") +
              (t.result == Location::Inside ? "inside" : "outside") + " with no face test",
          2, StepFocus::Radii, -1);
}

void cubemapSteps(const Trace3D& t, double scale, StepModel& m) {
  filteredCode(t.radiusFilter,
               {"d = x - x_T; cube face: the largest |d_i| and its sign",
                "(s,t) = (d_u, d_v) / |d_major|; cell = floor((s+1)/2 * n)",
                "radius filter: |d| < r_in: INSIDE; |d| > r_out: OUTSIDE",
                "test the cell's faces (a walk, or a zone's bisection, where crowded)",
                "OUTSIDE if one s < 0, else BOUNDARY if one s = 0, else INSIDE"},
               m);
  StepList l{m};
  if (t.atCentre || t.nonFinite) {
    l.add(t.atCentre ? "the point is the centre x_T itself" : "a coordinate is not finite", 0);
    l.result(t.result, 0);
    return;
  }
  if (t.cubeFace >= 0) cubeCellSteps(t, scale, l);
  if (t.fallback) l.add("no cell could be used: every face is tested", 3);
  if (t.crowded && t.zoneSteps.empty() && t.sectorSteps.empty())
    l.add("the cell lists many faces: a walk among them", 3);
  if (!t.sectorSteps.empty())
    l.add("the cell lies over a fan of thin faces: bisection by angle around its axis", 3);
  for (const SectorTest& z : t.sectorSteps)
    l.add(
        "fan key " + std::to_string(z.index) + ": orient3d(x_T, axis, v, x) = " + signWord(z.sign),
        3);
  if (!t.zoneSteps.empty())
    l.add("the cell lies over a zone of thin faces: bisection over its edges' planes", 3);
  for (const ZoneTest& z : t.zoneSteps)
    l.add("zone edge " + std::to_string(z.edge) + ": orient3d(x_T, a, b, x) = " + signWord(z.sign),
          3);
  walkSteps(t, l, 3);
  testSteps(t.faces, l, 3, StepFocus::Face);
  l.result(t.result, t.byRadius ? 2 : 4);
}

}  // namespace

StepModel buildSteps3D(const Trace3D& t, Vec3 point, double scale) {
  StepModel m;
  m.title = std::string(toString(t.method)) + ": point " + compact(point, scale);
  switch (t.method) {
    case Method3D::Halfspace: halfspaceSteps(t, m); break;
    case Method3D::Walk: walkMethodSteps(t, scale, m); break;
    case Method3D::Cubemap: cubemapSteps(t, scale, m); break;
  }
  return m;
}

StepModel buildSteps(const Trace2D& t, Vec2 point, const ConvexPolygon& polygon) {
  StepModel m;
  m.title = std::string(toString(t.method)) + ": point " + compact(point);
  switch (t.method) {
    case Method2D::Halfplane: halfplaneSteps(t, m); break;
    case Method2D::Wedge: wedgeSteps(t, polygon, m); break;
    case Method2D::Slab: slabSteps(t, m); break;
    case Method2D::Uniform: uniformSteps(t, point.y, m); break;
    case Method2D::Polar: polarSteps(t, m); break;
  }
  return m;
}

namespace {

// the steps as the inspector lists them
std::vector<TraceLine> inspectorLines(const StepModel& m) {
  std::vector<TraceLine> out;
  out.push_back({TraceLine::Heading, m.title});
  if (!m.note.empty()) out.push_back({TraceLine::Step, m.note});
  std::size_t predicates = 0;
  for (const Step& s : m.steps) {
    const bool tested =
        s.kind == TraceLine::Positive || s.kind == TraceLine::Negative || s.kind == TraceLine::Zero;
    predicates += tested ? 1 : 0;
    std::string text = s.caption;
    if (s.kind == TraceLine::Result)
      text +=
          "  (" + std::to_string(predicates) + (predicates == 1 ? " predicate)" : " predicates)");
    out.push_back({s.kind, std::move(text)});
  }
  return out;
}

}  // namespace

std::vector<TraceLine> describeTrace(const Trace2D& trace, Vec2 point,
                                     const ConvexPolygon& polygon) {
  return inspectorLines(buildSteps(trace, point, polygon));
}

std::vector<TraceLine> describeTrace3D(const Trace3D& trace, Vec3 point, double scale) {
  return inspectorLines(buildSteps3D(trace, point, scale));
}

int clampStep(int k, std::size_t count) {
  if (k < 0 || count == 0) return -1;
  return std::min(k, static_cast<int>(count) - 1);
}

int nextStep(int k, std::size_t count, bool forward) {
  if (count == 0) return -1;
  const int last = static_cast<int>(count) - 1;
  if (k < 0) return forward ? 0 : last;
  return std::clamp(k + (forward ? 1 : -1), 0, last);
}

void StepPlayer::start(int& step, std::size_t count, double now) {
  if (step < 0 || step >= static_cast<int>(count) - 1) step = 0;
  playing = count > 0;
  last = now;
}

int StepPlayer::tick(int step, std::size_t count, double now) {
  if (!playing || count == 0) return step;
  const double period = 1.0 / std::max(0.05f, speed);
  while (now - last >= period && step < static_cast<int>(count) - 1) {
    ++step;
    last += period;
  }
  if (step >= static_cast<int>(count) - 1) playing = false;
  return step;
}

}  // namespace convexloc::viewer
