// convexloc-viewer — the Lines mode's draw list.
#include "logic/dual/dual_view2d.hpp"

#include <string>
#include <vector>

#include "logic/base/format.hpp"
#include "logic/draw/structure2d.hpp"
#include "logic/view/camera2d.hpp"

namespace convexloc::viewer {
namespace {

// polar slab boundaries drawn in the inset at most (beyond, every other one, and so on)
constexpr std::size_t kMaxDualRays = 256;

// the colour of an exact sign
Rgba signColour(const Palette& p, int sign) {
  return sign > 0 ? p.positive : (sign < 0 ? p.negative : p.zero);
}

// a box's outline
void frameBox(const Box2& b, Rgba c, float width, DrawList& out, float dash = 0.0f) {
  const glm::dvec2 k[4] = {{b.lo.x, b.lo.y}, {b.hi.x, b.lo.y}, {b.hi.x, b.hi.y}, {b.lo.x, b.hi.y}};
  for (int i = 0; i < 4; ++i) out.segment(at2(k[i]), at2(k[(i + 1) % 4]), c, width, dash);
}

// the two frames and their titles
void frames(const DualInset& in, const Palette& pal, DrawList& out) {
  frameBox(in.frame, pal.box, 1.25f, out);
  out.label(at2({in.frame.lo.x, in.frame.hi.y}), "dual P*", pal.text, {34.0f, 12.0f});
  // the primal title at the bottom, where a line placed above the polygon does not run
  out.label(at2({in.primal.lo.x, in.primal.lo.y}), "primal P", pal.text, {38.0f, -12.0f});
}

// the dual polygon, its polar slab boundaries and its centre c*, mapped into the inset
void dualPolygon(const Lines2D& lines, const Palette& pal, DrawList& out) {
  const DualInset& in = lines.inset();
  const auto dual = lines.dualVertices();
  const auto centre = lines.dualCentre();
  const auto& cells = lines.dualCells();
  if (centre && !cells.empty()) {
    const std::size_t step = (cells.size() + kMaxDualRays - 1) / kMaxDualRays;
    for (std::size_t i = 0; i < cells.size(); i += step)
      out.segment(at2(in.toWorld(*centre)), at2(in.toWorld(cells[i].hitLo)), pal.structure, 1.0f);
  }
  for (std::size_t i = 1; i + 1 < dual.size(); ++i)
    out.triangle(at2(in.toWorld(dual[0])), at2(in.toWorld(dual[i])), at2(in.toWorld(dual[i + 1])),
                 pal.polygonFill);
  for (std::size_t i = 0; i < dual.size(); ++i)
    out.segment(at2(in.toWorld(dual[i])), at2(in.toWorld(dual[(i + 1) % dual.size()])),
                pal.polygonEdge, 2.0f);
  if (centre) out.marker(at2(in.toWorld(*centre)), pal.centre, 9.0f, MarkerShape::Cross);
}

// b's cell filled, the dual edges it lists drawn thick, b and the ray from c* through it
void dualCell(const Lines2D& lines, const Palette& pal, bool labels, DrawList& out) {
  const DualInset& in = lines.inset();
  const auto& line = lines.line();
  const auto b = lines.dualPoint();
  const auto centre = lines.dualCentre();
  if (!line || !b || !centre) return;
  const std::int64_t cell = line->trace.cell;
  const auto& cells = lines.dualCells();
  const Rgba mark = pal.hoverEdge;
  if (cell >= 0 && static_cast<std::size_t>(cell) < cells.size()) {
    const Cell2D& c = cells[static_cast<std::size_t>(cell)];
    for (std::size_t i = 1; i + 1 < c.outline.size(); ++i)
      out.triangle(at2(in.toWorld(c.outline[0])), at2(in.toWorld(c.outline[i])),
                   at2(in.toWorld(c.outline[i + 1])), withAlpha(mark, 0.28f));
    const auto dual = lines.dualVertices();
    for (const std::uint32_t e : c.edges)
      if (e < dual.size())
        out.segment(at2(in.toWorld(dual[e])), at2(in.toWorld(dual[(e + 1) % dual.size()])), mark,
                    5.0f);
  }
  out.segment(at2(in.toWorld(*centre)), at2(in.toWorld(*b)), pal.text, 1.25f, 5.0f);
  out.marker(at2(in.toWorld(*b)), pal.rim, 14.0f);
  out.marker(at2(in.toWorld(*b)), pal.text, 10.0f);
  if (labels) {
    out.label(at2(in.toWorld(*b)), "b", pal.text, {12.0f, -12.0f});
    // the cell's name halfway along the ray, where it does not cover b or P*'s edge
    const glm::dvec2 half = 0.5 * (in.toWorld(*centre) + in.toWorld(*b));
    if (cell >= 0) out.label(at2(half), "cell " + std::to_string(cell), mark, {34.0f, 0.0f});
  }
}

// the line across the primal frame, its two points, the clipped segment, entry and exit
void primalLine(const LineProbe2D& line, const DualInset& in, const Palette& pal, bool labels,
                DrawList& out) {
  glm::dvec2 a, b;
  if (clipLineToBox(toGlm(line.p1), toGlm(line.p2), in.primal, a, b))
    out.segment(at2(a), at2(b), pal.text, 1.5f);
  if (line.clipped)
    out.segment(at2(toGlm(line.clipped->a)), at2(toGlm(line.clipped->b)), pal.inside, 6.0f);
  const char* names[2] = {"p1", "p2"};
  const Vec2 ends[2] = {line.p1, line.p2};
  for (int i = 0; i < 2; ++i) {
    out.marker(at2(toGlm(ends[i])), pal.text, 11.0f, MarkerShape::Ring);
    if (labels) out.label(at2(toGlm(ends[i])), names[i], pal.text, {-14.0f, -14.0f});
  }
  if (line.hit.crossing == Crossing::Misses || !line.entry || !line.exit) return;
  const bool one = *line.entry == *line.exit;
  // yellow squares in a dark rim, as boundary points are drawn, readable on both themes
  for (const Vec2& q : {*line.entry, *line.exit}) {
    out.marker(at2(toGlm(q)), pal.rim, 14.0f, MarkerShape::Square);
    out.marker(at2(toGlm(q)), pal.boundary, 11.0f, MarkerShape::Square);
  }
  if (!labels) return;
  out.label(at2(toGlm(*line.entry)), one ? "entry = exit" : "entry", pal.boundary, {-20.0f, 16.0f});
  if (!one) out.label(at2(toGlm(*line.exit)), "exit", pal.boundary, {20.0f, 16.0f});
}

// the vertices the cell proposed (ringed in the cell's colour) and the extremes (by sign)
void primalVertices(const Lines2D& lines, const Palette& pal, bool labels, DrawList& out) {
  const auto& line = lines.line();
  const auto v = lines.intersector()->vertices();
  const LineTrace& t = line->trace;
  if (t.cell >= 0 && t.startMax < v.size() && t.startMin < v.size()) {
    out.marker(at2(toGlm(v[t.startMax])), pal.hoverEdge, 24.0f, MarkerShape::Ring);
    out.marker(at2(toGlm(v[t.startMin])), pal.hoverEdge, 24.0f, MarkerShape::Ring);
  }
  const ExtremeVertices& x = t.extremes;
  if (x.largest >= v.size() || x.smallest >= v.size()) return;
  out.marker(at2(toGlm(v[x.largest])), signColour(pal, x.largestSign), 13.0f);
  out.marker(at2(toGlm(v[x.smallest])), signColour(pal, x.smallestSign), 13.0f);
  if (!labels) return;
  out.label(at2(toGlm(v[x.largest])), "max f" + signText(x.largestSign),
            signColour(pal, x.largestSign), {0.0f, -24.0f});
  out.label(at2(toGlm(v[x.smallest])), "min f" + signText(x.smallestSign),
            signColour(pal, x.smallestSign), {0.0f, 24.0f});
}

}  // namespace

void buildLines2D(const Lines2D& lines, const Palette& pal, bool labels, DrawList& out) {
  if (!lines.enabled() || !lines.intersector()) return;
  frames(lines.inset(), pal, out);
  dualPolygon(lines, pal, out);
  const auto& line = lines.line();
  if (!line) return;
  dualCell(lines, pal, labels, out);
  primalLine(*line, lines.inset(), pal, labels, out);
  primalVertices(lines, pal, labels, out);
}

}  // namespace convexloc::viewer
