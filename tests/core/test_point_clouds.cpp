// Point clouds read for --hull: .xyz and .pts files (x y z a line, extra columns read past, a
// .pts point count checked), and ASCII PLY files whose element counts are wrong, blamed on
// the header line that holds the count.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "convexloc/error.hpp"
#include "convexloc/mesh_reader.hpp"
#include "mesh_bytes.hpp"

using namespace convexloc;
using testing::HasSubstr;

namespace {

using meshbytes::Problem;
using meshbytes::problemOf;

// the corners of [0, 1]^3 and its centre, with intensity and colour columns, comma- or
// blank-separated, as scanners write them
const char* kScan =
    "# a scan\n"
    "0 0 0 12 255 0 0\n0 0 1 13 255 0 0\n0,1,0,14,0,255,0\n0 1 1 15 0 255 0\n"
    "1 0 0 16 0 0 255\n1 0 1 17 0 0 255\n\n1 1 0 18 1 1 1\r\n1 1 1 19 1 1 1\n"
    "0.5 0.5 0.5 20 1 1 1\n";

// a cube with `vertices` announced for its 8 vertex lines, as ASCII PLY
std::string cubePly(int vertices, int faces) {
  return "ply\nformat ascii 1.0\nelement vertex " + std::to_string(vertices) +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
         std::to_string(faces) +
         "\nproperty list uchar int vertex_indices\nend_header\n"
         "-1 -1 -1\n-1 -1 1\n-1 1 -1\n-1 1 1\n1 -1 -1\n1 -1 1\n1 1 -1\n1 1 1\n"
         "4 0 1 3 2\n4 4 6 7 5\n4 0 4 5 1\n4 2 3 7 6\n4 0 2 6 4\n4 1 5 7 3\n";
}

}  // namespace

TEST(PointClouds, XyzIsReadAsPointsWithExtraColumnsReadPast) {
  EXPECT_EQ(meshFormatOf("scan.XYZ"), MeshFormat::Xyz);
  EXPECT_EQ(meshFormatOf("scan.pts"), MeshFormat::Xyz);
  const MeshData m = parseMesh(MeshFormat::Xyz, kScan);
  ASSERT_EQ(m.vertices.size(), 9u);
  EXPECT_EQ(m.faceCount(), 0u);
  EXPECT_EQ(m.vertices[2], (Vec3{0, 1, 0}));
  EXPECT_EQ(m.vertices[8], (Vec3{0.5, 0.5, 0.5}));
  EXPECT_EQ(m.vertexLines[6], 9u);  // after the blank line
  const ConvexPolyhedron hull = ConvexPolyhedron::hullOf(m.vertices);
  EXPECT_EQ(hull.vertexCount(), 8u);
  EXPECT_EQ(hull.planeCount(), 6u);
  // without --hull, a cloud is refused with the advice to take its hull
  try {
    polyhedronOf(m);
    ADD_FAILURE() << "a point cloud was accepted as a polyhedron";
  } catch (const GeometryError& e) {
    EXPECT_THAT(e.what(), HasSubstr("--hull"));
  }
}

TEST(PointClouds, XyzRefusesShortLinesAndBadNumbersWithTheirLine) {
  Problem p = problemOf(MeshFormat::Xyz, "0 0 0\n1 2\n");
  EXPECT_EQ(p.line, 2u);
  EXPECT_THAT(p.message, HasSubstr("a point needs 3 coordinates x y z, found 2 numbers"));
  p = problemOf(MeshFormat::Xyz, "0 0 0\n1 2 3\n1 2 zz\n");
  EXPECT_EQ(p.line, 3u);
  p = problemOf(MeshFormat::Xyz, "0 0 0 1 red\n");
  EXPECT_EQ(p.line, 1u);
}

TEST(PointClouds, APtsCountIsCheckedAndBlamedOnItsLine) {
  const std::string points = "0 0 0 5\n1 0 0 5\n0 1 0 5\n0 0 1 5\n";
  EXPECT_EQ(parseMesh(MeshFormat::Xyz, "4\n" + points).vertices.size(), 4u);
  Problem p = problemOf(MeshFormat::Xyz, "# scanner\n5\n" + points);
  EXPECT_EQ(p.line, 2u);
  EXPECT_THAT(p.message, HasSubstr("the point count on this line says 5, but the file holds 4"));
  p = problemOf(MeshFormat::Xyz, "-4\n" + points);
  EXPECT_EQ(p.line, 1u);
  EXPECT_THAT(p.message, HasSubstr("a point count must be a whole number"));
}

TEST(PointClouds, APlyCountTooLargeOrTooSmallPointsAtTheHeader) {
  EXPECT_EQ(parseMesh(MeshFormat::Ply, cubePly(8, 6)).faceCount(), 6u);
  // one vertex too many: the first face line is read as vertex 8
  Problem p = problemOf(MeshFormat::Ply, cubePly(9, 6));
  EXPECT_EQ(p.line, 3u);
  EXPECT_THAT(p.message,
              HasSubstr("element 'vertex' announces 9 records: line 18 ('4 0 1 3 2') fails as "
                        "vertex 8 of 9 (unexpected text after the values"));
  EXPECT_THAT(p.message, HasSubstr("reads as a 'face' record: is the count too large?"));
  // one vertex too few: the last vertex line is read as the first face
  p = problemOf(MeshFormat::Ply, cubePly(7, 6));
  EXPECT_EQ(p.line, 3u);
  EXPECT_THAT(p.message,
              HasSubstr("element 'vertex' announces 7 records: line 17 ('1 1 1') fails as face 0"));
  EXPECT_THAT(p.message, HasSubstr("reads as one more 'vertex': is the count too small?"));
  // one face too few: the last face line is left over
  p = problemOf(MeshFormat::Ply, cubePly(8, 5));
  EXPECT_EQ(p.line, 7u);
  EXPECT_THAT(p.message,
              HasSubstr("element 'face' announces 5 records: line 23 after them reads as one "
                        "more: is the count too small?"));
  // a face of 2 vertices has a face's shape: its own line is blamed, not a count
  p = problemOf(MeshFormat::Ply,
                cubePly(8, 6).replace(cubePly(8, 6).find("4 1 5 7 3"), 9, "2 1 5"));
  EXPECT_EQ(p.line, 23u);
  EXPECT_THAT(p.message, HasSubstr("face 5 has 2 vertices"));
}
