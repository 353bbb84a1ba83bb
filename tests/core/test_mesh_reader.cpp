// OFF and OBJ readers: what they accept, every rejection with its line, writers that read
// back the same doubles, and the files in tests/data.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>
#include <string>

#include "convexloc/error.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/mesh_reader.hpp"
#include "mesh_bytes.hpp"
#include "shapes3d.hpp"

using namespace convexloc;
using testing::HasSubstr;

namespace {

const char* kCubeOff =
    "# a cube\n"
    "OFF\n"
    "\n"
    "8 6 12   # counts\n"
    "-1 -1 -1\n-1 -1 1\n-1 1 -1\n-1 1 1\n"
    "1 -1 -1\r\n1 -1 1\n1 1 -1\n1 1 1\n"
    "4 0 1 3 2\n4 4 6 7 5\n4 0 4 5 1\n"
    "4 2 3 7 6   255 0 0\n4 0 2 6 4\n4 1 5 7 3\n";

// the ParseError of parsing `text` as OFF (or OBJ), with its line
using meshbytes::Problem;
using meshbytes::problemOf;
Problem offProblem(const std::string& text) {
  return problemOf(MeshFormat::Off, text);
}
Problem objProblem(const std::string& text) {
  return problemOf(MeshFormat::Obj, text);
}

// a cube in OBJ with texture and normal references and statements to ignore
std::string cubeObj() {
  return "# cube\nmtllib cube.mtl\no cube\n"
         "v -1 -1 -1\nv -1 -1 1\nv -1 1 -1\nv -1 1 1\nv 1 -1 -1\nv 1 -1 1\nv 1 1 -1\nv 1 1 1 1.0\n"
         "vt 0 0\nvt 1 0\nvn 0 0 1\ng side\ns off\nusemtl red\n"
         "f 1/1/1 2/2/1 4/1/1 3/2/1\nf 5//1 7//1 8//1 6//1\nf 1 5 6 2\n"
         "f 3 4 8 7\nf 1/1 3/1 7/1 5/1\nf -7 -3 -1 -5\n";
}

}  // namespace

TEST(OffReader, ReadsACubeWithCommentsBlankLinesAndColours) {
  MeshData m = parseMesh(MeshFormat::Off, kCubeOff);
  ASSERT_EQ(m.vertices.size(), 8u);
  ASSERT_EQ(m.faceCount(), 6u);
  EXPECT_EQ(m.vertices[5], (Vec3{1, -1, 1}));
  EXPECT_EQ(m.vertexLines[0], 5u);
  EXPECT_EQ(m.faceLines[3], 16u);
  EXPECT_EQ(m.face(3)[2], 7u);
  ConvexPolyhedron p(m);
  EXPECT_DOUBLE_EQ(p.volume(), 8.0);
}

TEST(OffReader, HeaderVariants) {
  EXPECT_EQ(parseMesh(MeshFormat::Off,
                      "OFF 4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n")
                .faceCount(),
            4u);
  EXPECT_EQ(parseMesh(MeshFormat::Off,
                      "4 4\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n")
                .faceCount(),
            4u);
  MeshData c = parseMesh(MeshFormat::Off,
                         "COFF\n4 4 6\n0 0 0 1 0 0 1\n1 0 0 1 0 0 1\n0 1 0 1 0 0 1\n0 0 1 1 0 0 1\n"
                         "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n");
  EXPECT_EQ(c.vertices[1], (Vec3{1, 0, 0}));
  EXPECT_THAT(offProblem("4OFF\n1 1 0\n").message, HasSubstr("only 3D OFF"));
  EXPECT_THAT(offProblem("nOFF\n3\n").message, HasSubstr("only 3D OFF"));
  EXPECT_THAT(offProblem("PLY\n").message, HasSubstr("not an OFF file"));
  EXPECT_THAT(offProblem("").message, HasSubstr("empty OFF file"));
  EXPECT_THAT(offProblem("OFF\n8\n").message, HasSubstr("needs the vertex and face counts"));
  EXPECT_THAT(offProblem("OFF\n8 x 0\n").message,
              HasSubstr("face count is not a non-negative integer"));
  EXPECT_THAT(offProblem("OFF\n-8 6 0\n").message,
              HasSubstr("vertex count is not a non-negative integer"));
  EXPECT_THAT(offProblem("OFF\n8 6 0 9\n").message,
              HasSubstr("unexpected text after the OFF counts"));
}

