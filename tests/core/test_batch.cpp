// locateParallel: the same answers as one point at a time, for any thread count and any
// batch size (small batches, sizes that are not multiples of the 64-point runs).
#include <gtest/gtest.h>

#include <vector>

#include "convexloc/batch.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/locate2d.hpp"
#include "convexloc/locate3d.hpp"

using namespace convexloc;

namespace {

template <class Locator, class Point>
void expectSameAsOneByOne(const Locator& loc, const std::vector<Point>& pts) {
  std::vector<Location> want(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) want[i] = loc.locate(pts[i]);
  for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{63}, std::size_t{1000},
                        kMinPointsPerThread * 2 + 1, pts.size()}) {
    for (unsigned threads : {0u, 1u, 2u, 3u, 7u}) {
      SCOPED_TRACE("n " + std::to_string(n) + ", threads " + std::to_string(threads));
      std::vector<Location> got(n, static_cast<Location>(0xff));
      locateParallel(loc, std::span<const Point>(pts.data(), n), std::span<Location>(got), threads);
      for (std::size_t i = 0; i < n; ++i) ASSERT_EQ(got[i], want[i]) << "point " << i;
    }
  }
}

}  // namespace

TEST(Batch, ThreadCountFollowsTheBatchSize) {
  EXPECT_EQ(batchThreads(10, 8), 1u);
  EXPECT_EQ(batchThreads(kMinPointsPerThread * 3, 8), 3u);
  EXPECT_EQ(batchThreads(kMinPointsPerThread * 100, 2), 2u);
  EXPECT_GE(batchThreads(kMinPointsPerThread * 100, 0), 1u);
}

TEST(Batch, Polygon2DMatchesOneByOne) {
  const ConvexPolygon p(generatePolygon(PolygonKind::Regular, 4096, 1));
  const std::vector<Vec2> pts = generatePoints(p, 3 * kMinPointsPerThread + 77, 5, true);
  for (Method2D m : {Method2D::Polar, Method2D::Uniform, Method2D::Wedge}) {
    SCOPED_TRACE(std::string(toString(m)));
    expectSameAsOneByOne(Locator2D(p, m), pts);
  }
}

TEST(Batch, Polyhedron3DMatchesOneByOne) {
  const ConvexPolyhedron p(generatePolyhedron(PolyhedronKind::Geodesic, 5000, 1));
  const std::vector<Vec3> pts = generatePoints3D(p, 3 * kMinPointsPerThread + 77, 5, true);
  expectSameAsOneByOne(CubemapLocator(p), pts);
  expectSameAsOneByOne(Locator3D(p, Method3D::Cubemap), pts);
}
