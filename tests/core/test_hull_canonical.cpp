// Canonical exact hulls: the vertices are exactly the extreme points of the cloud, decided
// here by brute force in GMP rationals (Caratheodory: a point is not extreme iff it lies in
// a segment, triangle or tetrahedron of other points, each nondegenerate), the faces are the
// maximal planes, and the same points in any order give the same shape, array for array.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <set>
#include <string>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/mesh_reader.hpp"
#include "convexloc/polygon.hpp"
#include "convexloc/polyhedron.hpp"
#include "mesh_bytes.hpp"
#include "reference2d.hpp"
#include "reference3d.hpp"

using namespace convexloc;

namespace {

bool lexLess(Vec3 a, Vec3 b) {
  return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
}

// the 2D orientation of a, b, c projected on coordinate plane `axis` (0: yz, 1: zx, 2: xy),
// in rationals
int projectedCross(Vec3 o, Vec3 a, Vec3 b, int axis) {
  auto flat = [axis](Vec3 p) {
    return axis == 0 ? Vec2{p.y, p.z} : axis == 1 ? Vec2{p.z, p.x} : Vec2{p.x, p.y};
  };
  return ref::crossRational(flat(o), flat(a), flat(b));
}

// p lies in the closed segment a b, which is not a point
bool inSegment(Vec3 p, Vec3 a, Vec3 b) {
  for (int axis = 0; axis < 3; ++axis)
    if (projectedCross(a, b, p, axis) != 0) return false;
  auto within = [](double lo, double v, double hi) {
    return (lo <= v && v <= hi) || (hi <= v && v <= lo);
  };
  return !(a == b) && within(a.x, p.x, b.x) && within(a.y, p.y, b.y) && within(a.z, p.z, b.z);
}

// p lies in the closed triangle a b c, which has an area
bool inTriangle(Vec3 p, Vec3 a, Vec3 b, Vec3 c) {
  if (reftest::rationalOrient(a, b, c, p) != 0) return false;
  for (int axis = 0; axis < 3; ++axis) {
    const int s = projectedCross(a, b, c, axis);
    if (s == 0) continue;
    return projectedCross(a, b, p, axis) * s >= 0 && projectedCross(b, c, p, axis) * s >= 0 &&
           projectedCross(c, a, p, axis) * s >= 0;
  }
  return false;  // a, b, c on one line
}

// p lies in the closed tetrahedron a b c d, which has a volume
bool inTetrahedron(Vec3 p, Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const int s = reftest::orient(a, b, c, d);
  return s != 0 && reftest::orient(a, b, c, p) * s >= 0 && reftest::orient(a, b, p, d) * s >= 0 &&
         reftest::orient(a, p, c, d) * s >= 0 && reftest::orient(p, b, c, d) * s >= 0;
}

// the extreme points of a small cloud, distinct and sorted, by brute force
std::vector<Vec3> bruteExtremePoints(std::vector<Vec3> cloud) {
  std::sort(cloud.begin(), cloud.end(), lexLess);
  cloud.erase(std::unique(cloud.begin(), cloud.end()), cloud.end());
  std::vector<Vec3> out;
  const std::size_t n = cloud.size();
  for (std::size_t i = 0; i < n; ++i) {
    std::vector<Vec3> others;
    for (std::size_t j = 0; j < n; ++j)
      if (j != i) others.push_back(cloud[j]);
    const Vec3 p = cloud[i];
    const std::size_t m = others.size();
    bool covered = false;
    for (std::size_t a = 0; a < m && !covered; ++a)
      for (std::size_t b = a + 1; b < m && !covered; ++b) {
        covered = inSegment(p, others[a], others[b]);
        for (std::size_t c = b + 1; c < m && !covered; ++c) {
          covered = inTriangle(p, others[a], others[b], others[c]);
          for (std::size_t d = c + 1; d < m && !covered; ++d)
            covered = inTetrahedron(p, others[a], others[b], others[c], others[d]);
        }
      }
    if (!covered) out.push_back(p);
  }
  return out;
}

// `cloud` in a random order
std::vector<Vec3> shuffled(std::vector<Vec3> cloud, Rng& rng) {
  for (std::size_t i = cloud.size(); i > 1; --i) std::swap(cloud[i - 1], cloud[rng.below(i)]);
  return cloud;
}

// a and b are the same shape, array for array
void expectSameShape(const ConvexPolyhedron& a, const ConvexPolyhedron& b) {
  ASSERT_EQ(a.vertexCount(), b.vertexCount());
  ASSERT_EQ(a.faceCount(), b.faceCount());
  EXPECT_TRUE(std::equal(a.vertices().begin(), a.vertices().end(), b.vertices().begin()));
  EXPECT_TRUE(std::equal(a.triangles().begin(), a.triangles().end(), b.triangles().begin()));
  EXPECT_EQ(a.planeCount(), b.planeCount());
}

// The hull of `cloud`, checked: the vertices sorted by coordinates, each the input point
// sourceVertex() names, no two consecutive corners of a plane face's loop collinear with the
// next, and the same shape from `orders` shuffles of the cloud.
ConvexPolyhedron canonicalHull(const std::vector<Vec3>& cloud, Rng& rng, int orders) {
  const ConvexPolyhedron h = ConvexPolyhedron::hullOf(cloud);
  const auto v = h.vertices();
  EXPECT_TRUE(std::is_sorted(v.begin(), v.end(), lexLess));
  for (std::size_t i = 0; i < v.size(); ++i) EXPECT_EQ(v[i], cloud[h.sourceVertex()[i]]);
  for (std::size_t f = 0; f < h.planeCount(); ++f) {
    const auto loop = h.planeLoop(f);
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Vec3 a = v[loop[i]], b = v[loop[(i + 1) % loop.size()]],
                 c = v[loop[(i + 2) % loop.size()]];
      EXPECT_FALSE(inSegment(b, a, c)) << "a vertex on an edge of plane face " << f;
    }
  }
  std::vector<Vec3> reversed(cloud.rbegin(), cloud.rend());
  expectSameShape(h, ConvexPolyhedron::hullOf(reversed));
  for (int k = 0; k < orders; ++k)
    expectSameShape(h, ConvexPolyhedron::hullOf(shuffled(cloud, rng)));
  return h;
}