TEST(OffReader, AbsurdHeaderCountsFailFast) {
  auto t0 = std::chrono::steady_clock::now();
  Problem p = offProblem("OFF\n8 1000000000000 0\n0 0 0\n");
  EXPECT_THAT(p.message, HasSubstr("announces 1000000000000 faces; at most"));
  EXPECT_EQ(p.line, 2u);
  EXPECT_THAT(offProblem("OFF\n99999999999999999999999999 6 0\n").message,
              HasSubstr("announces 99999999999999999999999999 vertices"));
  // under the limit but far more than the file holds: never allocated, fails at the end
  Problem q = offProblem("OFF\n4 100000000 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n");
  EXPECT_THAT(q.message, HasSubstr("the file ends after 1 of the 100000000 faces"));
  Problem r = offProblem("OFF\n100000000 1 0\n0 0 0\n");
  EXPECT_THAT(r.message, HasSubstr("the file ends after 1 of the 100000000 vertices"));
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count(), 0.5);
}

TEST(OffReader, BadLinesNameTheirLine) {
  const std::string head = "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n";
  Problem p = offProblem(head + "0 0\n");
  EXPECT_THAT(p.message, HasSubstr("a vertex needs 3 coordinates, found 2"));
  EXPECT_EQ(p.line, 6u);
  EXPECT_THAT(offProblem(head + "0 0 1 5\n").message, HasSubstr("found 4"));
  EXPECT_THAT(offProblem(head + "0 0 zero\n").message, HasSubstr("not a number: 'zero'"));
  EXPECT_THAT(offProblem(head + "0 0 1e999\n").message, HasSubstr("out of the range"));
  const std::string verts = head + "0 0 1\n";
  Problem q = offProblem(verts + "3 0 2 1\n3 0 1 4\n3 1 2 3\n3 2 0 3\n");
  EXPECT_THAT(q.message, HasSubstr("vertex index 4 is out of range: the file has 4 vertices"));
  EXPECT_EQ(q.line, 8u);
  EXPECT_THAT(offProblem(verts + "3 0 -2 1\n").message,
              HasSubstr("vertex index -2 is out of range"));
  EXPECT_THAT(offProblem(verts + "2 0 1\n").message, HasSubstr("a face needs at least 3 vertices"));
  EXPECT_THAT(offProblem(verts + "4 0 1 2\n").message,
              HasSubstr("announces 4 vertices but lists 3"));
  EXPECT_THAT(offProblem(verts + "3 0 1 x\n").message, HasSubstr("not a vertex index: 'x'"));
  EXPECT_THAT(offProblem(verts + "three 0 1 2\n").message,
              HasSubstr("starts with its vertex count"));
  EXPECT_THAT(offProblem(verts + "3 0 2 1 1 2\n").message,
              HasSubstr("unexpected text after the face"));
  Problem t = offProblem(verts + "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n7 7 7\n");
  EXPECT_THAT(t.message, HasSubstr("unexpected text after the last face"));
  EXPECT_EQ(t.line, 11u);
}

TEST(ObjReader, ReadsReferencesOfEveryFormAndIgnoresOtherStatements) {
  MeshData m = parseMesh(MeshFormat::Obj, cubeObj());
  ASSERT_EQ(m.vertices.size(), 8u);
  ASSERT_EQ(m.faceCount(), 6u);
  EXPECT_EQ(m.face(0)[2], 3u);
  EXPECT_EQ(m.face(5)[0], 1u);  // -7 counts back from the last vertex
  EXPECT_EQ(m.faceLines[0], 18u);
  ConvexPolyhedron p(m);
  EXPECT_DOUBLE_EQ(p.volume(), 8.0);
  // a face before its vertices (positive references may point forward)
  MeshData fwd = parseMesh(MeshFormat::Obj, "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n");
  EXPECT_EQ(fwd.faceCount(), 1u);
  // vertex colours
  EXPECT_EQ(parseMesh(MeshFormat::Obj, "v 1 2 3 0.5 0.5 0.5\n").vertices[0], (Vec3{1, 2, 3}));
}

