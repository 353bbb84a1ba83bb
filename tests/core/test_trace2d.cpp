// trace(p): it reports what locate(p) does. The result equals locate(p) and the reference,
// every recorded predicate sign is the exact sign (recomputed with the reference), polar
// traces name the cell cellIndex gives, slab and uniform traces name the cell holding p.y, and
// the edges tested are edges the cell lists.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "adversarial2d.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/locate2d.hpp"
#include "convexloc/polygon.hpp"
#include "reference2d.hpp"
#include "scale.hpp"
#include "shapes2d.hpp"

using namespace convexloc;

namespace {

// a method with a resolution (0 = the default)
struct Config {
  Method2D method;
  std::uint32_t resolution;
};

constexpr Config kConfigs[] = {
    {Method2D::Halfplane, 0}, {Method2D::Wedge, 0}, {Method2D::Slab, 0},  {Method2D::Uniform, 0},
    {Method2D::Uniform, 1},   {Method2D::Polar, 0}, {Method2D::Polar, 1},
};

// a few thousand queries: random, near the boundary, and the polar hard cases
std::vector<Vec2> tracePoints(const shapes::ShapeCase& shape, const ConvexPolygon& polygon) {
  Rng rng(0x7ace + shape.input.size());
  const PolarLocator polar(polygon);
  // without a centre, the fan's apex (vertex 0) stands in for it, as the query uses it
  const Vec2 centre = polar.centre().value_or(polygon.vertex(0));
  // the random ones scaled under the sanitizers (scale.hpp), the hard and edge points all kept
  std::vector<Vec2> pts =
      adversarial::randomPoints(polygon.bounds(), centre, testscale::scaled(2000, 200), rng);
  std::vector<Vec2> near = generatePoints(polygon, testscale::scaled(1000, 100), 3, true);
  pts.insert(pts.end(), near.begin(), near.end());
  std::vector<Vec2> hard = adversarial::polarPoints(polar, polygon);
  for (std::size_t i : adversarial::spread(hard.size(), 2000)) pts.push_back(hard[i]);
  std::vector<Vec2> edges = adversarial::boundaryPoints(polygon, shape.input, rng);
  for (std::size_t i : adversarial::spread(edges.size(), 2000)) pts.push_back(edges[i]);
  return pts;
}

// whether `edge` is among the edges cell `cell` lists
bool listed(const std::vector<Cell2D>& cells, std::int64_t cell, std::uint32_t edge) {
  if (cell < 0 || static_cast<std::size_t>(cell) >= cells.size()) return false;
  const std::vector<std::uint32_t>& e = cells[static_cast<std::size_t>(cell)].edges;
  return std::find(e.begin(), e.end(), edge) != e.end();
}

// the point lies outside the closed box
bool outside(const Box2& b, Vec2 p) {
  return p.x < b.lo.x || p.x > b.hi.x || p.y < b.lo.y || p.y > b.hi.y;
}

// the checks every method's trace must pass; returns false after the first failure
// (`want` is the reference's answer for p)
bool checkTrace(const std::string& where, const Locator2D& locator, const ConvexPolygon& polygon,
                const std::vector<Cell2D>& cells, Vec2 p, Location want) {
  std::span<const Vec2> v = polygon.vertices();
  const std::uint32_t n = static_cast<std::uint32_t>(v.size());
  const Trace2D t = locator.trace(p);
  const std::string at = where + " at " + adversarial::show(p);
  EXPECT_EQ(t.method, locator.method()) << at;
  EXPECT_EQ(t.result, locator.locate(p)) << at;
  EXPECT_EQ(t.result, want) << at;
  bool anyNegative = false, allPositive = true;
  for (const EdgeTest& e : t.edges) {
    if (e.edge >= n) {
      ADD_FAILURE() << at << ": edge " << e.edge << " of " << n;
      return false;
    }
    EXPECT_EQ(e.sign, ref::edgeSign(v, e.edge, p)) << at << ": edge " << e.edge;
    anyNegative |= e.sign < 0;
    allPositive &= e.sign > 0;
  }
  for (const RayTest& r : t.rays) {
    if (r.vertex >= n) {
      ADD_FAILURE() << at << ": ray vertex " << r.vertex << " of " << n;
      return false;
    }
    EXPECT_EQ(r.sign, ref::cross(t.apex, v[r.vertex], p)) << at << ": ray " << r.vertex;
  }
  // an inside answer rests on strictly positive edge tests
  if (t.result == Location::Inside && !t.atCentre && !t.byRadius) {
    EXPECT_FALSE(t.edges.empty()) << at;
    EXPECT_TRUE(allPositive) << at;
  }
  if (t.outsideBox) {
    EXPECT_TRUE(outside(polygon.bounds(), p)) << at;
    EXPECT_EQ(t.result, Location::Outside) << at;
    EXPECT_EQ(t.cell, -1) << at;
  }
  switch (locator.method()) {
    case Method2D::Halfplane: {
      // edges 0, 1, 2, ... in order, stopping at the first outer side
      for (std::size_t k = 0; k < t.edges.size(); ++k) EXPECT_EQ(t.edges[k].edge, k) << at;
      if (t.result == Location::Outside) {
        EXPECT_LT(t.edges.back().sign, 0) << at;
      } else {
        EXPECT_EQ(t.edges.size(), n) << at;
      }
      EXPECT_EQ(t.cell, -1) << at;
      break;
    }
    case Method2D::Wedge: {
      EXPECT_EQ(t.apex, v[0]) << at;
      EXPECT_FALSE(t.rays.empty()) << at;
      break;
    }
    case Method2D::Slab:
    case Method2D::Uniform: {
      if (t.outsideBox) break;
      EXPECT_GE(t.cell, 0) << at;
      if (t.cell < 0 || static_cast<std::size_t>(t.cell) >= cells.size()) {
        ADD_FAILURE() << at << ": cell " << t.cell << " of " << cells.size();
        return false;
      }
      const Cell2D& c = cells[static_cast<std::size_t>(t.cell)];
      if (const UniformLocator* u = locator.get<UniformLocator>()) {
        EXPECT_EQ(t.cell, u->slabOf(p.y)) << at;
        EXPECT_EQ(t.crowded, c.edges.size() > kCrowdedCell) << at;
      } else {
        EXPECT_LE(c.y0, p.y) << at;
        EXPECT_GE(c.y1, p.y) << at;
      }
      for (const EdgeTest& e : t.edges) EXPECT_TRUE(listed(cells, t.cell, e.edge)) << at;
      if (t.result == Location::Outside) {
        EXPECT_TRUE(anyNegative) << at;
      }
      break;
    }
    case Method2D::Polar: {
      const PolarLocator* polar = locator.get<PolarLocator>();
      if (cells.empty()) {  // no centre strictly inside: the fan from vertex 0
        EXPECT_EQ(t.apex, v[0]) << at;
        EXPECT_EQ(t.cell, -1) << at;
        break;
      }
      const std::int64_t c = polar->cellIndex(p);
      if (p == polar->centre()) {
        EXPECT_TRUE(t.atCentre) << at;
        EXPECT_EQ(t.result, Location::Inside) << at;
        EXPECT_EQ(c, -1) << at;
        break;
      }
      EXPECT_FALSE(t.atCentre) << at;
      EXPECT_EQ(t.cell, c) << at;
      if (c < 0) {  // offsets too large for the index arithmetic: the fan from vertex 0
        if (!t.rays.empty()) {
          EXPECT_EQ(t.apex, v[0]) << at;
        }
        break;
      }
      EXPECT_EQ(t.apex, polar->centre()) << at;
      EXPECT_LT(c, static_cast<std::int64_t>(polar->cellCount())) << at;
      EXPECT_EQ(t.octant, static_cast<int>(c / polar->slabsPerOctant())) << at;
      const Cell2D& cell = cells[static_cast<std::size_t>(c)];
      if (t.byRadius) {
        // decided by the cell's radii, before any edge test
        EXPECT_TRUE(t.edges.empty() && t.rays.empty()) << at;
        EXPECT_FALSE(t.crowded) << at;
        if (t.result == Location::Inside) {
          // nearer than where its ray leaves: inside, so on the inner side of every listed
          // edge (exact check)
          EXPECT_LT(t.distance, t.innerRadius) << at;
          for (std::uint32_t e : cell.edges) EXPECT_GT(ref::edgeSign(v, e, p), 0) << at << " edge " << e;
        } else {
          // farther than the part of every listed edge the cell sees; that part is never
          // farther than the edge's farthest endpoint (the answer itself is checked against
          // the reference above)
          EXPECT_EQ(t.result, Location::Outside) << at;
          EXPECT_GT(t.distance, t.outerRadius) << at;
          const Vec2 o = *polar->centre();  // a cell decided: there is a centre
          auto d2 = [&](Vec2 q) {
            const long double dx = static_cast<long double>(q.x) - o.x;
            const long double dy = static_cast<long double>(q.y) - o.y;
            return dx * dx + dy * dy;
          };
          long double farthest = 0;
          for (std::uint32_t e : cell.edges)
            for (std::uint32_t k : {e, e + 1 == n ? 0 : e + 1}) farthest = std::max(farthest, d2(v[k]));
          EXPECT_LE(static_cast<long double>(t.outerRadius) * t.outerRadius,
                    // floats are coarser than tiny doubles, and outer bounds never go below 2^-140
                    std::max(farthest, 0x1p-140L) * (1 + 1e-6L))
              << at;
        }
        break;
      }
      EXPECT_LE(t.innerRadius, t.distance * (1 + 1e-9)) << at;
      EXPECT_GE(t.outerRadius, t.distance * (1 - 1e-9)) << at;
      EXPECT_EQ(t.crowded, cell.edges.size() > kCrowdedCell) << at;
      for (const EdgeTest& e : t.edges) EXPECT_TRUE(listed(cells, c, e.edge)) << at;
      for (const RayTest& r : t.rays) EXPECT_TRUE(listed(cells, c, r.vertex)) << at;
      if (!t.crowded) {
        EXPECT_TRUE(t.rays.empty()) << at;
      }
      if (t.result == Location::Outside) {
        EXPECT_TRUE(anyNegative) << at;
      }
      break;
    }
  }
  return !testing::Test::HasFailure();
}

class TraceMatchesLocate : public testing::TestWithParam<std::size_t> {};

TEST_P(TraceMatchesLocate, EveryMethod) {
  const shapes::ShapeCase& shape = shapes::cases()[GetParam()];
  const ConvexPolygon polygon(shape.input);
  const std::vector<Vec2> points = tracePoints(shape, polygon);
  std::vector<Location> want(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    want[i] = ref::locate(polygon.vertices(), points[i]);
  for (Config config : kConfigs) {
    const Locator2D locator(polygon, config.method, config.resolution);
    const std::vector<Cell2D> cells = locator.cells();
    const std::string where = shape.name + " " + std::string(toString(config.method)) + "(" +
                              std::to_string(config.resolution) + ")";
    // halfplane traces are O(N) each: a sample on large polygons
    const std::size_t stride = config.method == Method2D::Halfplane && polygon.size() > 256 ? 8 : 1;
    for (std::size_t i = 0; i < points.size(); i += stride)
      if (!checkTrace(where, locator, polygon, cells, points[i], want[i])) return;
  }
}

INSTANTIATE_TEST_SUITE_P(Shapes, TraceMatchesLocate, testing::ValuesIn(shapes::caseIndices()),
                         shapes::CaseName());

// the trace of a few hand-checked points on the unit square
TEST(Trace, SquareByHand) {
  const ConvexPolygon square(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  const HalfplaneLocator half(square);
  Trace2D t = half.trace({2, 0.5});
  EXPECT_EQ(t.result, Location::Outside);
  ASSERT_EQ(t.edges.size(), 2u);
  EXPECT_EQ(t.edges[1].edge, 1u);
  EXPECT_EQ(t.edges[1].sign, -1);
  t = half.trace({0.5, 0});
  EXPECT_EQ(t.result, Location::Boundary);
  EXPECT_EQ(t.edges[0].sign, 0);

  const PolarLocator polar(square);
  EXPECT_EQ(polar.centre(), (Vec2{0.5, 0.5}));
  t = polar.trace(*polar.centre());
  EXPECT_TRUE(t.atCentre);
  EXPECT_EQ(t.result, Location::Inside);
  t = polar.trace({0.9, 0.6});  // octant 0, inside
  EXPECT_EQ(t.octant, 0);
  EXPECT_EQ(t.result, Location::Inside);
  t = polar.trace({0.1, 0.9});  // direction (-0.4, 0.4): the border of octants 2 and 3
  EXPECT_TRUE(t.octant == 2 || t.octant == 3) << t.octant;

  const SlabLocator slab(square);
  t = slab.trace({0.5, 5});
  EXPECT_TRUE(t.outsideBox);
  EXPECT_EQ(t.cell, -1);
  t = slab.trace({0.5, 1});  // on the top line
  EXPECT_EQ(t.result, Location::Boundary);
  EXPECT_EQ(t.cell, 0);

  const WedgeLocator wedge(square);
  t = wedge.trace({0.75, 0.25});
  EXPECT_EQ(t.apex, (Vec2{0, 0}));
  EXPECT_EQ(t.result, Location::Inside);
  EXPECT_EQ(t.cell, 1);
}

}  // namespace

// A point whose squared distance from the centre, as polar computes it, equals its cell's
// outer bound exactly is not beyond that bound: the radii must leave it to the edge tests (a
// '>=' in their comparison would call it inside). Found by stepping a coordinate ulp by ulp
// across the bound's circle; checked one point per call and in a batch (the AVX2 stage where
// the CPU has it) against the exact reference.
TEST(Trace, PolarExactlyOnTheOuterBoundGoesToTheEdgeTests) {
  for (auto [kind, n] : {std::pair{PolygonKind::Regular, std::size_t{8}},
                         std::pair{PolygonKind::Regular, std::size_t{1024}},
                         std::pair{PolygonKind::Random, std::size_t{200}},
                         std::pair{PolygonKind::Ellipse, std::size_t{64}}}) {
    SCOPED_TRACE(std::string(toString(kind)) + " " + std::to_string(n));
    const ConvexPolygon polygon(generatePolygon(kind, n, 3));
    const PolarLocator polar(polygon);
    const Vec2 c = polar.trace(polygon.vertices()[0]).apex;  // the centre
    Rng rng(5);
    std::vector<Vec2> found;
    for (int trial = 0; trial < 20000 && found.size() < 64; ++trial) {
      const Vec2 u{rng.uniform(-1, 1), rng.uniform(-1, 1)};
      const double len = std::sqrt(u.x * u.x + u.y * u.y);
      if (!(len > 0.1)) continue;
      const Trace2D seed = polar.trace({c.x + u.x, c.y + u.y});
      if (seed.cell < 0 || !(seed.outerRadius > 0)) continue;
      // the stored bound (a float): the trace shows its square root
      const float out2 = static_cast<float>(seed.outerRadius * seed.outerRadius);
      ASSERT_EQ(std::sqrt(static_cast<double>(out2)), seed.outerRadius);
      const double k = seed.outerRadius / len;
      Vec2 q{c.x + u.x * k, c.y + u.y * k};
      const double outward = u.x > 0 ? HUGE_VAL : -HUGE_VAL;
      for (int step = 0; step < 64; ++step) {
        const double dx = q.x - c.x, dy = q.y - c.y;
        const double d2 = dx * dx + dy * dy;  // as polar computes it
        if (d2 == static_cast<double>(out2)) {
          const Trace2D t = polar.trace(q);
          if (t.cell == seed.cell) {
            EXPECT_FALSE(t.byRadius);
            EXPECT_EQ(t.result, ref::locate(polygon.vertices(), q));
            EXPECT_EQ(polar.locate(q), t.result);
            found.push_back(q);
          }
          break;
        }
        q.x = std::nextafter(q.x, d2 < static_cast<double>(out2) ? outward : -outward);
      }
    }
    EXPECT_GE(found.size(), 16u);
    std::vector<Vec2> batch;
    for (Vec2 q : found) {
      batch.push_back(c);
      batch.push_back(q);
      batch.push_back({c.x + 100, c.y});
    }
    std::vector<Location> out(batch.size());
    polar.locate(batch, out);
    for (std::size_t i = 1; i < batch.size(); i += 3)
      EXPECT_EQ(out[i], ref::locate(polygon.vertices(), batch[i]));
  }
}
