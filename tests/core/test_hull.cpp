// Exact 3D hulls (ConvexPolyhedron::hullOf) and the 2D ConvexPolygon::hullOf, checked in
// exact arithmetic: every corner an input point, every input point inside or on every
// triangle's plane (core's orient3d, and GMP rationals that share no code with it), the
// facet planes equal to those of a brute-force rational hull on small clouds, and every
// locator built on the hull classifying every input point as Inside or Boundary.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/intersect3d.hpp"
#include "convexloc/locate3d.hpp"
#include "convexloc/polygon.hpp"
#include "convexloc/polyhedron.hpp"
#include "convexloc/predicates.hpp"
#include "reference3d.hpp"

using namespace convexloc;
using ::testing::HasSubstr;

namespace {

// n points on the unit sphere (axes scaled by `scale`), moved by `offset` along every axis
std::vector<Vec3> sphereCloud(std::size_t n, double offset, Vec3 scale, std::uint64_t seed) {
  Rng rng(seed);
  std::vector<Vec3> out(n);
  for (Vec3& p : out) {
    const double z = rng.uniform(-1, 1), a = rng.uniform(0, 2 * std::numbers::pi);
    const double r = std::sqrt(1 - z * z);
    p = {offset + scale.x * r * std::cos(a), offset + scale.y * r * std::sin(a),
         offset + scale.z * z};
  }
  return out;
}

// n points of a standard Gaussian in every coordinate, moved by `offset` (Box-Muller)
std::vector<Vec3> gaussianCloud(std::size_t n, double offset, std::uint64_t seed) {
  Rng rng(seed);
  auto normal = [&] {
    const double u = 1 - rng.uniform(), v = rng.uniform();
    return std::sqrt(-2 * std::log(u)) * std::cos(2 * std::numbers::pi * v);
  };
  std::vector<Vec3> out(n);
  for (Vec3& p : out) p = {offset + normal(), offset + normal(), offset + normal()};
  return out;
}

// How many input points lie strictly outside some triangle's plane of h, decided by core's
// orient3d (and, with `rational`, also by GMP rationals); and every corner must be the input
// point sourceVertex() names.
std::size_t outsideCount(std::span<const Vec3> points, const ConvexPolyhedron& h, bool rational) {
  const auto v = h.vertices();
  const auto source = h.sourceVertex();
  for (std::size_t i = 0; i < v.size(); ++i) {
    EXPECT_LT(source[i], points.size());
    if (source[i] < points.size()) {
      EXPECT_EQ(v[i], points[source[i]]) << "corner " << i;
    }
  }
  std::vector<char> out(points.size(), 0);
  for (const auto& t : h.triangles()) {
    const Vec3 a = v[t[0]], b = v[t[1]], c = v[t[2]];
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (orient3d(a, b, c, points[i]) < 0) out[i] = 1;
      if (rational && reftest::rationalOrient(a, b, c, points[i]) < 0) out[i] = 1;
    }
  }
  return static_cast<std::size_t>(std::count(out.begin(), out.end(), 1));
}

// the most point-plane pairs a test checks one by one (beyond, the exact walk and cube-map
// locators answer for every point instead, each in O(1) to O(sqrt F) plane tests)
constexpr std::size_t kPairsChecked = std::size_t{1} << 25;

// how many input points the methods classify Outside of h (the methods together; the
// half-space method, every plane for every point, only up to kPairsChecked pairs)
std::size_t locatorsOutside(std::span<const Vec3> points, const ConvexPolyhedron& h) {
  std::size_t outside = 0;
  std::vector<Location> where(points.size());
  for (Method3D m : kAllMethods3D) {
    if (m == Method3D::Halfspace && points.size() * h.faceCount() > kPairsChecked) continue;
    Locator3D locator(h, m);
    locator.locate(points, where);
    outside += static_cast<std::size_t>(std::count(where.begin(), where.end(), Location::Outside));
  }
  return outside;
}

