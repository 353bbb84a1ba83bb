// convexloc-viewer — the 2D draw lists.
#include "logic/draw/structure2d.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "logic/base/format.hpp"
#include "logic/draw/radii_arc.hpp"
#include "logic/draw/snap_indicator.hpp"
#include "logic/draw/y_gap.hpp"
#include "logic/draw/zoom_inset.hpp"
#include "logic/narration/steps.hpp"
#include "logic/view/camera2d.hpp"

namespace convexloc::viewer {
namespace {

// the corners of a box, counter-clockwise from the lower left
void boxCorners(const Box2& b, glm::dvec2 out[4]) {
  out[0] = {b.lo.x, b.lo.y};
  out[1] = {b.hi.x, b.lo.y};
  out[2] = {b.hi.x, b.hi.y};
  out[3] = {b.lo.x, b.hi.y};
}

// a convex outline filled as a fan
void fillOutline(const std::vector<Vec2>& outline, Rgba c, DrawList& out) {
  for (std::size_t i = 1; i + 1 < outline.size(); ++i)
    out.triangle(at2(toGlm(outline[0])), at2(toGlm(outline[i])), at2(toGlm(outline[i + 1])), c);
}

// the closed outline as segments
void strokeOutline(const std::vector<Vec2>& outline, Rgba c, float width, DrawList& out,
                   float dash = 0.0f) {
  for (std::size_t i = 0; i < outline.size(); ++i)
    out.segment(at2(toGlm(outline[i])), at2(toGlm(outline[(i + 1) % outline.size()])), c, width,
                dash);
}

// edge e of the polygon, drawn over the others
void strokeEdge(const ConvexPolygon& poly, std::size_t e, Rgba c, float width, DrawList& out) {
  out.segment(at2(toGlm(poly.edgeStart(e))), at2(toGlm(poly.edgeEnd(e))), c, width);
}

// where to write the name of edge e: its middle, pushed outward by `px` pixels
void labelEdge(const ConvexPolygon& poly, std::size_t e, std::string text, Rgba c, float px,
               DrawList& out) {
  const glm::dvec2 a = toGlm(poly.edgeStart(e)), b = toGlm(poly.edgeEnd(e));
  glm::dvec2 d = b - a;
  const double len = glm::length(d);
  glm::vec2 offset{0.0f};
  // outward normal of a counter-clockwise edge, y flipped for the screen
  if (len > 0.0)
    offset = glm::vec2(static_cast<float>(d.y / len), static_cast<float>(d.x / len)) * px;
  out.label(at2(0.5 * (a + b)), std::move(text), c, offset);
}

// the colour of a predicate's sign
Rgba signColour(const Palette& p, int sign) {
  return sign > 0 ? p.positive : (sign < 0 ? p.negative : p.zero);
}

// the polygon's interior, faintly (a cosmetic fan: left out for huge polygons)
void fillPolygon(const ConvexPolygon& poly, const Palette& pal, DrawList& out) {
  const std::size_t n = poly.size();
  if (n > kMaxFilledVertices) return;
  for (std::size_t i = 1; i + 1 < n; ++i)
    out.triangle(at2(toGlm(poly.vertex(0))), at2(toGlm(poly.vertex(i))),
                 at2(toGlm(poly.vertex(i + 1))), pal.polygonFill);
}

// cells listing more than the method's fewest edges, tinted apart
void tintCells(const Scene2D& scene, const Palette& pal, DrawList& out) {
  const std::size_t base = baseEdgesPerCell(scene.method());
  for (const Cell2D& c : scene.cells()) {
    const bool crowded = c.edges.size() > kCrowdedCell;
    if (c.edges.size() <= base && !crowded) continue;
    fillOutline(c.outline, cellTint(pal, c.edges.size(), base, crowded), out);
  }
}

// a box's outline, dashed
void drawBox(const Box2& box, Rgba colour, float width, DrawList& out) {
  glm::dvec2 k[4];
  boxCorners(box, k);
  for (int i = 0; i < 4; ++i) out.segment(at2(k[i]), at2(k[(i + 1) % 4]), colour, width, 6.0f);
}

// halfplane: the edges' lines; inside is where every line has the point on its inner side
void halfplaneLines(const ConvexPolygon& poly, const Palette& pal, DrawList& out) {
  const std::size_t n = poly.size();
  if (n > 4096) return;
  const Box2 wide = grow(poly.bounds(), 0.35);
  const float alpha = n <= 64 ? 1.0f : (n <= 512 ? 0.5f : 0.25f);
  for (std::size_t e = 0; e < n; ++e) {
    glm::dvec2 p, q;
    if (clipLineToBox(toGlm(poly.edgeStart(e)), toGlm(poly.edgeEnd(e)), wide, p, q))
      out.segment(at2(p), at2(q), withAlpha(pal.structure, pal.structure.a * alpha), 1.0f);
  }
}

// wedge: the fan of diagonals from vertex 0
void wedgeFan(const std::vector<Cell2D>& cells, const Palette& pal, DrawList& out) {
  for (std::size_t i = 0; i + 1 < cells.size(); ++i)
    out.segment(at2(toGlm(cells[i].outline[0])), at2(toGlm(cells[i].outline[2])), pal.structure,
                1.0f);
}

// slab, uniform: the slabs' lower sides, and the top of the last
void slabLines(const std::vector<Cell2D>& cells, const Palette& pal, DrawList& out) {
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const auto& o = cells[i].outline;
    out.segment(at2(toGlm(o[0])), at2(toGlm(o[1])), pal.structure, 1.0f);
    if (i + 1 == cells.size()) out.segment(at2(toGlm(o[2])), at2(toGlm(o[3])), pal.structure, 1.0f);
  }
}

// polar: the rays bounding the slabs, from the centre to the box; the octant lines (the
// rays at the start of each octant's first cell) and the octants' numbers
void polarRays(const Scene2D& scene, const Palette& pal, const View2DOptions& opt, bool dense,
               DrawList& out) {
  const auto& cells = scene.cells();
  const std::uint32_t q = scene.effectiveResolution();
  if (!dense)
    for (const Cell2D& c : cells)
      if (q == 0 || c.index % q != 0)
        out.segment(at2(toGlm(c.outline[0])), at2(toGlm(c.hitLo)), pal.structure, 1.0f);
  if (q == 0) return;
  if (opt.showOctants)
    for (const Cell2D& c : cells)
      if (c.index % q == 0)
        out.segment(at2(toGlm(c.outline[0])), at2(toGlm(c.hitLo)), pal.octant, 1.6f, 9.0f);
  if (!opt.showLabels || cells.empty()) return;
  // near the box along each octant's middle
  for (std::uint32_t o = 0; o < 8; ++o) {
    const std::size_t first = static_cast<std::size_t>(o) * q, last = first + q - 1;
    if (last >= cells.size()) break;
    const glm::dvec2 ctr = toGlm(cells[first].outline[0]);
    const glm::dvec2 mid = 0.5 * (toGlm(cells[first].hitLo) + toGlm(cells[last].hitHi));
    out.label(at2(ctr + 0.88 * (mid - ctr)), numbered("octant ", o), pal.textMuted);
  }
}

// each method's structure; dense subdivisions keep only what stays readable
void methodStructure(const Scene2D& scene, const Palette& pal, const View2DOptions& opt,
                     DrawList& out) {
  const bool dense = scene.cells().size() > kMaxCellLines;
  switch (scene.method()) {
    case Method2D::Halfplane: halfplaneLines(scene.polygon(), pal, out); break;
    case Method2D::Wedge:
      if (!dense) wedgeFan(scene.cells(), pal, out);
      break;
    case Method2D::Slab:
    case Method2D::Uniform:
      if (!dense) slabLines(scene.cells(), pal, out);
      break;
    case Method2D::Polar: polarRays(scene, pal, opt, dense, out); break;
  }
}

// the centre x_T, and the wedge's apex x0
void markCentre(const Scene2D& scene, const Palette& pal, const View2DOptions& opt, DrawList& out) {
  if (auto c = scene.centre()) {
    out.marker(at2(toGlm(*c)), pal.centre, 11.0f, MarkerShape::Cross);
    if (opt.showLabels) out.label(at2(toGlm(*c)), "x_T", pal.text, {16.0f, -14.0f});
  }
  if (scene.method() == Method2D::Wedge && opt.showLabels)
    out.label(at2(toGlm(scene.polygon().vertex(0))), "x0", pal.text, {10.0f, 10.0f});
}

// vertex numbers and handles where they fit
void vertexLabelsAndHandles(const ConvexPolygon& poly, const Palette& pal, const View2DOptions& opt,
                            DrawList& out) {
  const std::size_t n = poly.size();
  if (opt.showLabels && n <= kMaxLabelledVertices) {
    const Box2 box = poly.bounds();
    const glm::dvec2 mid{0.5 * (box.lo.x + box.hi.x), 0.5 * (box.lo.y + box.hi.y)};
    for (std::size_t i = 0; i < n; ++i) {
      glm::dvec2 d = toGlm(poly.vertex(i)) - mid;
      const double len = glm::length(d);
      glm::vec2 off =
          len > 0.0
              ? glm::vec2(static_cast<float>(d.x / len), static_cast<float>(-d.y / len)) * 14.0f
              : glm::vec2(0.0f);
      out.label(at2(toGlm(poly.vertex(i))), std::to_string(i), pal.textMuted, off);
    }
  }
  if (opt.showHandles && n <= kMaxHandles)
    for (std::size_t i = 0; i < n; ++i)
      out.marker(at2(toGlm(poly.vertex(i))), pal.handle, 9.0f, MarkerShape::Ring);
}

// the hovered cell, its outline, and the edges it lists in bold
void hoveredCell(const Scene2D& scene, const Palette& pal, const View2DOptions& opt,
                 DrawList& out) {
  const ConvexPolygon& poly = scene.polygon();
  const Cell2D& c = scene.cells()[static_cast<std::size_t>(scene.hoveredCell())];
  fillOutline(c.outline, pal.hoverFill, out);
  strokeOutline(c.outline, pal.hoverOutline, 1.5f, out);
  // an edge the placed point's trace names gets that label instead
  auto traced = [&](std::uint32_t e) {
    if (!scene.probe()) return false;
    for (const EdgeTest& t : scene.probe()->trace.edges)
      if (t.edge == e) return true;
    return false;
  };
  for (std::uint32_t e : c.edges) {
    strokeEdge(poly, e, pal.hoverEdge, 5.0f, out);
    if (opt.showLabels && c.edges.size() <= 12 && !traced(e))
      labelEdge(poly, e, numbered("e", e), pal.hoverEdge, 16.0f, out);
  }
}

// a dashed arc (or circle) through `points`
void dashedPath(const std::vector<glm::dvec2>& points, Rgba colour, float width, DrawList& out) {
  for (std::size_t k = 0; k + 1 < points.size(); ++k)
    out.segment(at2(points[k]), at2(points[k + 1]), colour, width, 6.0f);
}

// polar: the cell's two radii around the centre x_T (inside within r_in, outside beyond
// r_out), as arcs inside the cell's wedge (they hold for its points only), labelled at the
// arcs' middles when `current`
void radiiArcs(const Scene2D& scene, const Trace2D& t, const Palette& pal, bool current,
               bool labels, DrawList& out) {
  const glm::dvec2 c = toGlm(t.apex);
  const std::ptrdiff_t pos = cellPosition(scene, t.cell);
  glm::dvec2 lo{0.0}, hi{0.0};
  if (pos >= 0) {
    const Cell2D& cell = scene.cells()[static_cast<std::size_t>(pos)];
    lo = toGlm(cell.dirLo), hi = toGlm(cell.dirHi);
  }
  const float w = current ? 2.0f : 1.0f;
  const float a = current ? 1.0f : 0.5f;
  const auto inner = wedgeArc(c, t.innerRadius, lo, hi);
  const auto outer = wedgeArc(c, t.outerRadius, lo, hi);
  dashedPath(inner, withAlpha(pal.positive, a), w, out);
  dashedPath(outer, withAlpha(pal.negative, a), w, out);
  if (current && labels) {
    out.label(at2(inner[inner.size() / 2]), "r_in", pal.positive, {0.0f, 12.0f});
    out.label(at2(outer[outer.size() / 2]), "r_out", pal.negative, {0.0f, -12.0f});
  }
}

// the step number (from 1) of each ray test, in the order of the trace's rays
std::vector<std::size_t> rayStepNumbers(const StepModel& m) {
  std::vector<std::size_t> numbers;
  for (std::size_t i = 0; i < m.steps.size(); ++i)
    if (m.steps[i].focus == StepFocus::Ray) numbers.push_back(i + 1);
  return numbers;
}

// the placed point and its trace: the cell chosen, the rays and edges tested by sign
void probeTrace(const Scene2D& scene, const Probe& probe, const Palette& pal,
                const View2DOptions& opt, DrawList& out) {
  const ConvexPolygon& poly = scene.polygon();
  const std::size_t n = poly.size();
  const auto& cells = scene.cells();
  const Trace2D& t = probe.trace;
  const glm::dvec2 x = toGlm(probe.point);
  if (t.outsideBox) drawBox(poly.bounds(), pal.negative, 2.0f, out);
  // the radii, where they decided
  if (t.byRadius) radiiArcs(scene, t, pal, true, opt.showLabels, out);
  // the cell the query chose
  const std::ptrdiff_t pos = cellPosition(scene, t.cell);
  if (pos >= 0) {
    const Cell2D& c = cells[static_cast<std::size_t>(pos)];
    fillOutline(c.outline, withAlpha(colourOf(pal, t.result), 0.16f), out);
    strokeOutline(c.outline, withAlpha(colourOf(pal, t.result), 0.9f), 1.75f, out);
  }
  // the ray from the apex (polar centre, wedge vertex 0) to the point
  if (t.method == Method2D::Polar || t.method == Method2D::Wedge)
    out.segment(at2(toGlm(t.apex)), at2(x), pal.text, 1.25f, 5.0f);
  // rays tested by bisection: from the apex through a vertex, coloured by the sign, each
  // numbered as the Steps window numbers its test
  const bool rayLabels = opt.showLabels && t.rays.size() <= 24;
  const std::vector<std::size_t> rayStep =
      rayLabels ? rayStepNumbers(buildSteps(t, probe.point, poly)) : std::vector<std::size_t>{};
  for (std::size_t k = 0; k < t.rays.size(); ++k) {
    const RayTest r = t.rays[k];
    if (r.vertex >= n) continue;
    const glm::dvec2 a = toGlm(t.apex), v = toGlm(poly.vertex(r.vertex));
    out.segment(at2(a), at2(a + 1.08 * (v - a)), withAlpha(signColour(pal, r.sign), 0.9f), 2.0f);
    if (rayLabels && k < rayStep.size())
      out.label(at2(a + 1.08 * (v - a)), std::to_string(rayStep[k]) + signText(r.sign),
                signColour(pal, r.sign), {0.0f, -10.0f});
  }
  // edges tested, coloured by the sign
  const bool fewEdges = t.edges.size() <= 16;
  for (const EdgeTest& e : t.edges) {
    if (e.edge >= n) continue;
    strokeEdge(poly, e.edge, signColour(pal, e.sign), 4.5f, out);
    if (opt.showLabels && fewEdges)
      labelEdge(poly, e.edge, numbered("e", e.edge).append(signText(e.sign)),
                signColour(pal, e.sign), 18.0f, out);
  }
  out.marker(at2(x), pal.rim, 17.0f, MarkerShape::Disc);
  out.marker(at2(x), colourOf(pal, t.result), 13.0f, MarkerShape::Disc);
  if (opt.showLabels)
    out.label(at2(x), std::string(toString(t.result)), textColourOf(pal, t.result), {12.0f, 12.0f});
}

// === The query step by step: each step up to the current one drawn, the current one bold

// what a step is drawn from
struct StepDraw {
  const Scene2D& scene;
  const Trace2D& t;
  glm::dvec2 point;
  const Palette& pal;
  const View2DOptions& opt;
  DrawList& out;
};

// the horizontal line y = value across the (grown) box, with a label at its left end
void probeLine(const StepDraw& d, double y, Rgba c, float width, const std::string& label) {
  const Box2 b = grow(d.scene.polygon().bounds(), 0.06);
  d.out.segment(at2({b.lo.x, y}), at2({b.hi.x, y}), c, width);
  if (d.opt.showLabels && !label.empty()) d.out.label(at2({b.lo.x, y}), label, c, {-28.0f, 0.0f});
}

// the cell with this index, outlined (and filled when current)
void stepCell(const StepDraw& d, std::int64_t index, bool current) {
  const std::ptrdiff_t pos = cellPosition(d.scene, index);
  if (pos < 0) return;
  const Cell2D& c = d.scene.cells()[static_cast<std::size_t>(pos)];
  const Rgba colour = d.pal.hoverEdge;
  if (current) fillOutline(c.outline, withAlpha(colour, 0.18f), d.out);
  strokeOutline(c.outline, withAlpha(colour, current ? 1.0f : 0.5f), current ? 2.5f : 1.25f, d.out);
}

// polar: the octant's two bounding rays from the centre (the first cell's lower ray, the
// last cell's upper one)
void stepOctant(const StepDraw& d, int octant, bool current) {
  const auto& cells = d.scene.cells();
  const std::size_t q = cells.size() / 8;
  if (q == 0 || octant < 0 || static_cast<std::size_t>(octant) >= 8) return;
  const glm::dvec2 c = toGlm(d.t.apex);
  const Rgba colour = withAlpha(d.pal.hoverEdge, current ? 1.0f : 0.5f);
  const float w = current ? 2.5f : 1.25f;
  d.out.segment(at2(c), at2(toGlm(cells[octant * q].hitLo)), colour, w);
  d.out.segment(at2(c), at2(toGlm(cells[octant * q + q - 1].hitHi)), colour, w);
  // the structure names every octant already where it is drawn: named once
  if (current && d.opt.showLabels && !d.opt.showStructure)
    d.out.label(
        at2(0.5 * (toGlm(cells[octant * q].hitLo) + toGlm(cells[octant * q + q - 1].hitHi))),
        numbered("octant ", static_cast<std::uint64_t>(octant)), d.pal.hoverEdge);
}

// polar: the cell's two radii around the centre
void stepRadii(const StepDraw& d, bool current) {
  radiiArcs(d.scene, d.t, d.pal, current, d.opt.showLabels, d.out);
}

// a ray from the apex through a vertex, by its sign
void stepRay(const StepDraw& d, const Step& s, bool current, std::size_t number) {
  const ConvexPolygon& poly = d.scene.polygon();
  if (s.item < 0 || static_cast<std::size_t>(s.item) >= poly.size()) return;
  const glm::dvec2 a = toGlm(d.t.apex), v = toGlm(poly.vertex(static_cast<std::size_t>(s.item)));
  const Rgba c = withAlpha(signColour(d.pal, s.sign), current ? 1.0f : 0.45f);
  d.out.segment(at2(a), at2(a + 1.08 * (v - a)), c, current ? 3.0f : 1.5f);
  if (current && d.opt.showLabels)
    d.out.label(at2(a + 1.08 * (v - a)), "step " + std::to_string(number) + signText(s.sign), c,
                {0.0f, -12.0f});
}

// an edge tested, by its sign
void stepEdge(const StepDraw& d, const Step& s, bool current) {
  const ConvexPolygon& poly = d.scene.polygon();
  if (s.item < 0 || static_cast<std::size_t>(s.item) >= poly.size()) return;
  const auto e = static_cast<std::size_t>(s.item);
  const Rgba c = withAlpha(signColour(d.pal, s.sign), current ? 1.0f : 0.5f);
  strokeEdge(poly, e, c, current ? 6.0f : 3.5f, d.out);
  if (current && d.opt.showLabels)
    labelEdge(poly, e, numbered("e", e).append(signText(s.sign)), c, 20.0f, d.out);
}

// one step's drawing; `number` counts from 1
void drawStep(const StepDraw& d, const Step& s, bool current, std::size_t number) {
  const Rgba hi = withAlpha(d.pal.hoverEdge, current ? 1.0f : 0.45f);
  switch (s.focus) {
    case StepFocus::Box: drawBox(d.scene.polygon().bounds(), d.pal.negative, 2.5f, d.out); break;
    case StepFocus::Search:
      for (const SlabProbe& p : d.t.probes)
        if (p.rank == s.item)
          probeLine(d, p.y, hi, current ? 2.5f : 1.25f, current ? sortedY(p.rank) : "");
      if (current) probeLine(d, d.point.y, withAlpha(d.pal.text, 0.8f), 1.0f, "x.y");
      break;
    case StepFocus::Index:
      stepCell(d, s.item, current);
      if (current) probeLine(d, d.point.y, withAlpha(d.pal.text, 0.8f), 1.0f, "x.y");
      break;
    case StepFocus::Octant: stepOctant(d, static_cast<int>(s.item), current); break;
    case StepFocus::Cell: stepCell(d, s.item, current); break;
    case StepFocus::Radii: stepRadii(d, current); break;
    case StepFocus::Ray: stepRay(d, s, current, number); break;
    case StepFocus::Edge: stepEdge(d, s, current); break;
    default: break;
  }
}

// the placed point's steps up to `step` (the current one bold), the point and its ray
void probeSteps(const Scene2D& scene, const Probe& probe, const Palette& pal,
                const View2DOptions& opt, int step, DrawList& out) {
  const Trace2D& t = probe.trace;
  const StepModel m = buildSteps(t, probe.point, scene.polygon());
  const int k = clampStep(step, m.steps.size());
  const glm::dvec2 x = toGlm(probe.point);
  const StepDraw d{scene, t, x, pal, opt, out};
  if ((t.method == Method2D::Polar || t.method == Method2D::Wedge) && !t.atCentre)
    out.segment(at2(toGlm(t.apex)), at2(x), pal.text, 1.25f, 5.0f);
  for (int j = 0; j <= k; ++j)
    drawStep(d, m.steps[static_cast<std::size_t>(j)], j == k, static_cast<std::size_t>(j) + 1);
  const bool done = m.steps[static_cast<std::size_t>(k)].focus == StepFocus::Result;
  const Rgba colour = done ? colourOf(pal, t.result) : pal.text;
  out.marker(at2(x), pal.rim, 17.0f, MarkerShape::Disc);
  out.marker(at2(x), colour, 13.0f, MarkerShape::Disc);
  if (opt.showLabels)
    out.label(at2(x), done ? std::string(toString(t.result)) : "x",
              done ? textColourOf(pal, t.result) : pal.text, {12.0f, 12.0f});
}

// A dragged vertex: accepted edits are the shape itself; a rejected one shows where the
// mouse is, tied to the kept vertex, with the reason.
void dragMarker(const Scene2D& scene, const Drag& d, const Palette& pal, DrawList& out) {
  const ConvexPolygon& poly = scene.polygon();
  const glm::dvec2 kept = toGlm(poly.vertex(std::min(d.vertex, poly.size() - 1)));
  out.marker(at2(kept), pal.hoverEdge, 13.0f, MarkerShape::Ring);
  if (d.rejected) {
    out.segment(at2(kept), at2(toGlm(d.cursor)), pal.handleError, 1.5f, 5.0f);
    out.marker(at2(toGlm(d.cursor)), pal.handleError, 13.0f, MarkerShape::Cross);
    out.label(at2(toGlm(d.cursor)), d.message, pal.handleError, {14.0f, 14.0f});
  }
}

}  // namespace

