// The cube map's slabs (core/src/cubemap/slabs.cpp): after a leaf's radii, n . (p - c)
// against two bounds decides the points over flat parts of the surface. Checked against the
// independent exact reference on the CAD family (cylinders turned, moved to 10^6, rounded to
// float32, read as hulls; squat, tall and coarse), a cube, and a box far from the origin: random
// points, near-boundary ones, the surface's vertices, edge and face points and their ulp
// neighbours, cell borders, the centre, and points a hair either side of the surface along
// rays through every vertex, where slabs decide the most; the single-point query, the batch
// and the trace agree, and no slab decides a point on the boundary. Tables without slabs
// load and answer the same; tables with a wrong number of slab values are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "../bench/cad_family.hpp"
#include "adversarial3d.hpp"
#include "convexloc/error.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/locate3d.hpp"
#include "reference3d.hpp"
#include "scale.hpp"
#include "shapes3d.hpp"

using namespace convexloc;
using testscale::scaled;

namespace {

struct Shape {
  std::string name;
  std::function<ConvexPolyhedron()> make;
};

// c + s (v - c) for every `step`-th vertex v and s a hair (2^-k, k = 12 .. 52) either side of 1
void aroundVertexRays(std::vector<Vec3>& out, const ConvexPolyhedron& p, Vec3 c) {
  const auto v = p.vertices();
  const std::size_t step = std::max<std::size_t>(1, v.size() / scaled(300, 30));
  for (std::size_t i = 0; i < v.size(); i += step)
    for (int k = 12; k <= 52; k += 8)
      for (double s : {1 - std::ldexp(1.0, -k), 1 + std::ldexp(1.0, -k)})
        out.push_back(
            {c.x + s * (v[i].x - c.x), c.y + s * (v[i].y - c.y), c.z + s * (v[i].z - c.z)});
}

// random, near-boundary and hard points of p
std::vector<Vec3> probePoints(const ConvexPolyhedron& p, const CubemapLocator& cm) {
  Rng rng(7);
  std::vector<Vec3> pts = generatePoints3D(p, scaled(2500, 250), 21, false);
  const auto near = generatePoints3D(p, scaled(1000, 100), 22, true);
  pts.insert(pts.end(), near.begin(), near.end());
  const auto surface = adversarial3d::surfacePoints(p, scaled(300, 60), rng);
  pts.insert(pts.end(), surface.begin(), surface.end());
  const auto cells = adversarial3d::cubemapPoints(p, cm, rng);
  pts.insert(pts.end(), cells.begin(), cells.end());
  aroundVertexRays(pts, p, *cm.centre());
  return pts;
}

class CubemapSlabs : public ::testing::TestWithParam<Shape> {};

TEST_P(CubemapSlabs, DecideExactlyAndNeverOnTheBoundary) {
  const ConvexPolyhedron p = GetParam().make();
  const CubemapLocator cm(p);
  ASSERT_TRUE(cm.centre());
  const std::vector<Vec3> pts = probePoints(p, cm);
  const reftest::Reference ref(p);
  std::vector<Location> batch(pts.size());
  cm.locate(pts, batch);
  std::size_t bySlab = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Location want = ref.locate(pts[i]);
    const Trace3D t = cm.trace(pts[i]);
    bySlab += t.bySlab;
    if (cm.locate(pts[i]) != want || batch[i] != want || t.result != want ||
        (t.bySlab && want == Location::Boundary)) {
      ADD_FAILURE() << "wrong at " << pts[i].x << ' ' << pts[i].y << ' ' << pts[i].z
                    << (t.bySlab ? " (slab)" : "");
      return;
    }
  }
  EXPECT_GT(bySlab, 0u) << "no slab decided";
  EXPECT_LE(cm.stats().bytes, 128 * p.faceCount() + 65536);
}

INSTANTIATE_TEST_SUITE_P(
    Shapes, CubemapSlabs,
    ::testing::Values(Shape{"cad64_squat",
                            [] {
                              return cadfamily::polyhedron({64, 0.1, false});
                            }},
                      Shape{"cad64_tall_moved",
                            [] {
                              return cadfamily::polyhedron({64, 10, true});
                            }},
                      Shape{"cad512_moved",
                            [] {
                              return cadfamily::polyhedron({512, 1, true});
                            }},
                      Shape{"cad1024_tall",
                            [] {
                              return cadfamily::polyhedron({1024, 4, false});
                            }},
                      Shape{"cube", [] { return ConvexPolyhedron(shapes3d::cube()); }},
                      Shape{"far_box",
                            [] {
                              MeshData m = shapes3d::cube();
                              for (Vec3& v : m.vertices)
                                v = {v.x * 3e-3 + 1e12, v.y * 7e-3 - 4e11, v.z + 2e12};
                              return ConvexPolyhedron(m);
                            }}),
    [](const ::testing::TestParamInfo<Shape>& param) { return param.param.name; });

// a locator loaded from tables without slabs (older tables) answers the same, none by slab
// slab values that are not 5 per node are refused
TEST(CubemapSlabs, TablesWithoutSlabsLoadAndWrongOnesAreRefused) {
  const ConvexPolyhedron p = cadfamily::polyhedron({256, 4, true});
  const CubemapLocator built(p);
  CubemapTables t = built.tables();
  ASSERT_FALSE(t.slabs.empty());
  CubemapTables bare = t;
  bare.slabs.clear();
  const CubemapLocator loaded(p, bare);
  const reftest::Reference ref(p);
  std::size_t bySlab = 0;
  for (const Vec3& q : generatePoints3D(p, scaled(3000, 300), 5, false)) {
    const Trace3D tr = loaded.trace(q);
    EXPECT_FALSE(tr.bySlab);
    EXPECT_EQ(tr.result, ref.locate(q));
    EXPECT_EQ(loaded.locate(q), built.locate(q));
    bySlab += built.trace(q).bySlab;
  }
  EXPECT_GT(bySlab, 0u);
  t.slabs.pop_back();
  EXPECT_THROW(CubemapLocator(p, t), ParseError);
  t = built.tables();
  t.slabs[3] = std::nanf("");
  EXPECT_THROW(CubemapLocator(p, t), ParseError);
}

}  // namespace