std::vector<Vec3> sortedVertices(const ConvexPolyhedron& h) {
  return {h.vertices().begin(), h.vertices().end()};
}

// the 8 corners of [0, 1]^3
std::vector<Vec3> boxCorners() {
  std::vector<Vec3> out;
  for (int i = 0; i < 8; ++i) out.push_back({double(i & 1), double(i >> 1 & 1), double(i >> 2)});
  return out;
}

// how many times the big tests are scaled down (CONVEXLOC_HOSTILE_SCALE, as in the sanitized
// run, where 0.1 makes them 8 times smaller)
int shrink() {
  const char* env = std::getenv("CONVEXLOC_HOSTILE_SCALE");
  return env && std::atof(env) < 1 ? 8 : 1;
}

}  // namespace

TEST(CanonicalHull3D, VerticesAreTheBruteForceExtremePointsInEveryOrder) {
  Rng rng(83);
  for (int round = 0; round < 80 / shrink(); ++round) {
    SCOPED_TRACE(round);
    // small lattices (many points on faces and edges), dyadic points on a box's edges and
    // faces, a flat lattice moved to 1e15, or points on a box's faces moved one ulp in, out
    // or not at all (the box's corners among them)
    const std::size_t n = round % 4 == 3 ? 2 + rng.below(9) : 6 + rng.below(14);
    std::vector<Vec3> cloud(n);
    for (Vec3& q : cloud) {
      const int kind = round % 4;
      if (kind == 3) {
        double c[3] = {rng.uniform(), rng.uniform(), std::round(rng.uniform())};
        c[2] = std::nextafter(c[2], c[2] + double(int(rng.below(3)) - 1));
        std::rotate(c, c + rng.below(3), c + 3);
        q = {c[0], c[1], c[2]};
      } else if (kind == 0) {
        q = {double(rng.below(3)), double(rng.below(3)), double(rng.below(3))};
      } else if (kind == 1) {
        q = {double(rng.below(2)), double(rng.below(2)), 0.25 * double(rng.below(5))};
        if (rng.below(2)) std::swap(q.x, q.z);
      } else {
        q = {1e15 + 0.125 * double(rng.below(4)), 1e15 - 0.125 * double(rng.below(4)),
             double(rng.below(3)) - 1};
      }
    }
    if (round % 4 == 3) {
      const std::vector<Vec3> corners = boxCorners();
      cloud.insert(cloud.end(), corners.begin(), corners.end());
    }
    try {
      const ConvexPolyhedron h = canonicalHull(cloud, rng, 3);
      EXPECT_EQ(sortedVertices(h), bruteExtremePoints(cloud));
    } catch (const GeometryError& e) {
      EXPECT_NE(std::string(e.what()).find("zero volume"), std::string::npos) << e.what();
    }
  }
}

