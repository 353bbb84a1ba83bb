// What a refused polyhedron says: a reflex edge's fold (its angle and how far off the plane)
// and whether float32 rounding explains it or --hull would fill a real dent; every refusal
// that the hull of the vertices cures mentions --hull; a face whose vertices are not in one
// plane is refused from whichever vertex it is listed.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/mesh_reader.hpp"
#include "convexloc/polyhedron.hpp"
#include "shapes3d.hpp"

using namespace convexloc;
using shapes3d::failureOf;
using testing::HasSubstr;
using testing::Not;

namespace {

// x through a float (volatile: GCC 12's vectorizer may fold the round trip away)
double toFloat(double x) {
  volatile float f = static_cast<float>(x);
  return f;
}

// A cylinder of radius 5 and height 20 over `sides` sides, tilted by 0.3 radians about the x
// axis and moved to 100, every coordinate rounded to float32 as a binary STL holds it: the
// side quads split in two, the caps fanned.
MeshData float32Cylinder(std::uint32_t sides) {
  MeshData m;
  const double c = std::cos(0.3), s = std::sin(0.3);
  for (std::uint32_t i = 0; i < sides; ++i) {
    const double a = 2 * std::numbers::pi * i / sides;
    for (double z : {-10.0, 10.0}) {
      const double y = 5 * std::sin(a);
      m.addVertex({toFloat(100 + 5 * std::cos(a)), toFloat(c * y - s * z), toFloat(s * y + c * z)});
    }
  }
  for (std::uint32_t i = 0; i < sides; ++i) {
    const std::uint32_t j = (i + 1) % sides;
    m.addFace({2 * i, 2 * j, 2 * j + 1});
    m.addFace({2 * i, 2 * j + 1, 2 * i + 1});
    if (i > 0 && j > 0) m.addFace({0, 2 * j, 2 * i}), m.addFace({1, 2 * i + 1, 2 * j + 1});
  }
  return m;
}

// the number printed after `before` in `text`, NaN when there is none
double numberAfter(const std::string& text, const std::string& before) {
  const std::size_t at = text.find(before);
  if (at == std::string::npos) return std::nan("");
  return std::strtod(text.c_str() + at + before.size(), nullptr);
}

// the angle between the planes of triangles (a, b, c) and (a, c, d), in degrees, the long way
double foldDegrees(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  auto normal = [](Vec3 p, Vec3 q, Vec3 r) {
    const double ux = q.x - p.x, uy = q.y - p.y, uz = q.z - p.z;
    const double wx = r.x - p.x, wy = r.y - p.y, wz = r.z - p.z;
    const double n[3] = {uy * wz - uz * wy, uz * wx - ux * wz, ux * wy - uy * wx};
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    return std::vector<double>{n[0] / length, n[1] / length, n[2] / length};
  };
  const std::vector<double> m = normal(a, b, c), n = normal(a, c, d);
  return std::acos(m[0] * n[0] + m[1] * n[1] + m[2] * n[2]) * 180 / std::numbers::pi;
}

}  // namespace

TEST(PolyhedronMessages, AFloat32RoundingFoldSaysHullIsSafe) {
  const shapes3d::Failure f = failureOf(float32Cylinder(4096));
  ASSERT_THAT(f.message, HasSubstr("not convex: reflex edge"));
  EXPECT_THAT(f.message, HasSubstr("a float32 STL rounding fold: --hull is safe"));
  EXPECT_LT(numberAfter(f.message, "a fold of "), 1e-2);
  EXPECT_LT(numberAfter(f.message, "degrees, "), 1e-5);  // off the plane
  // a quad of the same float32 cylinder, one face: not planar, within the rounding
  MeshData quads = float32Cylinder(4096);
  quads.indices.clear();
  quads.faceStart.assign(1, 0);
  for (std::uint32_t i = 0; i < 4096; ++i) {
    const std::uint32_t j = (i + 1) % 4096;
    quads.addFace({2 * i, 2 * j, 2 * j + 1, 2 * i + 1});
  }
  std::vector<std::uint32_t> cap, other;
  for (std::uint32_t i = 0; i < 4096; ++i)
    cap.push_back(2 * (4095 - i)), other.push_back(2 * i + 1);
  quads.addFace(cap);
  quads.addFace(other);
  const shapes3d::Failure q = failureOf(quads);
  EXPECT_THAT(q.message, HasSubstr("is not planar"));
  EXPECT_THAT(q.message, HasSubstr("within the rounding of float32 coordinates"));
  // and its hull is a polyhedron
  EXPECT_GT(ConvexPolyhedron::hullOf(float32Cylinder(4096).vertices).vertexCount(), 100u);
}