// The hull, checked exactly against its cloud: no point outside any triangle's plane (every
// pair up to kPairsChecked, with rationals too when `rational`), none outside for the
// locators.
ConvexPolyhedron checkedHull(std::span<const Vec3> points, bool rational) {
  ConvexPolyhedron h = ConvexPolyhedron::hullOf(points);
  if (points.size() * h.faceCount() <= kPairsChecked) {
    EXPECT_EQ(outsideCount(points, h, rational), 0u);
  }
  EXPECT_EQ(locatorsOutside(points, h), 0u);
  return h;
}

// the corners' coordinates, sorted
std::vector<Vec3> cornerSet(const ConvexPolyhedron& h) {
  std::vector<Vec3> out(h.vertices().begin(), h.vertices().end());
  std::sort(out.begin(), out.end(), [](Vec3 a, Vec3 b) {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
  });
  return out;
}

}  // namespace

// === Clouds far from the origin, nearly flat, Gaussian

TEST(ExactHull3D, SphereCloudsFarFromTheOrigin) {
  for (double offset : {1e12, 1e13, 1e14, 1e15})
    for (std::size_t n : {std::size_t{200}, std::size_t{20000}}) {
      SCOPED_TRACE(std::to_string(n) + " points at " + std::to_string(offset));
      const std::vector<Vec3> cloud = sphereCloud(n, offset, {1, 1, 1}, 11);
      checkedHull(cloud, n <= 200);
    }
}

TEST(ExactHull3D, TheIssuesCloudKeepsEveryPointOnItsHull) {
  // 200 points of a unit sphere moved by 1e12: Qhull kept 99 and left 101 outside; the
  // points are distinct and in convex position, so every one is a corner
  const std::vector<Vec3> cloud = sphereCloud(200, 1e12, {1, 1, 1}, 3);
  const ConvexPolyhedron h = checkedHull(cloud, true);
  EXPECT_EQ(h.vertexCount(), 200u);
  EXPECT_EQ(h.faceCount(), 396u);
}

TEST(ExactHull3D, ANeedleFrom1eMinus308To1e154IsAccepted) {
  // found by fuzzing: seen from its inside, the corners near the origin and the one near 1e154
  // round to two antipodal directions, so a floating-point winding count saw two turns
  const std::vector<Vec3> cloud = {
      {-0x1.cc121cdc315fap+415, -0x1.bac1d2d37d1e4p+415, -0x1.e67ae2e778b1p+417},
      {-0x1.a0991a5b39378p+353, 0x1.9346d2c9d578ep+350, 0x1.25574a9abf383p+353},
      {0x1.6e56735725705p-865, 0x1.e9084e918f0c3p-863, -0x1.e361767b2ab13p-865},
      {0x1.f554042fecadcp+512, -0x1.93c31cd10a036p+513, 0x1.7cfc7b0bc65b2p+512},
      {0, 0, 0x1p-190},
      {0, 0, 0x1p-1022},
      {0x1.9a3f69fc40e6ap-738, 0x1.29924da7c209p-735, 0x1.9d7acdf6cfd4cp-735}};
  const ConvexPolyhedron h = checkedHull(cloud, true);
  EXPECT_GE(h.vertexCount(), 4u);
}

TEST(ExactHull3D, FlatEllipsoids) {
  for (double offset : {0.0, 1e6}) {
    SCOPED_TRACE(offset);
    const std::vector<Vec3> cloud = sphereCloud(20000, offset, {1, 1, 1e-9}, 5);
    const ConvexPolyhedron h = checkedHull(cloud, false);
    EXPECT_GT(h.vertexCount(), 100u);
  }
}

TEST(ExactHull3D, GaussianCloudsAt1e15) {
  // coordinates on a grid of 1/8: many duplicates and exactly coplanar points
  for (std::size_t n : {std::size_t{300}, std::size_t{20000}}) {
    SCOPED_TRACE(n);
    checkedHull(gaussianCloud(n, 1e15, 17), n <= 300);
  }
}

TEST(ExactHull3D, IsTheSameForTheSamePoints) {
  const std::vector<Vec3> cloud = gaussianCloud(5000, 0, 23);
  const ConvexPolyhedron a = ConvexPolyhedron::hullOf(cloud), b = ConvexPolyhedron::hullOf(cloud);
  ASSERT_EQ(a.faceCount(), b.faceCount());
  EXPECT_TRUE(std::equal(a.triangles().begin(), a.triangles().end(), b.triangles().begin()));
  EXPECT_TRUE(std::equal(a.vertices().begin(), a.vertices().end(), b.vertices().begin()));
}

