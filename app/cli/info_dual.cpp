// convexloc CLI — `info --intersect`: the line and plane methods built, measured and listed.
#include "info_dual.hpp"

#include <algorithm>
#include <cstdio>
#include <limits>
#include <utility>

#include "convexloc/generate2d.hpp"
#include "convexloc/intersect2d.hpp"
#include "convexloc/intersect3d.hpp"
#include "convexloc/methods.hpp"

namespace convexloc::cli {

const DualWords kLineWords{
    "Line methods (convexloc intersect: misses, touches or crosses the polygon)", "edge",
    "'dual size' counts the vertices of the dual polygon (the edges' unit normals and their\n"
    "antipodes), 'max' the dual's edges (the polygon's vertices) one cell lists."};
const DualWords kPlaneWords{
    "Plane methods (convexloc intersect: misses, touches or crosses the polyhedron)", "face",
    "'dual size' counts the plane faces of the dual polyhedron (the hull of the unit face\n"
    "normals), 'max' the dual's faces one cube-map cell lists."};

namespace {

// a line method's dual size (the dual polygon's vertices) and the polygon's edges
std::pair<std::size_t, std::size_t> sizesOf(const LineStats& s) {
  return {s.dualVertices, s.vertices};
}

// a plane method's dual size (the dual polyhedron's plane faces) and the polyhedron's faces
std::pair<std::size_t, std::size_t> sizesOf(const PlaneStats& s) {
  return {s.dualFaces, s.faces};
}

// one line (plane) method's row; the table's numbers from the dual's locator
template <class Intersector>
DualRow rowOf(const Intersector& x) {
  const auto s = x.stats();
  const auto [dualSize, elements] = sizesOf(s);
  DualRow row;
  row.name = toString(x.method());
  row.cost = costOf(x.method());
  row.dualSize = dualSize;
  if (const auto* dual = x.dualLocator()) {
    const auto table = dual->stats();
    row.cells = table.cells;
    row.entries = table.entries;
    row.maxPerCell = table.maxPerCell;
  }
  row.bytes = s.bytes;
  row.bytesPer = static_cast<double>(s.bytes) / static_cast<double>(elements);
  row.buildSeconds = s.buildSeconds;
  return row;
}

// queries the dual's work is measured on
constexpr int kMeasured = 1000;

// uniform in [lo, hi] enlarged by 10% of its width on either side, kept finite (for shapes
// near the largest doubles, where the width itself would overflow)
double around(Rng& rng, double lo, double hi) {
  const double t = rng.uniform(-0.1, 1.1), big = std::numeric_limits<double>::max();
  return std::clamp(lo * (1 - t) + hi * t, -big, big);
}

// a random line (plane) through two (three) random points of the enlarged box, traced
LineTrace randomTrace(const LineIntersector& x, Rng& rng, const Box2& b) {
  const Vec2 p{around(rng, b.lo.x, b.hi.x), around(rng, b.lo.y, b.hi.y)};
  const Vec2 q{around(rng, b.lo.x, b.hi.x), around(rng, b.lo.y, b.hi.y)};
  return x.trace(p, q == p ? Vec2{p.x + 1, p.y} : q);
}
PlaneTrace randomTrace(const PlaneIntersector& x, Rng& rng, const Box3& b) {
  Vec3 q[3];
  for (Vec3& p : q)
    p = {around(rng, b.lo.x, b.hi.x), around(rng, b.lo.y, b.hi.y), around(rng, b.lo.z, b.hi.z)};
  if (collinear(q[0], q[1], q[2])) q[2] = {q[2].x + 1, q[2].y, q[2].z + 2};
  return x.trace(q[0], q[1], q[2]);
}

// the dual's mean exact comparisons and climb moves per query on kMeasured random queries
template <class Intersector, class Box>
std::string measuredWork(const Intersector& x, const Box& box, const char* query) {
  Rng rng(1);
  double comparisons = 0, moves = 0;
  for (int k = 0; k < kMeasured; ++k) {
    const auto t = randomTrace(x, rng, box);
    comparisons += t.comparisons;
    moves += t.climbSteps;
  }
  return format(
      "The dual, on %d random %ss through the enlarged bounding box: %.2f exact\n"
      "comparisons and %.2f climb moves per %s on average.\n",
      kMeasured, query, comparisons / kMeasured, moves / kMeasured, query);
}

}  // namespace

// every line method built on the polygon, one row each; the dual's work measured
std::vector<DualRow> lineRows(const ConvexPolygon& polygon) {
  std::vector<DualRow> rows;
  for (LineMethod m : kAllLineMethods) {
    const LineIntersector x(polygon, m);
    rows.push_back(rowOf(x));
    if (m == LineMethod::Dual) rows.back().measured = measuredWork(x, polygon.bounds(), "line");
  }
  return rows;
}

// every plane method built on the polyhedron, one row each; the dual only when `buildDual`
std::vector<DualRow> planeRows(const ConvexPolyhedron& polyhedron, bool buildDual) {
  std::vector<DualRow> rows;
  for (PlaneMethod m : kAllPlaneMethods) {
    if (m != PlaneMethod::Dual || buildDual) {
      const PlaneIntersector x(polyhedron, m);
      rows.push_back(rowOf(x));
      if (m == PlaneMethod::Dual)
        rows.back().measured = measuredWork(x, polyhedron.bounds(), "plane");
    } else {
      DualRow& row = rows.emplace_back();
      row.name = toString(m);
      row.cost = costOf(m);
      row.built = false;
    }
  }
  return rows;
}

namespace {

// one row of the intersection table
void reportDualRow(Output& out, const DualRow& row) {
  out.put(format("  %-10s %-9s", row.name.c_str(), row.cost.c_str()));
  if (!row.built) {
    out.put(" not built: add --intersect (this build takes seconds per 10^5 faces)\n");
    return;
  }
  if (row.dualSize == 0) {
    out.put(format(" %9s", "-"));
  } else {
    out.put(format(" %9zu", row.dualSize));
  }
  if (row.cells == 0) {
    out.put(format(" %8s %9s %5s", "-", "-", "-"));
  } else {
    out.put(format(" %8zu %9zu %5zu", row.cells, row.entries, row.maxPerCell));
  }
  out.put(
      format(" %12zu %11.1f %10s\n", row.bytes, row.bytesPer, duration(row.buildSeconds).c_str()));
}

}  // namespace

// the intersection section: every line (plane) method, one row each
void reportDualTable(Output& out, const std::vector<DualRow>& rows, const DualWords& words) {
  out.put(format("\n%s\n", words.title));
  const std::string perElement = std::string("bytes/") + words.element;
  out.put(format("  %-10s %-9s %9s %8s %9s %5s %12s %11s %10s\n", "method", "query", "dual size",
                 "cells", "entries", "max", "bytes", perElement.c_str(), "build"));
  for (const DualRow& row : rows) reportDualRow(out, row);
  out.put(std::string("\n") + words.note +
          "\nEvery method decides exactly: the dual's table only proposes where its exact climb "
          "starts.\n");
  for (const DualRow& row : rows)
    if (!row.measured.empty()) out.put(row.measured);
}

}  // namespace convexloc::cli
