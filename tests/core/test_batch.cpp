// locateParallel: the same answers as one point at a time, for any thread count and any
// batch size (small batches, sizes that are not multiples of the 64-point runs).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <initializer_list>
#include <limits>
#include <string>
#include <type_traits>
#include <vector>

#include "adversarial2d.hpp"
#include "adversarial3d.hpp"
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

// Appends points no cell takes (infinite, NaN, far beyond the double range of directions),
// then checks that the batch gives the one-point answers with the AVX2 code (where the CPU
// has it) and with the scalar code.
template <class Locator, class Point>
void expectVectorAndScalarAgree(const Locator& loc, std::vector<Point> pts,
                                std::initializer_list<Point> extreme) {
  pts.insert(pts.end(), extreme);
  std::vector<Location> want(pts.size()), vec(pts.size()), scalar(pts.size());
  for (std::size_t i = 0; i < pts.size(); ++i) want[i] = loc.locate(pts[i]);
  setVectorBatches(true);
  loc.locate(std::span<const Point>(pts), std::span<Location>(vec));
  setVectorBatches(false);
  loc.locate(std::span<const Point>(pts), std::span<Location>(scalar));
  setVectorBatches(true);
  for (std::size_t i = 0; i < pts.size(); ++i) {
    std::string at = "point " + std::to_string(i);
    if constexpr (std::is_same_v<Point, Vec2>) at += ": " + adversarial::show(pts[i]);
    ASSERT_EQ(vec[i], want[i]) << at;
    ASSERT_EQ(scalar[i], want[i]) << at;
  }
}

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kBig = std::numeric_limits<double>::max();

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

TEST(Batch, CubemapVectorAndScalarCodeAgree) {
  // the AVX2 aim (where the CPU has it) and the scalar one give the same answers, on random
  // points, hard ones (cell borders, cube edges, the centre and its ulp neighbours) and
  // points no cell takes (infinite, NaN, far beyond the double range of the directions)
  for (auto [kind, n] : {std::pair{PolyhedronKind::Geodesic, std::size_t{20000}},
                         std::pair{PolyhedronKind::Cube, std::size_t{12}},
                         std::pair{PolyhedronKind::TinyFaces, std::size_t{3000}},
                         std::pair{PolyhedronKind::ThinSlab, std::size_t{400}}}) {
    SCOPED_TRACE(std::string(toString(kind)));
    const ConvexPolyhedron p(generatePolyhedron(kind, n, 7));
    const CubemapLocator cm(p);
    Rng rng(3);
    std::vector<Vec3> pts = generatePoints3D(p, 50000, 9, true);
    auto hard = adversarial3d::cubemapPoints(p, cm, rng);
    pts.insert(pts.end(), hard.begin(), hard.end());
    expectVectorAndScalarAgree(cm, std::move(pts),
                               {Vec3{kInf, 0, 0}, Vec3{0, std::nan(""), 0}, Vec3{kBig, -kBig, kBig},
                                Vec3{-kBig, 0, 0}, Vec3{0, 0, -kInf}});
  }
  std::printf("[ info     ] AVX2 batch code %s on this CPU\n",
              vectorBatches() ? "used" : "not available");
}

TEST(Batch, PolarVectorAndScalarCodeAgree) {
  // as above for the polar cell index: random points, the locator's hard points (its centre,
  // axes, diagonals and cell borders with their ulp neighbours), tiny and huge offsets
  for (auto [kind, n] : {std::pair{PolygonKind::Regular, std::size_t{4096}},
                         std::pair{PolygonKind::Regular, std::size_t{8}},
                         std::pair{PolygonKind::Random, std::size_t{300}},
                         std::pair{PolygonKind::TinyEdges, std::size_t{500}},
                         std::pair{PolygonKind::Sliver, std::size_t{100}}}) {
    SCOPED_TRACE(std::string(toString(kind)) + " " + std::to_string(n));
    const ConvexPolygon polygon(generatePolygon(kind, n, 5));
    const PolarLocator polar(polygon);
    std::vector<Vec2> pts = generatePoints(polygon, 50000, 4, true);
    auto hard = adversarial::polarPoints(polar, polygon);
    pts.insert(pts.end(), hard.begin(), hard.end());
    expectVectorAndScalarAgree(
        polar, std::move(pts),
        {Vec2{kInf, 0}, Vec2{0, std::nan("")}, Vec2{kBig, -kBig}, Vec2{-kBig, 0},
         polar.centre().value_or(polygon.vertex(0))});  // vertex 0: the fan's apex
  }
}