// === Coplanar, collinear and repeated points

TEST(ExactHull3D, PointsOnACubesFacesAreAllOnTheBoundary) {
  // random points exactly on the faces of [-1, 1]^3, no corners among them: every one lies
  // on the boundary of any convex set inside the cube that holds it
  Rng rng(31);
  std::vector<Vec3> cloud(20000);
  for (std::size_t i = 0; i < cloud.size(); ++i) {
    Vec3 p{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    const double side = i % 2 ? 1.0 : -1.0;
    (i % 6 < 2 ? p.x : i % 6 < 4 ? p.y : p.z) = side;
    cloud[i] = p;
  }
  const ConvexPolyhedron h = checkedHull(cloud, false);
  reftest::Reference ref(h);
  ASSERT_TRUE(ref.sound());
  std::size_t boundary = 0;
  for (Vec3 p : cloud) boundary += ref.locate(p) == Location::Boundary;
  EXPECT_EQ(boundary, cloud.size());
}

TEST(ExactHull3D, LatticePointsGiveTheCube) {
  // the k^3 integer lattice: the hull is [0, k - 1]^3; surface points are Boundary, the
  // rest Inside
  const int k = 12;
  std::vector<Vec3> cloud;
  for (int x = 0; x < k; ++x)
    for (int y = 0; y < k; ++y)
      for (int z = 0; z < k; ++z) cloud.push_back({double(x), double(y), double(z)});
  const ConvexPolyhedron h = checkedHull(cloud, false);
  EXPECT_DOUBLE_EQ(h.volume(), (k - 1.0) * (k - 1.0) * (k - 1.0));
  reftest::Reference ref(h);
  ASSERT_TRUE(ref.sound());
  EXPECT_EQ(ref.planes(), 6u);
  for (Vec3 p : cloud) {
    const bool surface =
        p.x == 0 || p.y == 0 || p.z == 0 || p.x == k - 1 || p.y == k - 1 || p.z == k - 1;
    EXPECT_EQ(ref.locate(p), surface ? Location::Boundary : Location::Inside);
  }
}

TEST(ExactHull3D, RepeatedPointsChangeNothing) {
  const std::vector<Vec3> cloud = sphereCloud(2000, 1e9, {1, 1, 1}, 41);
  std::vector<Vec3> repeated;
  for (int copy = 0; copy < 3; ++copy) repeated.insert(repeated.end(), cloud.begin(), cloud.end());
  Rng rng(2);
  for (std::size_t i = repeated.size(); i > 1; --i)
    std::swap(repeated[i - 1], repeated[rng.below(i)]);
  const ConvexPolyhedron once = checkedHull(cloud, false), thrice = checkedHull(repeated, false);
  EXPECT_EQ(cornerSet(once), cornerSet(thrice));
  EXPECT_EQ(once.vertexCount(), thrice.vertexCount());
}

TEST(ExactHull3D, PointsOnTheHullsEdgesStayOnIt) {
  // a tetrahedron with many points exactly on its edges (dyadic steps) and inside it
  const Vec3 c[4] = {{0, 0, 0}, {8, 0, 0}, {0, 8, 0}, {0, 0, 8}};
  std::vector<Vec3> cloud;
  for (int i = 0; i < 4; ++i)
    for (int j = i + 1; j < 4; ++j)
      for (int s = 1; s < 64; ++s) {
        const double t = s / 64.0;
        cloud.push_back({c[i].x + t * (c[j].x - c[i].x), c[i].y + t * (c[j].y - c[i].y),
                         c[i].z + t * (c[j].z - c[i].z)});
      }
  for (int i = 0; i < 4; ++i) cloud.push_back(c[i]);
  cloud.push_back({1, 1, 1});
  const ConvexPolyhedron h = checkedHull(cloud, true);
  reftest::Reference ref(h);
  ASSERT_TRUE(ref.sound());
  EXPECT_EQ(ref.planes(), 4u);
  EXPECT_DOUBLE_EQ(h.volume(), 512.0 / 6.0);
  for (std::size_t i = 0; i + 1 < cloud.size(); ++i)
    EXPECT_EQ(ref.locate(cloud[i]), Location::Boundary);
  EXPECT_EQ(ref.locate(cloud.back()), Location::Inside);
}

// === Against a brute-force rational hull

namespace {

// The facet planes of the hull of a small cloud, by brute force in GMP rationals: for every
// three points not on one line with no point strictly on either side of their plane, the
// set of points on that plane.
std::set<std::vector<std::size_t>> bruteFacets(std::span<const Vec3> p) {
  std::set<std::vector<std::size_t>> out;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      for (std::size_t k = j + 1; k < p.size(); ++k) {
        int above = 0, below = 0;
        std::vector<std::size_t> on;
        for (std::size_t q = 0; q < p.size(); ++q) {
          const int s = reftest::rationalOrient(p[i], p[j], p[k], p[q]);
          above += s > 0, below += s < 0;
          if (s == 0) on.push_back(q);
        }
        if (above + below > 0 && (above == 0 || below == 0)) out.insert(on);
      }
  return out;
}

// the same sets for the planes of h's triangles
std::set<std::vector<std::size_t>> hullFacets(std::span<const Vec3> p, const ConvexPolyhedron& h) {
  std::set<std::vector<std::size_t>> out;
  const auto v = h.vertices();
  for (const auto& t : h.triangles()) {
    std::vector<std::size_t> on;
    for (std::size_t q = 0; q < p.size(); ++q)
      if (reftest::rationalOrient(v[t[0]], v[t[1]], v[t[2]], p[q]) == 0) on.push_back(q);
    out.insert(on);
  }
  return out;
}

}  // namespace

TEST(ExactHull3D, SmallCloudsMatchTheBruteForceHull) {
  Rng rng(59);
  for (int round = 0; round < 120; ++round) {
    SCOPED_TRACE(round);
    const std::size_t n = 4 + rng.below(20);
    std::vector<Vec3> cloud(n);
    // small integers (many coplanar, collinear and equal points), or doubles near 1e15
    const bool lattice = round % 2 == 0;
    for (Vec3& q : cloud) {
      if (lattice)
        q = {double(rng.below(4)), double(rng.below(4)), double(rng.below(3))};
      else
        q = {1e15 + 0.125 * double(rng.below(5)), 1e15 - 0.125 * double(rng.below(5)),
             rng.uniform(-1, 1)};
    }
    try {
      const ConvexPolyhedron h = checkedHull(cloud, true);
      EXPECT_EQ(hullFacets(cloud, h), bruteFacets(cloud));
    } catch (const GeometryError& e) {
      EXPECT_THAT(e.what(), HasSubstr("zero volume"));  // a flat draw
      EXPECT_TRUE(bruteFacets(cloud).empty());
    }
  }
}

TEST(ExactHull3D, GeneralCloudsMatchSmallHull) {
  // in general position every facet is a triangle, and smallHull lists each one
  Rng rng(61);
  for (int round = 0; round < 20; ++round) {
    std::vector<Vec3> cloud = sphereCloud(10 + rng.below(50), 0, {1, 1, 1}, 100 + round);
    cloud.push_back({0.1, 0.2, -0.1});
    const ConvexPolyhedron h = checkedHull(cloud, false);
    const MeshData small = smallHull(cloud);
    EXPECT_EQ(h.faceCount(), small.faceCount());
    EXPECT_EQ(hullFacets(cloud, h).size(), small.faceCount());
  }
}

// === Refusals

TEST(ExactHull3D, DegenerateCloudsAreRefusedClearly) {
  auto message = [](std::vector<Vec3> cloud) {
    try {
      ConvexPolyhedron::hullOf(cloud);
    } catch (const GeometryError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({}), "a hull needs at least 4 points not in one plane, got none");
  EXPECT_THAT(message({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}),
              HasSubstr("at least 4 points not in one plane, got 3"));
  EXPECT_THAT(message({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}}),
              HasSubstr("the 4 points are all equal"));
  std::vector<Vec3> line, plane;
  for (int i = 0; i < 50; ++i) {
    line.push_back({1e15 + i, 2e15 + 2 * i, -3.0 * i});
    plane.push_back({1e15 + i % 7, 1e15 + (i * i) % 11, 1e15 + i % 7 + (i * i) % 11});
  }
  EXPECT_THAT(message(line), HasSubstr("zero volume: the 50 points are collinear"));
  EXPECT_THAT(message(plane), HasSubstr("zero volume: the 50 points are coplanar"));
  std::vector<Vec3> nan = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, std::nan("")}};
  EXPECT_THAT(message(nan), HasSubstr("point 3 has a coordinate that is not a finite number"));
}

