// stats() and cells(): memory stays under 64 bytes per edge plus a constant on every preset,
// the statistics agree with the cells, and the cells hold what they must: each polar cell
// the edges its wedge meets (checked exactly), each uniform slab every edge whose y range
// maps to it, each slab its two spanning edges.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "adversarial2d.hpp"
#include "convexloc/error.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/locate2d.hpp"
#include "convexloc/polygon.hpp"
#include "reference2d.hpp"
#include "shapes2d.hpp"

using namespace convexloc;

namespace {

// the memory bound of the issue: 64 bytes per edge plus a small constant
constexpr std::size_t kBytesPerEdge = 64;
constexpr std::size_t kBytesConstant = 4096;

// the statistics agree with each other and with the cells
void checkStatsAgainstCells(const std::string& where, const Stats2D& s,
                            const std::vector<Cell2D>& cells, std::size_t n) {
  EXPECT_EQ(s.edges, n) << where;
  EXPECT_GE(s.buildSeconds, 0.0) << where;
  EXPECT_GT(s.bytes, 0u) << where;
  EXPECT_DOUBLE_EQ(s.bytesPerEdge, static_cast<double>(s.bytes) / static_cast<double>(n)) << where;
  ASSERT_EQ(s.cells, cells.size()) << where;
  ASSERT_GT(s.cells, 0u) << where;
  ASSERT_EQ(s.histogram.size(), kCrowdedCell + 2) << where;
  std::vector<std::size_t> histogram(kCrowdedCell + 2, 0);
  std::size_t entries = 0, most = 0, crowded = 0;
  for (std::size_t i = 0; i < cells.size(); ++i) {
    EXPECT_EQ(cells[i].index, i) << where;
    const std::size_t k = cells[i].edges.size();
    entries += k;
    most = std::max(most, k);
    crowded += k > kCrowdedCell;
    ++histogram[std::min(k, histogram.size() - 1)];
    for (std::uint32_t e : cells[i].edges) EXPECT_LT(e, n) << where << " cell " << i;
  }
  EXPECT_EQ(s.entries, entries) << where;
  EXPECT_EQ(s.maxPerCell, most) << where;
  EXPECT_EQ(s.crowdedCells, crowded) << where;
  EXPECT_EQ(s.histogram, histogram) << where;
  std::size_t total = 0;
  for (std::size_t h : s.histogram) total += h;
  EXPECT_EQ(total, s.cells) << where;
  EXPECT_NEAR(s.meanPerCell, static_cast<double>(entries) / static_cast<double>(s.cells), 1e-9)
      << where;
  EXPECT_LE(s.meanPerCell, static_cast<double>(s.maxPerCell)) << where;
}

// the direction at pseudo-angle a in [0, 8): octant a/1, then u = 1, v = fraction (even
// octants) or u = 1 - fraction, v = 1 (odd), rotated by quarter turns; written independently
// of core, in long double
Vec2 directionAt(long double a) {
  const int octant = static_cast<int>(std::floor(a));
  const long double f = a - octant;
  long double u = 1, v = f;
  if (octant % 2) {
    u = 1 - f;
    v = 1;
  }
  switch (octant / 2) {
    case 0: return {static_cast<double>(u), static_cast<double>(v)};
    case 1: return {static_cast<double>(-v), static_cast<double>(u)};
    case 2: return {static_cast<double>(-u), static_cast<double>(-v)};
    default: return {static_cast<double>(v), static_cast<double>(-u)};
  }
}

// the pseudo-angle in [0, 8) of a direction, in long double
long double pseudoAngleOf(Vec2 d) {
  const long double x = d.x, y = d.y;
  long double u, v;
  int quad;
  if (y >= 0 && x > 0) {
    quad = 0;
    u = x;
    v = y;
  } else if (x <= 0 && y > 0) {
    quad = 1;
    u = y;
    v = -x;
  } else if (x < 0 && y <= 0) {
    quad = 2;
    u = -x;
    v = -y;
  } else {
    quad = 3;
    u = -y;
    v = x;
  }
  return v <= u ? 2 * quad + v / u : 2 * quad + 2 - u / v;
}

// the edges through which the ray from c along d leaves the polygon, decided exactly: edge e
// with its start clockwise of (or on) the ray and its end strictly counter-clockwise
std::vector<std::uint32_t> exitEdges(std::span<const Vec2> v, Vec2 c, Vec2 d) {
  std::vector<std::uint32_t> out;
  const std::size_t n = v.size();
  for (std::size_t e = 0; e < n; ++e)
    if (ref::crossDirection(c, d, v[e]) <= 0 && ref::crossDirection(c, d, v[(e + 1) % n]) > 0)
      out.push_back(static_cast<std::uint32_t>(e));
  return out;
}

// the listed edges are a run of consecutive edges, counter-clockwise
bool consecutiveRun(const std::vector<std::uint32_t>& edges, std::size_t n) {
  for (std::size_t k = 1; k < edges.size(); ++k)
    if (edges[k] != (edges[k - 1] + 1) % n) return false;
  return true;
}

// === Memory: 64 bytes per edge on any valid polygon

TEST(Memory, UnderSixtyFourBytesPerEdgeOnEveryPreset) {
  for (PolygonKind kind : kAllPolygonKinds) {
    const ConvexPolygon polygon(generatePolygon(kind, 100000, 1));
    const std::size_t n = polygon.size();
    for (Method2D m : kAllMethods2D) {
      const Stats2D s = Locator2D(polygon, m).stats();
      const std::string where = std::string(toString(kind)) + " " + std::string(toString(m));
      EXPECT_LE(s.bytes, kBytesPerEdge * n + kBytesConstant)
          << where << ": " << s.bytes << " bytes for " << n << " edges";
      EXPECT_EQ(s.edges, n) << where;
    }
  }
}

TEST(Memory, TinyEdgesPresetStaysSmallAtEveryResolutionDefault) {
  // edge lengths differing by 10^10: the paper's grid would need ~10^10 cells
  const ConvexPolygon polygon(generatePolygon(PolygonKind::TinyEdges, 100000, 1));
  const Stats2D polar = PolarLocator(polygon).stats();
  const Stats2D uniform = UniformLocator(polygon).stats();
  EXPECT_LE(polar.bytesPerEdge, 64.0);
  EXPECT_LE(uniform.bytesPerEdge, 64.0);
  // the crowded corner is searched, not subdivided
  EXPECT_GT(polar.crowdedCells, 0u);
  EXPECT_GT(polar.maxPerCell, kCrowdedCell);
}

TEST(Memory, RegularMillionGon) {
  const auto t0 = std::chrono::steady_clock::now();
  const ConvexPolygon polygon(generatePolygon(PolygonKind::Regular, std::size_t{1} << 20, 1));
  const std::size_t n = polygon.size();
  EXPECT_GT(n, std::size_t{1} << 19);
  for (Method2D m : {Method2D::Uniform, Method2D::Polar}) {
    const Locator2D locator(polygon, m);
    const Stats2D s = locator.stats();
    EXPECT_LE(s.bytes, kBytesPerEdge * n + kBytesConstant) << toString(m);
    // and it answers: the centre, a vertex, a point beyond a vertex
    EXPECT_EQ(locator.locate({0, 0}), Location::Inside);
    EXPECT_EQ(locator.locate(polygon.vertex(n / 3)), Location::Boundary);
    Vec2 v = polygon.vertex(n / 7);
    EXPECT_EQ(locator.locate({2 * v.x, 2 * v.y}), Location::Outside);
  }
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 60.0);
}

