// convexloc-viewer — the smallest y-gap, marked.
#include "logic/draw/y_gap.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include "logic/base/format.hpp"

namespace convexloc::viewer {
namespace {

// a count or a size that may be astronomic: grouped digits up to 10^9, then 1.2e+12
std::string largeText(double v) {
  if (v < 1e9) return grouped(static_cast<std::size_t>(v + 0.5));
  return approx(v, 3);
}

// an arrowhead at `tip`, pointing along (0, dir) in world units of `size`
void arrowHead(glm::dvec2 tip, double dir, double size, Rgba c, DrawList& out) {
  out.segment(at2(tip), at2(tip + glm::dvec2(-0.45 * size, -dir * size)), c, 2.0f);
  out.segment(at2(tip), at2(tip + glm::dvec2(0.45 * size, -dir * size)), c, 2.0f);
}

}  // namespace

std::string yGapCostText(const Scene2D& scene) {
  const auto g = smallestYGap(scene.polygon());
  if (!g) return {};
  const double slabs = g->paperSlabs();
  std::string s = "smallest y-gap " + approx(g->gap(), 3) +
                  "\npaper: (ymax - ymin) / gap = " + approx(g->ymax - g->ymin, 3) + " / " +
                  approx(g->gap(), 3) + "\n  = " + largeText(slabs) + " slabs, " +
                  binarySize(slabs * kPaperBytesPerSlab) + " at least" +
                  (slabs <= 1000.0 ? " (the ticks left)" : "");
  if (scene.method() == Method2D::Uniform)
    s += "\nconvexloc: " + grouped(scene.effectiveResolution()) + " slabs (bounded), " +
         binarySize(scene.stats().bytes) + ";\n  crowded slabs list extra edges";
  return s;
}

std::optional<YGap> smallestYGap(const ConvexPolygon& polygon) {
  std::vector<double> ys;
  for (const Vec2& v : polygon.vertices()) ys.push_back(v.y);
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  if (ys.size() < 2) return std::nullopt;
  YGap g;
  g.ymin = ys.front();
  g.ymax = ys.back();
  g.lo = ys[0];
  g.hi = ys[1];
  for (std::size_t i = 1; i + 1 < ys.size(); ++i)
    if (ys[i + 1] - ys[i] < g.gap()) {
      g.lo = ys[i];
      g.hi = ys[i + 1];
    }
  return g;
}

void drawYGap(const Scene2D& scene, const Palette& pal, DrawList& out) {
  const auto g = smallestYGap(scene.polygon());
  if (!g) return;
  const Box2 box = scene.polygon().bounds();
  const double w = box.hi.x - box.lo.x, h = g->ymax - g->ymin;
  const double x0 = box.lo.x - 0.06 * w, x1 = box.hi.x + 0.08 * w, xa = box.hi.x + 0.04 * w;
  const Rgba c = pal.negative;
  for (const double y : {g->lo, g->hi}) out.segment(at2({x0, y}), at2({x1, y}), c, 1.75f, 7.0f);
  // the dimension: arrows from outside onto each line, as for a gap too small to write in
  const double len = 0.08 * h;
  out.segment(at2({xa, g->hi + len}), at2({xa, g->lo - len}), c, 2.0f);
  arrowHead({xa, g->hi}, -1.0, 0.3 * len, c, out);
  arrowHead({xa, g->lo}, 1.0, 0.3 * len, c, out);
  // the paper's slabs as a ruler left of the box, one tick a slab, where they can be told
  // apart; convexloc's own slabs are the structure drawn across the polygon
  if (g->paperSlabs() <= 1000.0)
    for (double y = g->ymin; y <= g->ymax + 0.5 * g->gap(); y += g->gap())
      out.segment(at2({x0 - 0.03 * w, y}), at2({x0 + 0.02 * w, y}), withAlpha(c, 0.8f), 1.25f);
  // the label above the gap's upper line, mid-polygon: the legend may take the right side
  out.label(at2({0.5 * (box.lo.x + box.hi.x), g->hi}), "smallest y-gap " + approx(g->gap(), 3), c,
            {0.0f, -16.0f});
}

}  // namespace convexloc::viewer