TEST(CanonicalHull3D, ACubesCornersAndFaceCentresGiveEightVerticesInEveryOrder) {
  std::vector<Vec3> cloud;
  for (const Vec3 c : boxCorners()) cloud.push_back({2 * c.x - 1, 2 * c.y - 1, 2 * c.z - 1});
  for (int axis = 0; axis < 3; ++axis)
    for (double side : {-1.0, 1.0}) {
      double centre[3] = {0, 0, 0};
      centre[axis] = side;
      cloud.push_back({centre[0], centre[1], centre[2]});
    }
  Rng rng(89);
  const ConvexPolyhedron h = canonicalHull(cloud, rng, 500);
  EXPECT_EQ(h.vertexCount(), 8u);
  EXPECT_EQ(h.planeCount(), 6u);
  EXPECT_EQ(h.faceCount(), 12u);
  EXPECT_EQ(sortedVertices(h), bruteExtremePoints(cloud));
  // the corners first, the centres first, and the reverse of each
  std::vector<Vec3> centresFirst(cloud.begin() + 8, cloud.end());
  centresFirst.insert(centresFirst.end(), cloud.begin(), cloud.begin() + 8);
  expectSameShape(h, canonicalHull(centresFirst, rng, 0));
}

TEST(CanonicalHull3D, ABoxWithPointsOnItsFacesAndEdgesHasEightVerticesAndSixFaces) {
  Rng rng(97);
  std::vector<Vec3> cloud = boxCorners();
  for (int i = 0; i < 300; ++i) {
    // on a face (two free coordinates) or on an edge (one), dyadic or not
    double c[3] = {rng.uniform(), rng.uniform(), std::round(rng.uniform())};
    if (i % 3 == 0) c[1] = std::round(c[1]);
    if (i % 2 == 0) c[0] = std::ldexp(std::round(std::ldexp(c[0], 10)), -10);
    std::rotate(c, c + i % 3, c + 3);
    cloud.push_back({c[0], c[1], c[2]});
  }
  std::vector<Vec3> corners = boxCorners();
  std::sort(corners.begin(), corners.end(), lexLess);
  for (const std::vector<Vec3>& order : {cloud, shuffled(cloud, rng)}) {
    const ConvexPolyhedron h = canonicalHull(order, rng, 5);
    EXPECT_EQ(h.vertexCount(), 8u);
    EXPECT_EQ(h.planeCount(), 6u);
    EXPECT_EQ(h.faceCount(), 12u);
    EXPECT_EQ(sortedVertices(h), corners);
  }
}