std::ptrdiff_t cellPosition(const Scene2D& scene, std::int64_t index) {
  if (index < 0) return -1;
  const auto& cells = scene.cells();
  // cells are listed in index order; the wedge's start at 1
  const auto it = std::lower_bound(cells.begin(), cells.end(), index,
                                   [](const Cell2D& c, std::int64_t i) { return c.index < i; });
  if (it == cells.end() || static_cast<std::int64_t>(it->index) != index) return -1;
  return it - cells.begin();
}

void buildStructure2D(const Scene2D& scene, const Palette& pal, const View2DOptions& opt,
                      DrawList& out) {
  out.clear();
  fillPolygon(scene.polygon(), pal, out);
  if (opt.showStructure && opt.showTints) tintCells(scene, pal, out);
  if (opt.showBox) drawBox(scene.polygon().bounds(), pal.box, 1.25f, out);
  if (opt.showStructure) methodStructure(scene, pal, opt, out);
  // the polygon's edges, over the structure
  for (std::size_t e = 0; e < scene.polygon().size(); ++e)
    strokeEdge(scene.polygon(), e, pal.polygonEdge, 2.25f, out);
  if (opt.showCentre) markCentre(scene, pal, opt, out);
  vertexLabelsAndHandles(scene.polygon(), pal, opt, out);
  if (opt.showGap) drawYGap(scene, pal, out);
  // degenerate cases that show: the input points normalisation dropped as hollow grey
  // rings, tiny edges magnified beside the polygon, a far offset's digits over it
  for (const Vec2 q : scene.droppedPoints())
    out.marker(at2(toGlm(q)), pal.textMuted, 15.0f, MarkerShape::Ring);
  drawDegenerateInsets(scene.polygon(), pal, out, opt.zoomInset);
}

void buildOverlay2D(const Scene2D& scene, const Palette& pal, const View2DOptions& opt,
                    DrawList& out) {
  out.clear();
  if (scene.hoveredCell() >= 0 && !scene.drag()) hoveredCell(scene, pal, opt, out);
  if (const auto& probe = scene.probe()) {
    if (scene.step() >= 0)
      probeSteps(scene, *probe, pal, opt, scene.step(), out);  // the query step by step
    else
      probeTrace(scene, *probe, pal, opt, out);
  }
  if (const auto& d = scene.drag()) dragMarker(scene, *d, pal, out);
  snapIndicator(scene, pal, out);
}

}  // namespace convexloc::viewer
