// convexloc-viewer — the build, animated.
#include "logic/teach/build_anim.hpp"

#include <algorithm>
#include <cmath>

#include "logic/base/format.hpp"
#include "logic/draw/cube_cells.hpp"
#include "logic/scene/scene2d.hpp"
#include "logic/scene/scene3d.hpp"
#include "logic/view/camera2d.hpp"

namespace convexloc::viewer {
namespace {

// a convex outline filled as a fan
void fan(const std::vector<Vec2>& outline, Rgba c, DrawList& out) {
  for (std::size_t i = 1; i + 1 < outline.size(); ++i)
    out.triangle(at2(toGlm(outline[0])), at2(toGlm(outline[i])), at2(toGlm(outline[i + 1])), c);
}

// the mean of an outline's corners (inside it: the outline is convex)
glm::dvec2 middleOf(const std::vector<Vec2>& outline) {
  glm::dvec2 s{0.0};
  for (const Vec2 p : outline) s += toGlm(p);
  return outline.empty() ? s : s / static_cast<double>(outline.size());
}

}  // namespace

std::vector<std::size_t> BuildOrder::countsAt(std::size_t k) const {
  std::vector<std::size_t> counts(cellCount_, 0);
  for (std::size_t e = 0; e < std::min(k, steps()); ++e)
    for (const std::size_t c : cellsOfEdge_[e]) ++counts[c];
  return counts;
}

void BuildPlayback::show(std::size_t k, std::size_t steps) {
  step = std::min(k, steps);
  playing = false;
  carry = 0.0;
  ++version;
}

void BuildPlayback::advance(double seconds, std::size_t steps) {
  if (!active || !playing) return;
  carry += seconds * edgesPerSecond;
  const auto whole = static_cast<std::size_t>(carry);
  if (whole == 0) return;
  carry -= static_cast<double>(whole);
  step = std::min(step + whole, steps);
  if (step == steps) playing = false;
  ++version;
}

namespace {

// each cell's count at `step`, which is clamped to the order's steps first
std::vector<std::size_t> countsUpTo(const BuildOrder& order, std::size_t& step) {
  step = std::min(step, order.steps());
  return order.countsAt(step);
}

}  // namespace

void buildAnimation2D(const Scene2D& scene, std::size_t step, const Palette& pal, DrawList& out) {
  const std::vector<Cell2D>& cells = scene.cells();
  if (cells.empty()) return;
  const ConvexPolygon& poly = scene.polygon();
  const BuildOrder order(cells, poly.size());
  const std::vector<std::size_t> counts = countsUpTo(order, step);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const bool crowded = counts[c] > kCrowdedCell;
    if (counts[c] > 0) fan(cells[c].outline, cellTint(pal, counts[c], 0, crowded), out);
    if (crowded) out.marker(at2(middleOf(cells[c].outline)), pal.crowded, 9.0f, MarkerShape::Cross);
  }
  if (step == 0) return;
  // the edge just added, and the cells that list it, flashing
  const std::size_t e = step - 1;
  for (const std::size_t c : order.cellsOf(e)) {
    const std::vector<Vec2>& o = cells[c].outline;
    fan(o, withAlpha(pal.hoverEdge, 0.22f), out);
    for (std::size_t i = 0; i < o.size(); ++i)
      out.segment(at2(toGlm(o[i])), at2(toGlm(o[(i + 1) % o.size()])), pal.hoverEdge, 2.0f);
  }
  const glm::dvec2 a = toGlm(poly.edgeStart(e)), b = toGlm(poly.edgeEnd(e));
  out.segment(at2(a), at2(b), pal.hoverEdge, 5.0f);
  std::string text = numbered("e", e);
  text.append(" added: ").append(std::to_string(step)).append(" of ");
  text.append(std::to_string(order.steps())).append(" edges");
  // written outside the edge, along its outward normal (y down on the screen), far enough
  // that the text's box (about 7 by 16 pixels a character) clears the edge
  const glm::dvec2 d = b - a;
  const double len = glm::length(d);
  const glm::vec2 n = len > 0.0
                          ? glm::vec2(static_cast<float>(d.y / len), static_cast<float>(d.x / len))
                          : glm::vec2(0.0f, -1.0f);
  const float reach =
      12.0f + std::abs(n.x) * 3.6f * static_cast<float>(text.size()) + std::abs(n.y) * 9.0f;
  out.label(at2(0.5 * (a + b)), std::move(text), pal.hoverEdge, n * reach);
}

void buildAnimation3D(const Scene3D& scene, std::size_t step, unsigned farFaces, const Palette& pal,
                      DrawList& out) {
  const std::vector<Cell3D>& cells = scene.cells();
  if (cells.empty()) return;
  const BuildOrder order(cells, scene.polyhedron().planeCount());
  const std::vector<std::size_t> counts = countsUpTo(order, step);
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const bool crowded = counts[c] > kCrowdedCell3D;
    const glm::dvec3 middle = 0.5 * (toGlm(cells[c].corners[0]) + toGlm(cells[c].corners[2]));
    if (counts[c] > 0 && (farFaces >> cells[c].cubeFace & 1u))
      fillCubeCell(placeOf(cells[c]), cellTint(pal, counts[c], 0, crowded), out);
    if (crowded) out.marker(middle, pal.crowded, 9.0f, MarkerShape::Cross);
  }
  if (step == 0) return;
  // the face just added, and the cells that list it, outlined
  const std::size_t f = step - 1;
  for (const std::size_t c : order.cellsOf(f)) {
    fillCubeCell(placeOf(cells[c]), withAlpha(pal.hoverEdge, 0.22f), out);
    outlineCubeCell(placeOf(cells[c]), pal.hoverEdge, 2.0f, out);
  }
  const ConvexPolyhedron& solid = scene.polyhedron();
  for (const std::uint32_t tri : solid.planeTriangles(f)) {
    const auto& t = solid.triangles()[tri];
    out.triangle(toGlm(solid.vertices()[t[0]]), toGlm(solid.vertices()[t[1]]),
                 toGlm(solid.vertices()[t[2]]), withAlpha(pal.hoverEdge, 0.6f));
  }
  const auto loop = solid.planeLoop(f);
  for (std::size_t k = 0; k < loop.size(); ++k)
    out.segment(toGlm(solid.vertices()[loop[k]]),
                toGlm(solid.vertices()[loop[(k + 1) % loop.size()]]), pal.hoverEdge, 3.0f);
  std::string text = numbered("f", f);
  text.append(" added: ").append(std::to_string(step)).append(" of ");
  text.append(std::to_string(order.steps())).append(" faces");
  glm::dvec3 middle(0.0);
  for (const std::uint32_t w : loop) middle += toGlm(solid.vertices()[w]);
  out.label(middle / static_cast<double>(loop.size()), std::move(text), pal.hoverEdge,
            {0.0f, -22.0f});
}

std::size_t buildStepCount(const Scene2D& scene) {
  return scene.cells().empty() ? 0 : scene.polygon().size();
}

std::size_t buildStepCount(const Scene3D& scene) {
  return scene.cells().empty() ? 0 : scene.polyhedron().planeCount();
}

void appendBuildStep(DrawList& structure, const DrawList& step) {
  structure.fills.insert(structure.fills.end(), step.fills.begin(), step.fills.end());
  structure.segments.insert(structure.segments.end(), step.segments.begin(), step.segments.end());
  structure.markers.insert(structure.markers.end(), step.markers.begin(), step.markers.end());
  structure.labels.insert(structure.labels.begin(), step.labels.begin(), step.labels.end());
}

}  // namespace convexloc::viewer