TEST(CanonicalHull3D, AFloat32CylinderReadAsItsHullKeepsExactlyTheRingsExtremePoints) {
  // cylinder(h = 20, r = 5, $fn = 65536) as binary STL: the float32 ring is not convex, and
  // its hull's vertices are the extreme points of the ring at both heights, which the 2D hull
  // (a monotone chain, another algorithm) finds
  const std::size_t sides = std::size_t{65536} / static_cast<std::size_t>(shrink());
  std::vector<Vec2> ring(sides);
  MeshData mesh;
  for (std::size_t i = 0; i < sides; ++i) {
    const double a = 2 * std::numbers::pi * double(i) / double(sides);
    // through volatiles: GCC 12's vectorizer may fold the round trip through float away
    volatile float x = static_cast<float>(5 * std::cos(a)), y = static_cast<float>(5 * std::sin(a));
    ring[i] = {x, y};
    mesh.addVertex({ring[i].x, ring[i].y, -10});
    mesh.addVertex({ring[i].x, ring[i].y, 10});
  }
  const auto n = static_cast<std::uint32_t>(sides);
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    mesh.addFace({2 * i, 2 * j, 2 * j + 1});
    mesh.addFace({2 * i, 2 * j + 1, 2 * i + 1});
    if (i > 0 && j > 0) mesh.addFace({0, 2 * j, 2 * i}), mesh.addFace({1, 2 * i + 1, 2 * j + 1});
  }
  const std::string stl = meshbytes::written([&](std::FILE* f) { writeStl(f, mesh); });
  const MeshData read = parseMesh(MeshFormat::Stl, stl);
  const ConvexPolyhedron h = ConvexPolyhedron::hullOf(read.vertices);
  std::vector<Vec3> expected;
  const ConvexPolygon section = ConvexPolygon::hullOf(ring);
  for (const Vec2 p : section.vertices())
    for (double z : {-10.0, 10.0}) expected.push_back({p.x, p.y, z});
  std::sort(expected.begin(), expected.end(), lexLess);
  // at 65536 sides the rounded ring has points inside hull edges (at 8192 it is convex)
  if (shrink() == 1) {
    EXPECT_LT(expected.size(), 2 * sides);
  }
  EXPECT_EQ(h.vertexCount(), expected.size());
  EXPECT_TRUE(sortedVertices(h) == expected);
  EXPECT_EQ(h.planeCount(), expected.size() / 2 + 2);
}

TEST(CanonicalHull2D, TheSamePointsGiveTheSamePolygonInEveryOrder) {
  Rng rng(101);
  std::vector<Vec2> cloud;
  for (int i = 0; i < 400; ++i) cloud.push_back({double(rng.below(9)), double(rng.below(5))});
  cloud.push_back({-0.0, 0.0});
  const ConvexPolygon h = ConvexPolygon::hullOf(cloud);
  // the corners of the box [0, 8] x [0, 4] when every corner was drawn, else fewer
  for (int k = 0; k < 20; ++k) {
    std::vector<Vec2> other = cloud;
    for (std::size_t i = other.size(); i > 1; --i) std::swap(other[i - 1], other[rng.below(i)]);
    const ConvexPolygon g = ConvexPolygon::hullOf(other);
    ASSERT_EQ(g.size(), h.size());
    for (std::size_t i = 0; i < h.size(); ++i) {
      EXPECT_EQ(g.vertex(i), h.vertex(i));
      EXPECT_FALSE(std::signbit(g.vertex(i).x) || std::signbit(g.vertex(i).y));
    }
  }
  // every vertex extreme: a strict left turn at each, and no input point outside an edge
  for (std::size_t i = 0; i < h.size(); ++i) {
    EXPECT_GT(ref::crossRational(h.vertex(i), h.edgeEnd(i), h.edgeEnd((i + 1) % h.size())), 0);
    for (Vec2 p : cloud) EXPECT_GE(ref::crossRational(h.edgeStart(i), h.edgeEnd(i), p), 0);
  }
}
