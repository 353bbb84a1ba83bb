// convexloc-viewer — the legend's rows.
#include "logic/app/legend.hpp"

#include <algorithm>
#include <cstdio>
#include <string>
#include <utility>

#include "logic/base/format.hpp"
#include "logic/draw/y_gap.hpp"
#include "logic/teach/build_anim.hpp"

namespace convexloc::viewer {
namespace {

// which tints the cells show: some cell listing more than `base` and at most `crowdedAbove`
// (tinted as listing extra), some listing more than `crowdedAbove` (crowded)
template <class Cell>
std::pair<bool, bool> tintsIn(const std::vector<Cell>& cells,
                              const std::vector<std::uint32_t> Cell::*list, std::size_t base,
                              std::size_t crowdedAbove) {
  bool extra = false, crowded = false;
  for (const Cell& c : cells) {
    const std::size_t n = (c.*list).size();
    extra |= n > base && n <= crowdedAbove;
    crowded |= n > crowdedAbove;
  }
  return {extra, crowded};
}

LegendRow box(Rgba fill, Rgba edge, std::string text) {
  return {Swatch::Box, fill, edge, 1.0f, std::move(text), {}, {}};
}

LegendRow line(Rgba c, bool dashed, float width, std::string text) {
  return {dashed ? Swatch::DashedLine : Swatch::Line, c, c, width, std::move(text), {}, {}};
}

// the method, its size, and a row per class with its count (faded when hidden)
template <class Scene>
Legend heading(const Model& model, const Scene& scene, std::size_t elements, const char* noun) {
  Legend g;
  g.title = std::string(toString(scene.method()));
  g.subtitle = grouped(elements) + " " + noun;
  if (scene.stats().cells) g.subtitle += ", " + grouped(scene.stats().cells) + " cells";
  g.classes = classLegendRows(model, scene.counts(), scene.points().size());
  return g;
}

// the Lines mode: what the marks in both views are
Legend linesLegend(const Palette& pal) {
  Legend g;
  g.title = "Lines: the dual problem";
  g.rows = {line(pal.text, false, 1.5f, "the line through p1, p2"),
            line(pal.inside, false, 4.0f, "segment p1-p2 clipped"),
            box(pal.boundary, pal.rim, "entry and exit"),
            box(pal.positive, pal.negative, "extreme vertices (sign of f)"),
            box(withAlpha(pal.hoverEdge, 0.28f), pal.hoverEdge, "b's dual cell, its proposals"),
            line(pal.structure, false, 1.0f, "polar slabs of P*")};
  return g;
}

// the lines of the method's structure, as structure2d draws them (dense ones left out)
void structureRows(const Scene2D& scene, const Palette& pal, const View2DOptions& opt, Legend& g) {
  const bool dense = scene.cells().size() > kMaxCellLines;
  switch (scene.method()) {
    case Method2D::Halfplane:
      g.rows.push_back(line(pal.structure, false, 1.0f, "the edges' lines"));
      break;
    case Method2D::Wedge:
      if (!dense) g.rows.push_back(line(pal.structure, false, 1.0f, "diagonals from vertex 0"));
      break;
    case Method2D::Slab:
    case Method2D::Uniform:
      if (!dense) g.rows.push_back(line(pal.structure, false, 1.0f, "slab boundaries"));
      break;
    case Method2D::Polar:
      if (!scene.centre()) break;
      if (opt.showOctants && scene.effectiveResolution() > 0)
        g.rows.push_back(line(pal.octant, true, 1.6f, "octant lines through x_T"));
      if (!dense) g.rows.push_back(line(pal.structure, false, 1.0f, "polar slab boundaries"));
      break;
  }
}

// the build animation's rows: the cells the edge just added went to, the tint of the edges
// held so far, the crowded cells
void buildRows(const Model& model, const Palette& pal, Legend& g) {
  const bool flat = model.dim == Dim::Two;
  const char* noun = flat ? "edge" : "face";
  const std::size_t total = flat ? buildStepCount(model.scene2d) : buildStepCount(model.scene3d());
  const std::size_t crowdedAbove = flat ? kCrowdedCell : kCrowdedCell3D;
  const std::size_t most =
      flat ? model.scene2d.stats().maxPerCell : model.scene3d().stats().maxPerCell;
  g.subtitle = "build: " + std::to_string(model.build.step) + " of " + std::to_string(total) + " " +
               noun + "s in";
  g.rows.push_back(box(withAlpha(pal.hoverEdge, 0.22f), pal.hoverEdge,
                       std::string("cells listing the ") + noun + " just added"));
  g.rows.push_back(box(cellTint(pal, 2, 0, false), withAlpha(pal.extraEdges, 0.8f),
                       std::string("tint: ") + noun + "s held so far"));
  if (most > crowdedAbove)
    g.rows.push_back(
        box(cellTint(pal, 0, 0, true), withAlpha(pal.crowded, 0.8f),
            "crowded (> " + std::to_string(crowdedAbove) + " " + noun + "s), crossed"));
}

Legend legend2D(const Model& model) {
  const Palette& pal = paletteFor(model.settings.theme);
  if (model.lines2d.enabled()) return linesLegend(pal);
  const Scene2D& scene = model.scene2d;
  const View2DOptions& opt = model.settings.view2d;
  Legend g = heading(model, scene, scene.stats().edges, "edges");
  const Method2D m = scene.method();
  const std::size_t base = baseEdgesPerCell(m);
  // only what is drawn: a tint's row when some cell has that tint
  const auto [extra, crowded] = tintsIn(scene.cells(), &Cell2D::edges, base, kCrowdedCell);
  if (model.build.active) {
    buildRows(model, pal, g);
  } else if (opt.showStructure && opt.showTints && extra) {
    g.rows.push_back(box(cellTint(pal, base + 1, base, false), withAlpha(pal.extraEdges, 0.8f),
                         "cell listing " + std::to_string(base + 1) + "+ edges"));
  }
  if (!model.build.active && opt.showStructure && opt.showTints && crowded)
    g.rows.push_back(box(cellTint(pal, 0, base, true), withAlpha(pal.crowded, 0.8f),
                         "crowded cell (bisection)"));
  if (opt.showStructure) structureRows(scene, pal, opt, g);
  if (opt.showBox) g.rows.push_back(line(pal.box, true, 1.2f, "bounding box"));
  if (const std::size_t n = scene.droppedPoints().size())
    g.rows.push_back({Swatch::Disc,
                      pal.background,
                      pal.textMuted,
                      1.0f,
                      std::to_string(n) + " input point" + (n == 1 ? "" : "s") +
                          " dropped (repeated or collinear)",
                      {},
                      {}});
  // the paper's rule (Fig. 5): the smallest y-gap and what it costs, beside convexloc's
  if (opt.showGap) g.rows.push_back(line(pal.negative, true, 1.6f, yGapCostText(scene)));
  return g;
}

// the Planes mode's legend: the marks in both views
Legend planesLegend(const Palette& pal) {
  Legend g;
  g.title = "Planes: the dual problem";
  g.rows = {box(pal.slicePlane, pal.box, "the plane through q1, q2, q3"),
            box(withAlpha(pal.inside, 0.6f), pal.inside, "its section, per core"),
            box(pal.positive, pal.negative, "extreme vertices (sign of G)"),
            box(withAlpha(pal.hoverEdge, 0.35f), pal.hoverEdge, "cells of y, -y; their proposals")};
  return g;
}

Legend legend3D(const Model& model) {
  const Palette& pal = paletteFor(model.settings.theme);
  if (model.planes3d.enabled()) return planesLegend(pal);
  const Scene3D& scene = model.scene3d();
  const View3DOptions& opt = model.settings.view3d;
  Legend g = heading(model, scene, scene.stats().faces, "faces");
  const auto& cells = scene.cells();
  const auto [extra, crowded] = tintsIn(cells, &Cell3D::faces, kBaseFacesPerCell, kCrowdedCell3D);
  if (model.build.active) {
    buildRows(model, pal, g);
  } else if (opt.showCube && opt.showTints && extra) {
    g.rows.push_back(box(cellTint(pal, 2, kBaseFacesPerCell, false),
                         withAlpha(pal.extraEdges, 0.8f), "cell listing 2+ faces"));
  }
  if (!model.build.active && opt.showCube && opt.showTints && crowded)
    g.rows.push_back(box(cellTint(pal, 0, kBaseFacesPerCell, true), withAlpha(pal.crowded, 0.8f),
                         "crowded cell (walk)"));
  if (!cells.empty() && opt.showCube)
    g.rows.push_back(line(pal.cube, false, 1.0f, "cube-map grid around x_T"));
  // the pinned cells (Fig. 7): their pyramids from x_T and the faces they list
  for (const auto& [k, colour] : {std::pair{scene.pinnedCell(), pal.crowded},
                                  std::pair{scene.secondPinnedCell(), pal.inside}}) {
    if (k < 0) continue;
    const std::size_t faces = cells[static_cast<std::size_t>(k)].faces.size();
    g.rows.push_back(box(withAlpha(colour, 0.25f), colour,
                         "cell " + std::to_string(k) + ": its pyramid lists " +
                             std::to_string(faces) + (faces == 1 ? " face" : " faces")));
  }
  // the section's row only when the plane cuts the polyhedron
  const auto& cut = scene.section().classes;
  if (opt.showSlice &&
      std::any_of(cut.begin(), cut.end(), [](Location l) { return l != Location::Outside; }))
    g.rows.push_back(box(withAlpha(pal.inside, 0.45f), withAlpha(pal.inside, 0.8f),
                         "section: inside, per core"));
  return g;
}

}  // namespace

std::vector<LegendRow> classLegendRows(const Model& model, const std::array<std::size_t, 3>& counts,
                                       std::size_t total) {
  const Palette& pal = paletteFor(model.settings.theme);
  std::vector<LegendRow> rows;
  for (Location l : {Location::Inside, Location::Boundary, Location::Outside}) {
    const bool shown = (model.settings.visibleMask & classBit(l)) != 0;
    const std::size_t k = counts[static_cast<std::size_t>(l)];
    LegendRow r;
    r.swatch = Swatch::Disc;
    r.colour = shown ? colourOf(pal, l) : withAlpha(colourOf(pal, l), 0.25f);
    r.edge = pal.rim;
    r.text = std::string(toString(l));
    if (total) {
      r.count = grouped(k);
      r.share = percentText(k, total);
    }
    rows.push_back(std::move(r));
  }
  return rows;
}

Legend legendOf(const Model& model) {
  return model.dim == Dim::Two ? legend2D(model) : legend3D(model);
}

std::string percentText(std::size_t part, std::size_t whole) {
  if (!whole) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.1f%%",
                100.0 * static_cast<double>(part) / static_cast<double>(whole));
  return buf;
}

