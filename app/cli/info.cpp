// convexloc CLI — `info`: a readable report of a polygon or a polyhedron and of the
// subdivisions each method builds on it.
//
// One report serves both dimensions: the method section and the table are templates over
// the locator, and Dimension<Locator> holds the words and numbers that differ (edges or
// faces, bisection or a walk). What a method is and costs comes from convexloc/methods.hpp.
// Every locator is built before anything is written, so a rejected resolution leaves
// stdout empty.
#include <algorithm>
#include <charconv>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

#include "commands.hpp"
#include "convexloc/format.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/intersect2d.hpp"
#include "convexloc/intersect3d.hpp"
#include "convexloc/locate2d.hpp"
#include "convexloc/locate3d.hpp"
#include "convexloc/methods.hpp"
#include "info_dual.hpp"

namespace convexloc::cli {
namespace {

// === Text

// the widest bar of the histogram, in characters
constexpr std::size_t kBarWidth = 40;

// "x lo .. hi,  y lo .. hi", exactly
std::string extent(const Box2& b) {
  return "x " + exactText(b.lo.x) + " .. " + exactText(b.hi.x) + ",  y " + exactText(b.lo.y) +
         " .. " + exactText(b.hi.y);
}

// "x lo .. hi,  y lo .. hi,  z lo .. hi", exactly
std::string extent(const Box3& b) {
  return extent(Box2{{b.lo.x, b.lo.y}, {b.hi.x, b.hi.y}}) + ",  z " + exactText(b.lo.z) + " .. " +
         exactText(b.hi.z);
}

// a byte count, with a binary unit when large
std::string byteCount(std::size_t bytes) {
  if (bytes < 10 * 1024) return format("%zu bytes", bytes);
  return format("%zu bytes (", bytes) + binarySize(bytes) + ")";
}

// "O(sqrt F) expected: walks across ...": the cost, what qualifies it, and how the method works
std::string how(const MethodInfo& info) {
  std::string text(info.cost);
  if (!info.costNote.empty()) text.append(" ").append(info.costNote);
  return text.append(": ").append(info.summary);
}

// one labelled line of a report
void field(Output& out, const std::string& label, const std::string& value) {
  out.put(format("  %-17s %s\n", label.c_str(), value.c_str()));
}

// === What differs between the dimensions

// the words a report uses for one dimension's things
struct Words {
  const char* shape;          // "polygon"
  const char* element;        // "edge": what a cell lists
  const char* elements;       // "edges"
  const char* crowdedSearch;  // how a crowded cell is searched
  const char* resolution;     // what the table's resolution sets
  const char* example;        // the method the table suggests to see in detail
};

// the words and numbers of a report on one dimension's locators
template <class Locator>
struct Dimension;

template <>
struct Dimension<Locator2D> {
  static constexpr Words kWords{"polygon", "edge", "edges", "bisection", "resolution", "polar"};
  static constexpr std::size_t kCrowded = kCrowdedCell;
  static constexpr auto kCount = &Stats2D::edges;
  static constexpr auto kBytesPer = &Stats2D::bytesPerEdge;
};

template <>
struct Dimension<Locator3D> {
  static constexpr Words kWords{
      "polyhedron",         "face",   "faces", "a walk or a zone's bisection",
      "cubemap resolution", "cubemap"};
  static constexpr std::size_t kCrowded = kCrowdedCell3D;
  static constexpr auto kCount = &Stats3D::faces;
  static constexpr auto kBytesPer = &Stats3D::bytesPerFace;
};

// === The shapes

// the polygon's section: what was kept, dropped, reversed, and its extent
void reportShape(Output& out, const ConvexPolygon& polygon, const std::vector<Vec2>& input) {
  std::vector<Vec2> sorted = input;
  std::sort(sorted.begin(), sorted.end(),
            [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  const std::size_t distinct =
      static_cast<std::size_t>(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
  // every repeat goes; the other dropped vertices lay exactly on an edge
  const std::size_t repeated = input.size() - distinct;
  const std::size_t collinear = polygon.droppedCount() - repeated;

  out.put("Polygon\n");
  field(out, "vertices", format("%zu kept of %zu read", polygon.size(), input.size()));
  if (polygon.droppedCount() > 0)
    field(out, "dropped",
          format("%zu repeated, %zu on an edge between their neighbours", repeated, collinear));
  field(
      out, "orientation",
      polygon.wasClockwise() ? "clockwise in the file (reversed)" : "counter-clockwise, as given");
  field(out, "bounding box", extent(polygon.bounds()));
  field(out, "area", format("%.10g", polygon.area()));
  out.put("\n");
}

// the polyhedron's section: what was kept, merged, reversed, and its extent
void reportShape(Output& out, const ConvexPolyhedron& p, std::size_t verticesRead) {
  out.put("Polyhedron\n");
  field(out, "vertices", format("%zu kept of %zu read", p.vertexCount(), verticesRead));
  if (p.mergedVertices() > 0 || p.unusedVertices() > 0)
    field(out, "dropped",
          format("%zu equal to an earlier one (merged), %zu used by no face", p.mergedVertices(),
                 p.unusedVertices()));
  field(out, "faces",
        format("%zu read, %zu triangles, %zu plane faces (coplanar triangles merged)",
               p.inputFaces(), p.faceCount(), p.planeCount()));
  if (p.flippedSlivers() > 0)
    field(out, "slivers",
          format("%zu zero-area triangles flipped away (the surface is unchanged)",
                 p.flippedSlivers()));
  field(out, "orientation",
        p.wasInverted() ? "clockwise seen from outside in the file (reversed)"
                        : "counter-clockwise seen from outside, as given");
  field(out, "bounding box", extent(p.bounds()));
  field(out, "volume", format("%.10g", p.volume()));
  field(out, "area", format("%.10g", p.area()));
  out.put("\n");
}

// === One method in detail

// the lines only polar and uniform have: the centre and the slabs
void reportDetails(Output& out, const Locator2D& locator, const ConvexPolygon& polygon,
                   const Stats2D& s, std::uint32_t) {
  if (const auto* polar = locator.get<PolarLocator>()) {
    // without a centre, vertex 0: the apex of the fan every query then bisects
    const Vec2 centre = polar->centre().value_or(polygon.vertex(0));
    field(out, "centre",
          exactText(centre) + (s.entries == 0 ? "  (no double point lies strictly inside: "
                                                "every query bisects the fan)"
                                              : ""));
    field(out, "slabs per octant",
          format("%u (%u cells)", polar->slabsPerOctant(), polar->cellCount()));
  }
  if (const auto* uniform = locator.get<UniformLocator>())
    field(out, "slabs", format("%u", uniform->slabCount()));
}

// the centre line of walk and cubemap
std::string centreText(const std::optional<Vec3>& centre) {
  if (centre) return exactText(*centre);
  return "none: no double point lies strictly inside (every query tests all faces)";
}

// the lines only walk and cubemap have: the centre, the grid and the quadtree; `asked` is the
// resolution the user asked for (0: none)
void reportDetails(Output& out, const Locator3D& locator, const ConvexPolyhedron&, const Stats3D& s,
                   std::uint32_t asked) {
  if (const auto* walk = locator.get<WalkLocator>())
    field(out, "centre", centreText(walk->centre()));
  const auto* cube = locator.get<CubemapLocator>();
  if (!cube) return;
  field(out, "centre", centreText(cube->centre()));
  if (!s.centred) return;
  const std::uint32_t g = s.resolution;
  std::string grid =
      format("%u x %u per cube face (%zu base cells)", g, g, 6 * static_cast<std::size_t>(g) * g);
  if (asked > 0 && asked != g) grid += format(", asked for %u: coarsened to fit memory", asked);
  field(out, "grid", grid);
  field(out, "quadtree",
        s.maxLevel > 0 ? format("%zu nodes, refined %d levels where crowded", s.nodes, s.maxLevel)
                       : format("%zu nodes, no cell refined", s.nodes));
}

// a text bar chart of the cells per edge (or face) count; `what` names the unit
template <class Stats>
void reportHistogram(Output& out, const Stats& s, const char* what) {
  std::size_t last = 0, peak = 0;
  for (std::size_t k = 0; k < s.histogram.size(); ++k) {
    if (s.histogram[k] > 0) last = k;
    peak = std::max(peak, s.histogram[k]);
  }
  if (peak == 0) return;
  out.put(format("\n  %-16s  cells\n", (std::string(what) + " per cell").c_str()));
  for (std::size_t k = 0; k <= last; ++k) {
    const std::size_t count = s.histogram[k];
    const bool open = k + 1 == s.histogram.size();
    std::size_t bar = (count * kBarWidth + peak - 1) / peak;  // a non-empty row shows a mark
    std::string label = std::to_string(k) + (open ? "+" : "");
    out.put(format("  %14s  %7zu", label.c_str(), count));
    out.put(bar > 0 ? "  " + std::string(bar, '#') + "\n" : "\n");
  }
}

// the cells' lines: how many, how full, how many crowded
template <class Locator, class Stats>
void reportCells(Output& out, const Stats& s) {
  using D = Dimension<Locator>;
  if (s.cells == 0) {
    field(out, "cells", "none: this method keeps no table of cells");
    return;
  }
  field(out, "cells", format("%zu", s.cells));
  field(out, "entries",
        format("%zu (%s listed, summed over the cells)", s.entries, D::kWords.elements));
  field(out, std::string(D::kWords.elements) + " per cell",
        format("max %zu, mean %.2f", s.maxPerCell, s.meanPerCell));
  field(out, "crowded cells",
        format("%zu (more than %zu %s: searched by %s)", s.crowdedCells, D::kCrowded,
               D::kWords.elements, D::kWords.crowdedSearch));
  if constexpr (std::is_same_v<Stats, Stats3D>)
    if (s.zoneCells > 0)
      field(out, "zone cells",
            format("%zu of them over a zone of thin faces (a cylinder's or a prism's side): "
                   "searched by bisection",
                   s.zoneCells));
}

// one method in detail, built on `shape`; `asked` is the resolution the user asked for (0: none)
template <class Locator, class Shape>
void reportMethod(Output& out, const Locator& locator, const Shape& shape, std::uint32_t asked) {
  using D = Dimension<Locator>;
  const auto s = locator.stats();
  const MethodInfo& info = methodInfo(locator.method());
  out.put(format("Method %s\n", std::string(info.name).c_str()));
  field(out, "how", how(info));
  reportDetails(out, locator, shape, s, asked);
  if constexpr (std::is_same_v<decltype(s), const Stats3D>)
    field(out, D::kWords.elements, format("%zu (%zu triangles)", s.faces, s.triangles));
  else
    field(out, D::kWords.elements, format("%zu", s.*D::kCount));
  reportCells<Locator>(out, s);
  field(out, "memory", byteCount(s.bytes));
  field(out, std::string("bytes per ") + D::kWords.element, format("%.1f", s.*D::kBytesPer));
  field(out, "build time", duration(s.buildSeconds));
  if (s.cells > 0) reportHistogram(out, s, D::kWords.elements);
}

// === Every method in a table

// one row of the table
template <class Locator>
void reportRow(Output& out, const Locator& locator) {
  using D = Dimension<Locator>;
  const auto s = locator.stats();
  const MethodInfo& info = methodInfo(locator.method());
  const std::string name(info.name), cost(info.cost);
  if (s.cells == 0) {
    out.put(format("  %-10s %-9s %8s %9s %5s %6s %8s", name.c_str(), cost.c_str(), "-", "-", "-",
                   "-", "-"));
  } else {
    out.put(format("  %-10s %-9s %8zu %9zu %5zu %6.2f %8zu", name.c_str(), cost.c_str(), s.cells,
                   s.entries, s.maxPerCell, s.meanPerCell, s.crowdedCells));
  }
  out.put(
      format(" %12zu %11.1f %10s\n", s.bytes, s.*D::kBytesPer, duration(s.buildSeconds).c_str()));
}

// every method, one row each
template <class Locator>
void reportTable(Output& out, const std::vector<Locator>& locators, std::uint32_t resolution) {
  using D = Dimension<Locator>;
  const std::string chosen = std::string("resolution chosen from the ") + D::kWords.shape;
  out.put(format("Methods (%s)\n", resolution
                                       ? format("%s %u", D::kWords.resolution, resolution).c_str()
                                       : chosen.c_str()));
  const std::string perElement = std::string("bytes/") + D::kWords.element;
  out.put(format("  %-10s %-9s %8s %9s %5s %6s %8s %12s %11s %10s\n", "method", "query", "cells",
                 "entries", "max", "mean", "crowded", "bytes", perElement.c_str(), "build"));
  for (const Locator& locator : locators) reportRow(out, locator);
  out.put(
      format("\n'max' and 'mean' count %s per cell; a crowded cell (more than %zu %s) is\n"
             "searched by %s. One method in detail, with a histogram of its cells:\n"
             "  convexloc info SHAPE --method %s\n",
             D::kWords.elements, D::kCrowded, D::kWords.elements, D::kWords.crowdedSearch,
             D::kWords.example));
}

// === The command, for either dimension

// Builds the locators `o` asks for on `shape` (`method` alone when --method was given, else
// every one of `all`), then writes the report: the shape's section by `reportShapeTo`, then
// the method in detail or the table.
template <class Locator, class Shape, class Method, std::size_t N, class ShapeSection,
          class DualRows>
void report(const InfoOptions& o, const Shape& shape, Method method, const Method (&all)[N],
            ShapeSection&& reportShapeTo, DualRows&& dualRows, const DualWords& dualWords) {
  const bool one = !o.method.empty();
  std::vector<Locator> locators;
  locators.reserve(N);
  std::vector<DualRow> rows;
  aboutFile(o.shape, [&] {
    if (one) {
      locators.emplace_back(shape, method, o.resolution);
    } else {
      for (Method m : all) locators.emplace_back(shape, m, o.resolution);
    }
    if (o.intersect || !one) rows = dualRows();
  });

  Output out;
  out.put("Shape " + displayName(o.shape) + "\n\n");
  reportShapeTo(out);
  if (one)
    reportMethod(out, locators.front(), shape, o.resolution);
  else
    reportTable(out, locators, o.resolution);
  if (!rows.empty()) reportDualTable(out, rows, dualWords);
  out.finish();
}

}  // namespace

std::string duration(double seconds) {
  if (seconds < 1e-3) return format("%.1f us", seconds * 1e6);
  if (seconds < 1.0) return format("%.2f ms", seconds * 1e3);
  return format("%.2f s", seconds);
}

void info2D(const InfoOptions& o) {
  const Method2D method = method2DOrFail(o.method);
  std::vector<Vec2> input;
  const ConvexPolygon polygon = loadPolygon(o.shape, &input, o.hull);
  report<Locator2D>(
      o, polygon, method, kAllMethods2D, [&](Output& out) { reportShape(out, polygon, input); },
      [&] { return lineRows(polygon); }, kLineWords);
}

void info3D(const InfoOptions& o) {
  const Method3D method = method3DOrFail(o.method);
  std::size_t verticesRead = 0;
  const ConvexPolyhedron polyhedron = loadPolyhedron(o.shape, &verticesRead, o.hull);
  report<Locator3D>(
      o, polyhedron, method, kAllMethods3D,
      [&](Output& out) { reportShape(out, polyhedron, verticesRead); },
      [&] { return planeRows(polyhedron, o.intersect); }, kPlaneWords);
}

}  // namespace convexloc::cli