TEST(ObjReader, BadLinesNameTheirLine) {
  Problem p = objProblem("v 0 0 0\nv 1 2\n");
  EXPECT_THAT(p.message, HasSubstr("a vertex needs 3 coordinates"));
  EXPECT_EQ(p.line, 2u);
  EXPECT_THAT(objProblem("v 0 0 zero\n").message, HasSubstr("not a number: 'zero'"));
  EXPECT_THAT(objProblem("v 0 0 0 2\n").message, HasSubstr("weight w other than 1"));
  const std::string tri = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
  EXPECT_THAT(objProblem(tri + "f 1 2\n").message,
              HasSubstr("a face needs at least 3 vertices, this one has 2"));
  EXPECT_THAT(objProblem(tri + "f 0 1 2\n").message, HasSubstr("OBJ numbers vertices from 1"));
  EXPECT_THAT(objProblem(tri + "f 1 a 2\n").message, HasSubstr("not a vertex reference: 'a'"));
  EXPECT_THAT(objProblem(tri + "f 1 2 -4\n").message, HasSubstr("points before the first vertex"));
  Problem q = objProblem(tri + "f 1 2 3\nf 1 2 9\nv 5 5 5\n");
  EXPECT_THAT(q.message, HasSubstr("vertex reference 9 is out of range: the file has 4 vertices"));
  EXPECT_EQ(q.line, 5u);
  EXPECT_THAT(objProblem(tri + "f 1 2 \\\n3\n").message, HasSubstr("continuations"));
}

TEST(MeshWriters, RoundTripTheSameDoubles) {
  MeshData m = generatePolyhedron(PolyhedronKind::Offset, 320, 3);
  for (int format = 0; format < 2; ++format) {
    std::FILE* f = std::tmpfile();
    ASSERT_NE(f, nullptr);
    if (format == 0)
      writeOff(f, m);
    else
      writeObj(f, m);
    std::rewind(f);
    MeshData back = format == 0 ? parseMesh(MeshFormat::Off, f) : parseMesh(MeshFormat::Obj, f);
    std::fclose(f);
    EXPECT_EQ(back.vertices, m.vertices);
    EXPECT_EQ(back.indices, m.indices);
    EXPECT_EQ(back.faceStart, m.faceStart);
  }
  ConvexPolyhedron p(m);
  MeshData t = toMesh(p);
  EXPECT_EQ(t.faceCount(), p.faceCount());
  EXPECT_EQ(ConvexPolyhedron(t).faceCount(), p.faceCount());
}

TEST(MeshFiles, FormatByExtensionAndTheDataFiles) {
  EXPECT_EQ(meshFormatOf("a/b.OFF"), MeshFormat::Off);
  EXPECT_EQ(meshFormatOf("b.obj"), MeshFormat::Obj);
  EXPECT_FALSE(meshFormatOf("b.txt").has_value());
  EXPECT_THROW(readMesh("shape.3mf"), UsageError);
  EXPECT_THROW(readMesh(std::string(CONVEXLOC_TEST_DATA) + "/no_such_file.off"), Error);
  const std::string data = CONVEXLOC_TEST_DATA;
  EXPECT_EQ(loadPolyhedron(data + "/cube.off").faceCount(), 12u);
  EXPECT_EQ(loadPolyhedron(data + "/cube_uv.obj").faceCount(), 12u);
  EXPECT_TRUE(loadPolyhedron(data + "/tetra_inverted.off").wasInverted());
  auto fails = [&](const std::string& file, const std::string& text, std::size_t line) {
    try {
      loadPolyhedron(data + "/" + file);
      ADD_FAILURE() << file << " was accepted";
    } catch (const Error& e) {
      EXPECT_THAT(e.what(), HasSubstr(text)) << file;
      if (line) {
        EXPECT_EQ(e.line(), line) << file;
      }
    }
  };
  fails("open_box.off", "the surface is open", 0);
  fails("mixed_orientation.off", "inconsistent orientation", 15);
  fails("dented_cube.off", "not convex: reflex edge", 0);
  fails("star_bipyramid.off", "winds 2 times", 0);
  fails("flat.off", "zero volume", 0);
  fails("absurd_header.off", "announces 1000000000000 faces", 2);
  fails("bad_face.obj", "vertex reference 0", 6);
  fails("nan_vertex.obj", "not a number", 3);
  fails("nonmanifold.off", "not a manifold", 0);
}

// the example polyhedra shipped for users are valid
TEST(MeshFiles, AssetsValidate) {
  const std::string assets = CONVEXLOC_ASSETS;
  for (const char* name : {"cube.off", "icosahedron.off", "dodecahedron.off", "geodesic-1280.obj",
                           "tiny-faces-2000.off"}) {
    SCOPED_TRACE(name);
    EXPECT_NO_THROW(loadPolyhedron(assets + "/" + name));
  }
}