glm::dvec2 legendBoxSize(const Legend& g, const MeasureText& measure, double font, double padding,
                         double spacing) {
  const double f = font / 1.164, line = font + spacing, sw = 0.7 * f + 0.5 * f;
  auto width = [&](const std::string& t) { return t.empty() ? 0.0 : measure(t).x; };
  double name = 0.0, count = 0.0, share = 0.0, rows = 0.0;
  for (const LegendRow& r : g.classes) {
    name = std::max(name, width(r.text));
    count = std::max(count, width(r.count));
    share = std::max(share, width(r.share));
  }
  // a mark's text may run over lines (the y-gap's cost)
  std::size_t rowLines = 0;
  for (const LegendRow& r : g.rows)
    for (const std::string& t : breakAtSpaces(r.text, 1e300, measure)) {
      rows = std::max(rows, sw + width(t));
      ++rowLines;
    }
  const double classes = sw + name + (count > 0.0 ? 0.8 * f + count + 0.6 * f + share : 0.0);
  const double heading = width(g.title) + (g.subtitle.empty() ? 0.0 : 0.4 * f + width(g.subtitle));
  const double gap = !g.rows.empty() && !g.classes.empty() ? spacing : 0.0;
  // an em to spare: the window's table and swatches put their own gaps in the rows
  return {std::max({heading, classes, rows}) + 1.0 * f + 2.0 * padding,
          line * static_cast<double>(1 + g.classes.size() + rowLines) + gap + 2.0 * padding};
}

}  // namespace convexloc::viewer