TEST(PolyhedronMessages, ARealDentSaysHowLargeAFoldTheHullFills) {
  // the cube [0, 4]^3 with its top's centre pushed down to (2, 2, 3): the four spokes fold by
  // the angle between neighbouring dented triangles
  const MeshData dented = parseMesh(MeshFormat::Off, R"(OFF
9 9 0
0 0 0
4 0 0
4 4 0
0 4 0
0 0 4
4 0 4
4 4 4
0 4 4
2 2 3
4 0 3 2 1
4 0 1 5 4
4 1 2 6 5
4 2 3 7 6
4 3 0 4 7
3 4 5 8
3 5 6 8
3 6 7 8
3 7 4 8
)");
  const shapes3d::Failure f = failureOf(dented);
  ASSERT_THAT(f.message, HasSubstr("not convex: reflex edge"));
  const double degrees = foldDegrees({2, 2, 3}, {0, 0, 4}, {4, 0, 4}, {4, 4, 4});
  char want[64];
  std::snprintf(want, sizeof want, "--hull would fill a dent of %.2g degrees", degrees);
  EXPECT_THAT(f.message, HasSubstr(want));
  EXPECT_THAT(f.message, HasSubstr("beyond the rounding of float32 coordinates, a real dent"));
  EXPECT_THAT(f.message, Not(HasSubstr("--hull is safe")));
  // the far corner of a neighbouring triangle, e.g. (4, 4, 4) off the plane through (0, 0, 4),
  // (4, 0, 4) and (2, 2, 3), whose normal is (0, 4, 8): 16 / sqrt(80), printed to 2 digits
  EXPECT_NEAR(numberAfter(f.message, "degrees, "), 16 / std::sqrt(80.0), 0.06);
}

TEST(PolyhedronMessages, ANonPlanarFaceIsRefusedFromEveryFirstVertex) {
  // the cube [-1, 1]^3 with one top corner raised by 0.25: the top quad, listed from each of
  // its corners, either folds convexly along its fan diagonal or reflexly; both are refused
  const std::vector<std::uint32_t> top = {1, 5, 7, 3};
  for (int first = 0; first < 4; ++first) {
    SCOPED_TRACE(first);
    MeshData m = shapes3d::cube();
    m.vertices[7].z = 1.25;
    for (int k = 0; k < 4; ++k) m.indices[m.faceStart[5] + k] = top[(first + k) % 4];
    const shapes3d::Failure f = failureOf(m);
    EXPECT_THAT(f.message, HasSubstr("face 5 is not planar: vertex "));
    EXPECT_THAT(f.message, HasSubstr("beyond the rounding of float32 coordinates"));
    EXPECT_THAT(f.message, HasSubstr("--hull"));
    EXPECT_GT(numberAfter(f.message, " lies "), 0.1);
  }
}

TEST(PolyhedronMessages, EveryRefusalAHullCuresMentionsHull) {
  MeshData open = shapes3d::cube();
  open.indices.resize(open.faceStart[5]);
  open.faceStart.pop_back();
  EXPECT_THAT(failureOf(open).message, HasSubstr("the surface is open"));
  EXPECT_THAT(failureOf(open).message, HasSubstr("--hull"));
  EXPECT_THAT(failureOf(shapes3d::torus()).message, HasSubstr("V - E + F = 0"));
  EXPECT_THAT(failureOf(shapes3d::torus()).message, HasSubstr("--hull"));
  // two cubes apart: several pieces
  MeshData two = shapes3d::cube();
  const MeshData other = shapes3d::cube();
  for (Vec3 v : other.vertices) two.addVertex({v.x + 5, v.y, v.z});
  for (std::size_t f = 0; f < other.faceCount(); ++f) {
    std::vector<std::uint32_t> face;
    for (std::uint32_t k : other.face(f)) face.push_back(k + 8);
    two.addFace(face);
  }
  EXPECT_THAT(failureOf(two).message, HasSubstr("separate pieces"));
  EXPECT_THAT(failureOf(two).message, HasSubstr("--hull"));
  // a reflex edge, through the file reader too
  EXPECT_THAT(failureOf(float32Cylinder(4096)).message, HasSubstr("--hull"));
}