// === Statistics and cells on every shape of the matrix

class CellsAndStats : public testing::TestWithParam<std::size_t> {};

TEST_P(CellsAndStats, Agree) {
  const shapes::ShapeCase& shape = shapes::cases()[GetParam()];
  const ConvexPolygon polygon(shape.input);
  std::span<const Vec2> v = polygon.vertices();
  const std::size_t n = v.size();

  // halfplane: no cells
  {
    const HalfplaneLocator h(polygon);
    EXPECT_EQ(h.stats().cells, 0u);
    EXPECT_TRUE(h.cells().empty());
    EXPECT_EQ(h.stats().edges, n);
  }
  // wedge: the fan triangles (vertex 0, i, i + 1), each holding edge i
  {
    const std::vector<Cell2D> cells = WedgeLocator(polygon).cells();
    ASSERT_EQ(cells.size(), n - 2);
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const Cell2D& c = cells[i];
      EXPECT_EQ(c.outline, (std::vector<Vec2>{v[0], v[i + 1], v[i + 2]}));
      EXPECT_NE(std::find(c.edges.begin(), c.edges.end(), i + 1), c.edges.end());
    }
  }
  // slab: one slab between consecutive distinct vertex heights, holding the two edges
  // that span it
  {
    const SlabLocator slab(polygon);
    const std::vector<Cell2D> cells = slab.cells();
    std::vector<double> ys;
    for (Vec2 p : v) ys.push_back(p.y);
    std::sort(ys.begin(), ys.end());
    ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
    ASSERT_EQ(cells.size(), ys.size() - 1);
    checkStatsAgainstCells(shape.name + " slab", slab.stats(), cells, n);
    for (std::size_t s = 0; s < cells.size(); ++s) {
      EXPECT_EQ(cells[s].y0, ys[s]);
      EXPECT_EQ(cells[s].y1, ys[s + 1]);
      std::vector<std::uint32_t> spanning;
      for (std::uint32_t e = 0; e < n; ++e) {
        double a = v[e].y, b = v[(e + 1) % n].y;
        if (std::min(a, b) <= ys[s] && std::max(a, b) >= ys[s + 1]) spanning.push_back(e);
      }
      std::vector<std::uint32_t> got = cells[s].edges;
      std::sort(got.begin(), got.end());
      EXPECT_EQ(got, spanning) << shape.name << " slab " << s;
    }
  }
  // uniform: slab s lists exactly the edges whose y range maps over s, under slabOf
  for (std::uint32_t resolution : {0u, 1u, 7u}) {
    const UniformLocator uniform(polygon, resolution);
    const std::vector<Cell2D> cells = uniform.cells();
    const std::string where = shape.name + " uniform(" + std::to_string(resolution) + ")";
    if (resolution) {
      // a requested count is kept unless the height is beyond the index arithmetic
      EXPECT_TRUE(uniform.slabCount() == resolution || uniform.slabCount() == 1u) << where;
    }
    checkStatsAgainstCells(where, uniform.stats(), cells, n);
    std::vector<std::vector<std::uint32_t>> want(uniform.slabCount());
    for (std::uint32_t e = 0; e < n; ++e) {
      double a = v[e].y, b = v[(e + 1) % n].y;
      for (std::uint32_t s = uniform.slabOf(std::min(a, b)); s <= uniform.slabOf(std::max(a, b));
           ++s)
        want[s].push_back(e);
    }
    ASSERT_EQ(cells.size(), want.size()) << where;
    const Box2 box = polygon.bounds();
    EXPECT_EQ(cells.front().y0, box.lo.y) << where;
    EXPECT_EQ(cells.back().y1, box.hi.y) << where;
    for (std::size_t s = 0; s < cells.size(); ++s) {
      std::vector<std::uint32_t> got = cells[s].edges;
      std::sort(got.begin(), got.end());
      EXPECT_EQ(got, want[s]) << where << " slab " << s;
      EXPECT_LE(cells[s].y0, cells[s].y1) << where;
    }
  }
  // polar: each cell lists every edge its wedge meets
  for (std::uint32_t resolution : {0u, 1u, 5u}) {
    const PolarLocator polar(polygon, resolution);
    const std::string where = shape.name + " polar(" + std::to_string(resolution) + ")";
    const std::uint32_t q = polar.slabsPerOctant();
    if (resolution) {
      EXPECT_EQ(q, resolution) << where;
    }
    EXPECT_EQ(polar.cellCount(), 8 * q) << where;
    const std::vector<Cell2D> cells = polar.cells();
    if (cells.empty()) {
      // no double point strictly inside was found: no table, locate uses the fan
      EXPECT_EQ(polar.stats().entries, 0u) << where;
      EXPECT_FALSE(polar.centre().has_value()) << where;
      continue;
    }
    checkStatsAgainstCells(where, polar.stats(), cells, n);
    const Vec2 c = *polar.centre();
    EXPECT_EQ(ref::locate(v, c), Location::Inside) << where << ": the centre";
    const Box2 box = polar.box();
    const double size = std::max(box.hi.x - box.lo.x, box.hi.y - box.lo.y);
    for (std::size_t i : adversarial::spread(cells.size(), 256)) {
      const Cell2D& cell = cells[i];
      const std::string at = where + " cell " + std::to_string(i);
      EXPECT_EQ(cell.octant, static_cast<int>(i / q)) << at;
      EXPECT_TRUE(consecutiveRun(cell.edges, n)) << at;
      // the drawn borders are at pseudo-angles i / q and (i + 1) / q
      const long double lo = static_cast<long double>(i) / q,
                        hi = static_cast<long double>(i + 1) / q;
      EXPECT_NEAR(static_cast<double>(pseudoAngleOf(cell.dirLo)), static_cast<double>(lo), 1e-9)
          << at;
      if (i + 1 < cells.size()) {
        EXPECT_NEAR(static_cast<double>(pseudoAngleOf(cell.dirHi)), static_cast<double>(hi), 1e-9)
            << at;
      }
      // the drawn hits lie on the box
      for (Vec2 h : {cell.hitLo, cell.hitHi}) {
        const double tol = 1e-9 * size;
        EXPECT_TRUE(h.x >= box.lo.x - tol && h.x <= box.hi.x + tol && h.y >= box.lo.y - tol &&
                    h.y <= box.hi.y + tol)
            << at << " hit " << adversarial::show(h);
        const double toSide = std::min({std::fabs(h.x - box.lo.x), std::fabs(h.x - box.hi.x),
                                        std::fabs(h.y - box.lo.y), std::fabs(h.y - box.hi.y)});
        EXPECT_LE(toSide, tol) << at << " hit " << adversarial::show(h);
      }
      // rays inside the wedge, near both borders and in the middle: their exit edges are listed
      for (long double f : {1e-6L, 0.5L, 1 - 1e-6L}) {
        const Vec2 d = directionAt(lo + f * (hi - lo));
        const std::vector<std::uint32_t> exits = exitEdges(v, c, d);
        EXPECT_EQ(exits.size(), 1u) << at;
        for (std::uint32_t e : exits) {
          EXPECT_NE(std::find(cell.edges.begin(), cell.edges.end(), e), cell.edges.end())
              << at << ": the ray at fraction " << static_cast<double>(f) << " leaves through edge "
              << e << ", which the cell does not list";
        }
      }
      // a point far along the middle ray maps to the cell
      const Vec2 d = directionAt(lo + (hi - lo) / 2);
      const double scale = std::ldexp(1.0, std::ilogb(size));
      const Vec2 p{c.x + d.x * scale, c.y + d.y * scale};
      // (where the offsets from the centre keep their precision: not in the subnormal range)
      if (std::isfinite(p.x) && std::isfinite(p.y) && scale > 0x1p-1000 && q < (1u << 20)) {
        EXPECT_EQ(polar.cellIndex(p), static_cast<std::int64_t>(i))
            << at << " " << adversarial::show(p);
      }
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Shapes, CellsAndStats, testing::ValuesIn(shapes::caseIndices()),
                         shapes::CaseName());

// === Resolutions: chosen from N by default, settable, bounded

TEST(Resolution, DefaultsAndSettings) {
  const ConvexPolygon p(generatePolygon(PolygonKind::Regular, 1000, 1));
  const PolarLocator polar(p);
  EXPECT_GE(polar.slabsPerOctant(), 1u);
  EXPECT_EQ(polar.cellCount(), 8 * polar.slabsPerOctant());
  // the default grows with N: about one cell per two edges
  EXPECT_GE(polar.cellCount(), p.size() / 2);
  EXPECT_LE(polar.cellCount(), p.size() + 64);
  const UniformLocator uniform(p);
  EXPECT_GE(uniform.slabCount(), p.size() / 4);
  EXPECT_EQ(PolarLocator(p, 3).slabsPerOctant(), 3u);
  EXPECT_EQ(UniformLocator(p, 3).slabCount(), 3u);
  EXPECT_EQ(Locator2D(p, Method2D::Polar, 9).get<PolarLocator>()->slabsPerOctant(), 9u);
  EXPECT_EQ(Locator2D(p, Method2D::Uniform, 9).get<UniformLocator>()->slabCount(), 9u);
  EXPECT_EQ(Locator2D(p, Method2D::Slab, 9).get<PolarLocator>(), nullptr);
  EXPECT_THROW(PolarLocator(p, (1u << 23) + 1), UsageError);
  EXPECT_THROW(UniformLocator(p, (1u << 26) + 1), UsageError);
}

}  // namespace
