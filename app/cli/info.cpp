// convexloc CLI — `info`: a readable report of a polygon or a polyhedron and of the
// subdivisions each method builds on it.
#include <algorithm>
#include <charconv>
#include <cstdio>
#include <iterator>
#include <optional>
#include <string>
#include <vector>

#include "commands.hpp"
#include "convexloc/locate2d.hpp"
#include "convexloc/locate3d.hpp"

namespace convexloc::cli {
namespace {

// the widest bar of the histogram, in characters
constexpr std::size_t kBarWidth = 40;

// printf into a std::string
template <class... Args>
std::string format(const char* fmt, Args... args) {
  char buf[256];
  int n = std::snprintf(buf, sizeof buf, fmt, args...);
  return std::string(buf, static_cast<std::size_t>(std::clamp(n, 0, 255)));
}

// the shortest text that reads back as the same double
std::string exact(double v) {
  char buf[32];
  auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
  return ec == std::errc{} ? std::string(buf, end) : format("%.17g", v);
}

// "(x, y)" exactly
std::string exact(Vec2 p) {
  std::string s = exact(p.x);
  s.append(", ").append(exact(p.y)).append(")");
  return s.insert(0, 1, '(');
}

// "(x, y, z)" exactly
std::string exact(Vec3 p) {
  std::string s = exact(p.x);
  s.append(", ").append(exact(p.y)).append(", ").append(exact(p.z)).append(")");
  return s.insert(0, 1, '(');
}

// a duration in the unit that suits it
std::string duration(double seconds) {
  if (seconds < 1e-3) return format("%.1f us", seconds * 1e6);
  if (seconds < 1.0) return format("%.2f ms", seconds * 1e3);
  return format("%.2f s", seconds);
}

// a byte count, with a binary unit when large
std::string byteCount(std::size_t bytes) {
  double b = static_cast<double>(bytes);
  if (bytes < 10 * 1024) return format("%zu bytes", bytes);
  if (bytes < 10 * 1024 * 1024) return format("%zu bytes (%.1f KiB)", bytes, b / 1024);
  return format("%zu bytes (%.1f MiB)", bytes, b / (1024 * 1024));
}

// how the method finds the answer, in one line
const char* describe(Method2D m) {
  switch (m) {
    case Method2D::Halfplane: return "O(N): tests the point against every edge";
    case Method2D::Wedge: return "O(log N): bisection over the fan of triangles from vertex 0";
    case Method2D::Slab: return "O(log N): binary search over slabs at the vertices' heights";
    case Method2D::Uniform: return "O(1): equal horizontal slabs, each listing its edges";
    case Method2D::Polar: return "O(1): polar slabs around a centre, each listing its edges";
  }
  return "";
}

// the cost of one query, in O notation
const char* cost(Method2D m) {
  switch (m) {
    case Method2D::Halfplane: return "O(N)";
    case Method2D::Wedge:
    case Method2D::Slab: return "O(log N)";
    case Method2D::Uniform:
    case Method2D::Polar: return "O(1)";
  }
  return "";
}

// one labelled line of a report
void field(Output& out, const char* label, const std::string& value) {
  out.put(format("  %-17s %s\n", label, value.c_str()));
}

// the polygon's section: what was kept, dropped, reversed, and its extent
void reportPolygon(Output& out, const ConvexPolygon& polygon, const std::vector<Vec2>& input) {
  std::vector<Vec2> sorted = input;
  std::sort(sorted.begin(), sorted.end(),
            [](Vec2 a, Vec2 b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  const std::size_t distinct =
      static_cast<std::size_t>(std::unique(sorted.begin(), sorted.end()) - sorted.begin());
  // every repeat goes; the other dropped vertices lay exactly on an edge
  const std::size_t repeated = input.size() - distinct;
  const std::size_t collinear = polygon.droppedCount() - repeated;
  const Box2 b = polygon.bounds();

  out.put("Polygon\n");
  field(out, "vertices", format("%zu kept of %zu read", polygon.size(), input.size()));
  if (polygon.droppedCount() > 0)
    field(out, "dropped",
          format("%zu repeated, %zu on an edge between their neighbours", repeated, collinear));
  field(
      out, "orientation",
      polygon.wasClockwise() ? "clockwise in the file (reversed)" : "counter-clockwise, as given");
  field(out, "bounding box",
        "x " + exact(b.lo.x) + " .. " + exact(b.hi.x) + ",  y " + exact(b.lo.y) + " .. " +
            exact(b.hi.y));
  field(out, "area", format("%.10g", polygon.area()));
  out.put("\n");
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

// one method in detail
void reportMethod(Output& out, const Locator2D& locator, const ConvexPolygon& polygon) {
  const Method2D m = locator.method();
  const Stats2D s = locator.stats();
  out.put(format("Method %s\n", std::string(toString(m)).c_str()));
  field(out, "how", describe(m));
  if (const auto* polar = locator.get<PolarLocator>()) {
    // without a centre the report names the fan's apex, vertex 0, where queries start
    const Vec2 centre = polar->centre().value_or(polygon.vertex(0));
    field(out, "centre",
          exact(centre) + (s.entries == 0 ? "  (no double point lies strictly inside: "
                                            "every query bisects the fan)"
                                          : ""));
    field(out, "slabs per octant",
          format("%u (%u cells)", polar->slabsPerOctant(), polar->cellCount()));
  }
  if (const auto* uniform = locator.get<UniformLocator>())
    field(out, "slabs", format("%u", uniform->slabCount()));
  field(out, "edges", format("%zu", s.edges));
  if (s.cells == 0) {
    field(out, "cells", "none: this method keeps no table of cells");
  } else {
    field(out, "cells", format("%zu", s.cells));
    field(out, "entries", format("%zu (edges listed, summed over the cells)", s.entries));
    field(out, "edges per cell", format("max %zu, mean %.2f", s.maxPerCell, s.meanPerCell));
    field(out, "crowded cells",
          format("%zu (more than %zu edges: searched by bisection)", s.crowdedCells, kCrowdedCell));
  }
  field(out, "memory", byteCount(s.bytes));
  field(out, "bytes per edge", format("%.1f", s.bytesPerEdge));
  field(out, "build time", duration(s.buildSeconds));
  if (s.cells > 0) reportHistogram(out, s, "edges");
}

// every method, one row each
void reportTable(Output& out, const std::vector<Locator2D>& locators, std::uint32_t resolution) {
  out.put(format("Methods (%s)\n", resolution ? format("resolution %u", resolution).c_str()
                                              : "resolution chosen from the polygon"));
  out.put(format("  %-10s %-9s %8s %9s %5s %6s %8s %12s %11s %10s\n", "method", "query", "cells",
                 "entries", "max", "mean", "crowded", "bytes", "bytes/edge", "build"));
  for (const Locator2D& locator : locators) {
    const Method2D m = locator.method();
    const Stats2D s = locator.stats();
    const std::string name(toString(m));
    if (s.cells == 0) {
      out.put(format("  %-10s %-9s %8s %9s %5s %6s %8s", name.c_str(), cost(m), "-", "-", "-", "-",
                     "-"));
    } else {
      out.put(format("  %-10s %-9s %8zu %9zu %5zu %6.2f %8zu", name.c_str(), cost(m), s.cells,
                     s.entries, s.maxPerCell, s.meanPerCell, s.crowdedCells));
    }
    out.put(
        format(" %12zu %11.1f %10s\n", s.bytes, s.bytesPerEdge, duration(s.buildSeconds).c_str()));
  }
  out.put(
      format("\n'max' and 'mean' count edges per cell; a crowded cell (more than %zu edges) is\n"
             "searched by bisection. One method in detail, with a histogram of its cells:\n"
             "  convexloc info SHAPE --method polar\n",
             kCrowdedCell));
}

}  // namespace

void info2D(const InfoOptions& o) {
  const bool one = !o.method.empty();
  const Method2D method = method2DOrFail(o.method);
  std::vector<Vec2> input;
  const ConvexPolygon polygon = loadPolygon(o.shape, &input);

  // build everything before writing, so that a rejected resolution leaves stdout empty
  std::vector<Locator2D> locators;
  locators.reserve(std::size(kAllMethods2D));
  aboutFile(o.shape, [&] {
    if (one) {
      locators.emplace_back(polygon, method, o.resolution);
    } else {
      for (Method2D m : kAllMethods2D) locators.emplace_back(polygon, m, o.resolution);
    }
  });

  Output out;
  out.put("Shape " + displayName(o.shape) + "\n\n");
  reportPolygon(out, polygon, input);
  if (one)
    reportMethod(out, locators.front(), polygon);
  else
    reportTable(out, locators, o.resolution);
  out.finish();
}

// === Polyhedra

namespace {

// how the method finds the answer, in one line
const char* describe(Method3D m) {
  switch (m) {
    case Method3D::Halfspace: return "O(F): tests the point against every face plane";
    case Method3D::Walk:
      return "O(sqrt F) expected: walks across the faces toward the ray from the centre, then "
             "tests one plane";
    case Method3D::Cubemap:
      return "O(1): a grid on each face of a cube around the centre, each cell listing the faces "
             "it sees";
  }
  return "";
}

// the cost of one query, in O notation
const char* cost(Method3D m) {
  switch (m) {
    case Method3D::Halfspace: return "O(F)";
    case Method3D::Walk: return "O(sqrt F)";
    case Method3D::Cubemap: return "O(1)";
  }
  return "";
}

// "x lo .. hi,  y lo .. hi,  z lo .. hi", exactly
std::string extent(const Box3& b) {
  return "x " + exact(b.lo.x) + " .. " + exact(b.hi.x) + ",  y " + exact(b.lo.y) + " .. " +
         exact(b.hi.y) + ",  z " + exact(b.lo.z) + " .. " + exact(b.hi.z);
}

// the polyhedron's section: what was kept, merged, reversed, and its extent
void reportPolyhedron(Output& out, const ConvexPolyhedron& p, std::size_t verticesRead) {
  out.put("Polyhedron\n");
  field(out, "vertices", format("%zu kept of %zu read", p.vertexCount(), verticesRead));
  if (p.mergedVertices() > 0 || p.unusedVertices() > 0)
    field(out, "dropped",
          format("%zu equal to an earlier one (merged), %zu used by no face", p.mergedVertices(),
                 p.unusedVertices()));
  field(out, "faces", format("%zu read, %zu triangles", p.inputFaces(), p.faceCount()));
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

// the centre line of walk and cubemap
std::string centreText(const std::optional<Vec3>& centre) {
  if (centre) return exact(*centre);
  return "none: no double point lies strictly inside (every query tests all faces)";
}

// one method in detail; `asked` is the resolution the user asked for (0: none)
void reportMethod(Output& out, const Locator3D& locator, std::uint32_t asked) {
  const Method3D m = locator.method();
  const Stats3D s = locator.stats();
  out.put(format("Method %s\n", std::string(toString(m)).c_str()));
  field(out, "how", describe(m));
  if (const auto* walk = locator.get<WalkLocator>())
    field(out, "centre", centreText(walk->centre()));
  if (const auto* cube = locator.get<CubemapLocator>()) {
    field(out, "centre", centreText(cube->centre()));
    if (s.centred) {
      const std::uint32_t g = s.resolution;
      std::string grid = format("%u x %u per cube face (%zu base cells)", g, g,
                                6 * static_cast<std::size_t>(g) * g);
      if (asked > 0 && asked != g) grid += format(", asked for %u: coarsened to fit memory", asked);
      field(out, "grid", grid);
      field(out, "quadtree",
            s.maxLevel > 0
                ? format("%zu nodes, refined %d levels where crowded", s.nodes, s.maxLevel)
                : format("%zu nodes, no cell refined", s.nodes));
    }
  }
  field(out, "faces", format("%zu", s.faces));
  if (s.cells == 0) {
    field(out, "cells", "none: this method keeps no table of cells");
  } else {
    field(out, "cells", format("%zu", s.cells));
    field(out, "entries", format("%zu (faces listed, summed over the cells)", s.entries));
    field(out, "faces per cell", format("max %zu, mean %.2f", s.maxPerCell, s.meanPerCell));
    field(out, "crowded cells",
          format("%zu (more than %zu faces: searched by a walk)", s.crowdedCells, kCrowdedCell3D));
  }
  field(out, "memory", byteCount(s.bytes));
  field(out, "bytes per face", format("%.1f", s.bytesPerFace));
  field(out, "build time", duration(s.buildSeconds));
  if (s.cells > 0) reportHistogram(out, s, "faces");
}

// every method, one row each
void reportTable(Output& out, const std::vector<Locator3D>& locators, std::uint32_t resolution) {
  out.put(format("Methods (%s)\n", resolution ? format("cubemap resolution %u", resolution).c_str()
                                              : "resolution chosen from the polyhedron"));
  out.put(format("  %-10s %-9s %8s %9s %5s %6s %8s %12s %11s %10s\n", "method", "query", "cells",
                 "entries", "max", "mean", "crowded", "bytes", "bytes/face", "build"));
  for (const Locator3D& locator : locators) {
    const Method3D m = locator.method();
    const Stats3D s = locator.stats();
    const std::string name(toString(m));
    if (s.cells == 0) {
      out.put(format("  %-10s %-9s %8s %9s %5s %6s %8s", name.c_str(), cost(m), "-", "-", "-", "-",
                     "-"));
    } else {
      out.put(format("  %-10s %-9s %8zu %9zu %5zu %6.2f %8zu", name.c_str(), cost(m), s.cells,
                     s.entries, s.maxPerCell, s.meanPerCell, s.crowdedCells));
    }
    out.put(
        format(" %12zu %11.1f %10s\n", s.bytes, s.bytesPerFace, duration(s.buildSeconds).c_str()));
  }
  out.put(
      format("\n'max' and 'mean' count faces per cell; a crowded cell (more than %zu faces) is\n"
             "searched by a walk. One method in detail, with a histogram of its cells:\n"
             "  convexloc info SHAPE --method cubemap\n",
             kCrowdedCell3D));
}

}  // namespace

void info3D(const InfoOptions& o) {
  const bool one = !o.method.empty();
  const Method3D method = method3DOrFail(o.method);
  std::size_t verticesRead = 0;
  const ConvexPolyhedron polyhedron = loadPolyhedron(o.shape, &verticesRead);

  // build everything before writing, so that a rejected resolution leaves stdout empty
  std::vector<Locator3D> locators;
  locators.reserve(std::size(kAllMethods3D));
  aboutFile(o.shape, [&] {
    if (one) {
      locators.emplace_back(polyhedron, method, o.resolution);
    } else {
      for (Method3D m : kAllMethods3D) locators.emplace_back(polyhedron, m, o.resolution);
    }
  });

  Output out;
  out.put("Shape " + displayName(o.shape) + "\n\n");
  reportPolyhedron(out, polyhedron, verticesRead);
  if (one)
    reportMethod(out, locators.front(), o.resolution);
  else
    reportTable(out, locators, o.resolution);
  out.finish();
}

}  // namespace convexloc::cli