// === Callers

TEST(ExactHull3D, TheIcosahedronsDualKeepsAllTwentyNormals) {
  const ConvexPolyhedron ico(generatePolyhedron(PolyhedronKind::Icosahedron, 4, 1));
  const PlaneStats s = PlaneIntersector(ico, PlaneMethod::Dual).stats();
  EXPECT_EQ(s.dualVertices, 20u);
  // the dodecahedron's 12 pentagons: a pentagon of rounded unit normals is one face where its
  // five corners happen to be exactly coplanar, else three
  EXPECT_GE(s.dualFaces, 12u);
  EXPECT_LE(s.dualFaces, 36u);
}

TEST(ExactHull3D, GeneratedHullsAreExact) {
  for (PolyhedronKind k : {PolyhedronKind::SphereHull, PolyhedronKind::CubeHull,
                           PolyhedronKind::EllipsoidHull, PolyhedronKind::TinyFaces}) {
    SCOPED_TRACE(std::string(toString(k)));
    const MeshData a = generatePolyhedron(k, 3000, 9), b = generatePolyhedron(k, 3000, 9);
    EXPECT_EQ(a.vertices, b.vertices);
    EXPECT_EQ(a.indices, b.indices);
    EXPECT_NO_THROW(ConvexPolyhedron{a});
  }
}

