// The trace's step records: the slab method's binary search probe by probe, the uniform
// method's eq. (4) numbers, the polar index's octant, ratio and slab, the cube map's
// direction and cells per side; and the paper-faithful trace (TraceOptions::radii false),
// whose cell's edges (faces) decide and whose answer is locate(p)'s on random and
// adversarial points: vertices, points on edges and faces, the centre.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "adversarial2d.hpp"
#include "adversarial3d.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/locate2d.hpp"
#include "convexloc/locate3d.hpp"
#include "convexloc/polygon.hpp"
#include "convexloc/polyhedron.hpp"
#include "shapes2d.hpp"

using namespace convexloc;

namespace {

// the regular octagon of circumradius 1, vertex 0 on +x, mirror-symmetric in doubles
ConvexPolygon octagon() {
  const double r = std::sqrt(0.5);
  const std::vector<Vec2> v = {{1, 0},  {r, r},   {0, 1},  {-r, r},
                               {-1, 0}, {-r, -r}, {0, -1}, {r, -r}};
  return ConvexPolygon(v);
}

// random points over the box, near the boundary, the polar hard cases, on the edges, the
// vertices and the centre
std::vector<Vec2> hardPoints2D(const ConvexPolygon& polygon, std::uint64_t seed) {
  Rng rng(seed);
  const PolarLocator polar(polygon);
  const Vec2 centre = polar.centre().value_or(polygon.vertex(0));
  std::vector<Vec2> pts = adversarial::randomPoints(polygon.bounds(), centre, 1500, rng);
  std::vector<Vec2> near = generatePoints(polygon, 800, seed, true);
  pts.insert(pts.end(), near.begin(), near.end());
  std::vector<Vec2> hard = adversarial::polarPoints(polar, polygon);
  for (std::size_t i : adversarial::spread(hard.size(), 1500)) pts.push_back(hard[i]);
  const std::vector<Vec2> ring(polygon.vertices().begin(), polygon.vertices().end());
  std::vector<Vec2> onEdges = adversarial::boundaryPoints(polygon, ring, rng);
  for (std::size_t i : adversarial::spread(onEdges.size(), 1500)) pts.push_back(onEdges[i]);
  for (Vec2 v : polygon.vertices()) pts.push_back(v);
  pts.push_back(centre);
  return pts;
}

TEST(TraceSteps, SlabProbesAreTheBinarySearch) {
  const ConvexPolygon poly = octagon();
  const SlabLocator slab(poly);
  const std::vector<Cell2D> cells = slab.cells();
  std::vector<double> ys;
  for (Vec2 v : poly.vertices()) ys.push_back(v.y);
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  ASSERT_EQ(ys.size(), 5u);  // the octagon's distinct y: -1, -r, 0, r, 1
  for (Vec2 p : hardPoints2D(poly, 5)) {
    const Trace2D t = slab.trace(p);
    if (t.outsideBox) {
      EXPECT_TRUE(t.probes.empty());
      continue;
    }
    // each probe halves the range [first, first + count) as std::upper_bound does
    std::size_t first = 0, count = ys.size();
    for (const SlabProbe& pr : t.probes) {
      ASSERT_GT(count, 0u);
      const std::size_t mid = first + count / 2;
      EXPECT_EQ(pr.rank, mid);
      EXPECT_EQ(pr.y, ys[mid]);
      EXPECT_EQ(pr.above, p.y >= ys[mid]);
      first = pr.above ? mid + 1 : first;
      count = pr.above ? count - count / 2 - 1 : count / 2;
    }
    EXPECT_EQ(count, 0u);
    const std::size_t s = std::min(first == 0 ? 0 : first - 1, cells.size() - 1);
    EXPECT_EQ(t.cell, static_cast<std::int64_t>(s));
  }
  // the centre row: probes 0 (rank 2, above), then r (rank 4 is 1: below), rank 3 (r: below)
  const Trace2D mid = slab.trace({0.1, 0.0});
  ASSERT_EQ(mid.probes.size(), 3u);
  EXPECT_EQ(mid.probes[0].rank, 2u);
  EXPECT_TRUE(mid.probes[0].above);
  EXPECT_EQ(mid.probes[1].rank, 4u);
  EXPECT_FALSE(mid.probes[1].above);
  EXPECT_EQ(mid.probes[2].rank, 3u);
  EXPECT_FALSE(mid.probes[2].above);
  EXPECT_EQ(mid.cell, 2);
}

TEST(TraceSteps, UniformIndexIsEquationFour) {
  const ConvexPolygon poly = octagon();
  for (std::uint32_t slabs : {1u, 4u, 7u, 64u}) {
    const UniformLocator uniform(poly, slabs);
    for (Vec2 p : hardPoints2D(poly, 6)) {
      const Trace2D t = uniform.trace(p);
      if (t.outsideBox) {
        EXPECT_EQ(t.uniform.slabs, 0u);
        continue;
      }
      EXPECT_EQ(t.uniform.slabs, uniform.slabCount());
      EXPECT_EQ(t.uniform.yMin, poly.bounds().lo.y);
      EXPECT_NEAR(t.uniform.height * slabs, 2.0, 1e-12);
      const double floored = std::floor(t.uniform.value);
      const double last = static_cast<double>(t.uniform.slabs - 1);
      EXPECT_EQ(static_cast<double>(t.cell), std::min(floored, last)) << p.x << ' ' << p.y;
      EXPECT_NEAR(t.uniform.value, (p.y - t.uniform.yMin) / t.uniform.height, 1e-9);
    }
  }
  // y = 0.3 over 4 slabs of height 0.5 from -1: (0.3 + 1) / 0.5 = 2.6, slab 2
  const Trace2D t = UniformLocator(poly, 4).trace({0.0, 0.3});
  EXPECT_NEAR(t.uniform.value, 2.6, 1e-12);
  EXPECT_EQ(t.cell, 2);
}

TEST(TraceSteps, PolarIndexNumbersNameTheCell) {
  const ConvexPolygon poly = octagon();
  const PolarLocator polar(poly, 4);
  ASSERT_TRUE(polar.centre().has_value());
  for (Vec2 p : hardPoints2D(poly, 7)) {
    const Trace2D t = polar.trace(p);
    if (t.cell < 0) {
      EXPECT_EQ(t.polar.slabs, 0u);
      continue;
    }
    EXPECT_EQ(t.polar.slabs, 4u);
    EXPECT_LT(t.polar.slab, 4u);
    EXPECT_GE(t.polar.ratio, 0.0);
    EXPECT_LE(t.polar.ratio, 1.0);
    EXPECT_EQ(t.polar.base + t.polar.step * t.polar.slab, t.cell);
    EXPECT_EQ(t.polar.slab, std::min(static_cast<std::uint32_t>(t.polar.ratio * 4), 3u));
    EXPECT_EQ(t.polar.steep, std::fabs(t.polar.direction.y) > std::fabs(t.polar.direction.x));
  }
  // direction (1, 0.43) from the centre: octant 0, ratio 0.43, slab floor(1.72) = 1
  const Vec2 c = *polar.centre();
  const Trace2D t = polar.trace({c.x + 0.5, c.y + 0.215});
  EXPECT_EQ(t.octant, 0);
  EXPECT_NEAR(t.polar.ratio, 0.43, 1e-12);
  EXPECT_EQ(t.polar.slab, 1u);
  EXPECT_FALSE(t.polar.steep);
  EXPECT_EQ(t.cell, 1);
}

// the paper's polar query: no radius decides, the cell's edges (or the fan) do, and the
// answer is locate(p)'s
void checkPaperPolar(const ConvexPolygon& poly, std::uint32_t q, std::uint64_t seed,
                     const std::string& name) {
  const Locator2D loc(poly, Method2D::Polar, q);
  std::size_t wrong = 0, byEdge = 0;
  for (Vec2 p : hardPoints2D(poly, seed)) {
    const Trace2D t = loc.trace(p, TraceOptions{.radii = false});
    EXPECT_FALSE(t.radiusFilter);
    EXPECT_FALSE(t.byRadius);
    EXPECT_EQ(t.outerRadius, 0.0);
    if (t.result != loc.locate(p) && ++wrong <= 5)
      ADD_FAILURE() << name << " at " << adversarial::show(p) << ": paper trace "
                    << toString(t.result) << ", locate " << toString(loc.locate(p));
    // a cell's edge decides; without a cell the fan's rays may decide alone
    if (!t.atCentre) {
      EXPECT_FALSE(t.edges.empty() && (t.cell >= 0 || t.rays.empty()))
          << name << " at " << adversarial::show(p);
    }
    byEdge += t.cell >= 0 && !t.edges.empty();
    // the default trace still lets the radii decide
    EXPECT_TRUE(loc.trace(p).radiusFilter);
  }
  EXPECT_EQ(wrong, 0u) << name;
  if (!loc.cells().empty()) {  // with a centre, the cells' edges decide
    EXPECT_GT(byEdge, 0u) << name;
  }
}

TEST(TraceSteps, PaperPolarTraceTestsAnEdgeAndAgreesWithLocate) {
  checkPaperPolar(octagon(), 0, 8, "octagon");
  checkPaperPolar(octagon(), 1, 9, "octagon q=1");
  const std::vector<shapes::ShapeCase>& all = shapes::cases();
  for (std::size_t i : adversarial::spread(all.size(), 12))
    checkPaperPolar(ConvexPolygon(all[i].input), 0, 10 + i, all[i].name);
}

TEST(TraceSteps, OptionsAreIgnoredWithoutARadiusFilter) {
  const ConvexPolygon poly = octagon();
  for (Method2D m : {Method2D::Halfplane, Method2D::Wedge, Method2D::Slab, Method2D::Uniform}) {
    const Locator2D loc(poly, m);
    const Trace2D a = loc.trace({0.2, 0.1}), b = loc.trace({0.2, 0.1}, {.radii = false});
    EXPECT_EQ(a.result, b.result);
    EXPECT_EQ(a.edges.size(), b.edges.size());
  }
}

// points of a polyhedron: random, near and on the surface, the vertices, the centre
std::vector<Vec3> hardPoints3D(const ConvexPolyhedron& p, const CubemapLocator& cubemap,
                               std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Vec3> pts = generatePoints3D(p, 1500, seed, false);
  const std::vector<Vec3> near = generatePoints3D(p, 800, seed + 1, true);
  pts.insert(pts.end(), near.begin(), near.end());
  const std::vector<Vec3> surface = adversarial3d::surfacePoints(p, 600, rng);
  pts.insert(pts.end(), surface.begin(), surface.end());
  const std::vector<Vec3> aimed = adversarial3d::cubemapPoints(p, cubemap, rng);
  for (std::size_t i : adversarial::spread(aimed.size(), 1500)) pts.push_back(aimed[i]);
  for (Vec3 v : p.vertices()) pts.push_back(v);
  if (cubemap.centre()) pts.push_back(*cubemap.centre());
  return pts;
}

TEST(TraceSteps, PaperCubemapTraceTestsFacesAndAgreesWithLocate) {
  const PolyhedronKind kinds[] = {PolyhedronKind::Cube, PolyhedronKind::Octahedron,
                                  PolyhedronKind::Geodesic, PolyhedronKind::SphereHull,
                                  PolyhedronKind::ThinSlab};
  for (PolyhedronKind kind : kinds) {
    const ConvexPolyhedron poly(
        generatePolyhedron(kind, kind == PolyhedronKind::Cube ? 12 : 320, 3));
    for (std::uint32_t g : {0u, 1u, 6u}) {
      const Locator3D loc(poly, Method3D::Cubemap, g);
      const CubemapLocator& cm = *loc.get<CubemapLocator>();
      std::size_t wrong = 0;
      for (Vec3 p : hardPoints3D(poly, cm, 40 + g)) {
        const Trace3D t = loc.trace(p, {.radii = false});
        EXPECT_FALSE(t.radiusFilter);
        EXPECT_FALSE(t.byRadius);
        if (t.result != loc.locate(p) && ++wrong <= 5)
          ADD_FAILURE() << toString(kind) << " G=" << g << ": paper trace " << toString(t.result)
                        << ", locate " << toString(loc.locate(p));
        if (!t.atCentre && !t.nonFinite) {
          EXPECT_FALSE(t.faces.empty() && t.steps.empty());
        }
        if (t.cubeFace >= 0) {
          // the recorded direction and cells per side give the cell's column and row
          const Vec3 c = *cm.centre();
          EXPECT_EQ(t.direction.x, p.x - c.x);
          EXPECT_EQ(t.cellsPerSide, cm.resolution() << t.level);
          const double n = t.cellsPerSide;
          EXPECT_LE(std::fabs((t.s + 1) / 2 * n - (t.cellI + 0.5)), 0.5 + 1e-6);
          EXPECT_LE(std::fabs((t.t + 1) / 2 * n - (t.cellJ + 0.5)), 0.5 + 1e-6);
        }
      }
      EXPECT_EQ(wrong, 0u) << toString(kind) << " G=" << g;
    }
  }
}

TEST(TraceSteps, CubeTraceNamesFaceAndCell) {
  const ConvexPolyhedron cube(generatePolyhedron(PolyhedronKind::Cube, 12, 1));
  const CubemapLocator cm(cube, 4);
  ASSERT_TRUE(cm.centre().has_value());
  const Vec3 c = *cm.centre();
  // direction (0.5, 0.1, -0.2): cube face +x, s = 0.2, t = -0.4 on a 4 x 4 grid: cell (2, 1)
  const Trace3D t = cm.trace({c.x + 0.5, c.y + 0.1, c.z - 0.2});
  EXPECT_EQ(t.cubeFace, 0);
  EXPECT_EQ(t.cellsPerSide, 4u << t.level);
  EXPECT_NEAR(t.s, 0.2, 1e-12);
  EXPECT_NEAR(t.t, -0.4, 1e-12);
  if (t.level == 0) {
    EXPECT_EQ(t.cellI, 2u);
    EXPECT_EQ(t.cellJ, 1u);
  }
}

}  // namespace