// === 2D

TEST(ExactHull2D, IsTheStrictlyConvexHullWithInputIndices) {
  Rng rng(71);
  std::vector<Vec2> cloud;
  for (int i = 0; i < 3000; ++i) cloud.push_back({double(rng.below(50)), double(rng.below(30))});
  cloud.push_back({1e15, 1e15});
  const ConvexPolygon h = ConvexPolygon::hullOf(cloud);
  ASSERT_GE(h.size(), 3u);
  for (std::size_t i = 0; i < h.size(); ++i) {
    EXPECT_EQ(h.vertex(i), cloud[h.sourceIndex()[i]]);
    EXPECT_EQ(orient2d(h.vertex(i), h.vertex((i + 1) % h.size()), h.vertex((i + 2) % h.size())), 1);
  }
  for (Vec2 p : cloud)
    for (std::size_t i = 0; i < h.size(); ++i)
      EXPECT_GE(orient2d(h.edgeStart(i), h.edgeEnd(i), p), 0);
}

TEST(ExactHull2D, DegenerateCloudsAreRefusedClearly) {
  auto message = [](std::vector<Vec2> cloud) {
    try {
      ConvexPolygon::hullOf(cloud);
    } catch (const GeometryError& e) {
      return std::string(e.what());
    }
    return std::string("no error");
  };
  EXPECT_EQ(message({}), "a hull needs at least 3 points not on one line, got none");
  EXPECT_THAT(message({{0, 0}, {1, 1}}), HasSubstr("got 2"));
  EXPECT_THAT(message({{0, 0}, {1, 1}, {2, 2}, {0.5, 0.5}}),
              HasSubstr("zero area: the 4 points are collinear"));
  EXPECT_THAT(message({{3, 4}, {3, 4}, {3, 4}}), HasSubstr("the 3 points are all equal"));
  EXPECT_THAT(message({{0, 0}, {1, std::nan("")}, {2, 0}}),
              HasSubstr("point 1 has a coordinate that is not a finite number"));
}
