// STL and PLY readers: a convex polyhedron written in every encoding (ASCII and binary STL;
// PLY as ASCII, little- and big-endian binary, float and double properties) reads back as the
// polyhedron its OFF gives, and every 3D method answers the same on the same points; files
// assembled byte by byte read as they say; the point-cloud PLY and the hull.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <string>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/locate3d.hpp"
#include "convexloc/mesh_reader.hpp"
#include "mesh_bytes.hpp"
#include "shapes3d.hpp"

using namespace convexloc;
using testing::HasSubstr;

namespace {

using Corner = std::array<double, 3>;
using Facet = std::array<Corner, 3>;

Corner cornerOf(Vec3 p) {
  return {p.x, p.y, p.z};
}

// the triangles of `p` by their coordinates, each rotated to start at its least corner (the
// orientation kept), sorted: equal for two polyhedra with the same surface however numbered
std::vector<Facet> surfaceOf(const ConvexPolyhedron& p) {
  std::vector<Facet> out;
  for (const auto& t : p.triangles()) {
    Facet f{cornerOf(p.vertices()[t[0]]), cornerOf(p.vertices()[t[1]]),
            cornerOf(p.vertices()[t[2]])};
    std::rotate(f.begin(), std::min_element(f.begin(), f.end()), f.end());
    out.push_back(f);
  }
  std::sort(out.begin(), out.end());
  return out;
}

// query points: the generator's hard cases, uniform ones and every vertex
std::vector<Vec3> queriesFor(const ConvexPolyhedron& p) {
  std::vector<Vec3> q = generatePoints3D(p, 1500, 5, true);
  const std::vector<Vec3> uniform = generatePoints3D(p, 500, 6, false);
  q.insert(q.end(), uniform.begin(), uniform.end());
  q.insert(q.end(), p.vertices().begin(), p.vertices().end());
  return q;
}

// `got` is the polyhedron `want` is, and every method answers the same on `queries`
void expectSame(const ConvexPolyhedron& want, const MeshData& gotMesh,
                const std::vector<Vec3>& queries) {
  const ConvexPolyhedron got(gotMesh);
  ASSERT_EQ(surfaceOf(got), surfaceOf(want));
  for (Method3D m : kAllMethods3D) {
    const Locator3D a(want, m), b(got, m);
    std::vector<Location> ra(queries.size()), rb(queries.size());
    a.locate(queries, ra);
    b.locate(queries, rb);
    EXPECT_EQ(ra, rb) << toString(m);
  }
}

// a shape in every encoding, each read from memory and through a FILE
struct Encoded {
  std::string name;
  std::string bytes;
  bool stl;
};

std::vector<Encoded> encodings(const MeshData& m) {
  std::vector<Encoded> out;
  out.push_back(
      {"ascii stl", meshbytes::written([&](std::FILE* f) { writeStl(f, m, true); }), true});
  out.push_back({"binary stl", meshbytes::written([&](std::FILE* f) { writeStl(f, m); }), true});
  // assembled by hand, the header starting with "solid" as some exporters write it
  out.push_back({"binary stl 'solid' header",
                 meshbytes::binaryStl(meshbytes::facetsOf(m), "solid made by hand"), true});
  const std::pair<PlyEncoding, const char*> plys[] = {
      {PlyEncoding::Ascii, "ascii"},
      {PlyEncoding::BinaryLittleEndian, "little-endian"},
      {PlyEncoding::BinaryBigEndian, "big-endian"}};
  for (const auto& [enc, name] : plys)
    for (bool f32 : {false, true})
      out.push_back({std::string("ply ") + name + (f32 ? " float" : " double"),
                     meshbytes::written([&](std::FILE* f) { writePly(f, m, enc, f32); }), false});
  return out;
}

// every encoding of `mesh` (float-exact) gives the polyhedron of its OFF
void everyEncodingAgrees(const MeshData& mesh) {
  const std::string off = meshbytes::written([&](std::FILE* f) { writeOff(f, mesh); });
  const ConvexPolyhedron want(parseMesh(MeshFormat::Off, off));
  const std::vector<Vec3> queries = queriesFor(want);
  for (const Encoded& e : encodings(mesh)) {
    SCOPED_TRACE(e.name);
    const MeshData fromMemory =
        e.stl ? parseMesh(MeshFormat::Stl, e.bytes) : parseMesh(MeshFormat::Ply, e.bytes);
    const MeshData fromFile =
        e.stl ? meshbytes::throughFile(e.bytes,
                                       [](std::FILE* f) { return parseMesh(MeshFormat::Stl, f); })
              : meshbytes::throughFile(e.bytes,
                                       [](std::FILE* f) { return parseMesh(MeshFormat::Ply, f); });
    EXPECT_EQ(fromMemory.vertices, fromFile.vertices);
    EXPECT_EQ(fromMemory.indices, fromFile.indices);
    expectSame(want, fromMemory, queries);
  }
}

}  // namespace

TEST(StlPly, CubeInEveryEncoding) {
  everyEncodingAgrees(shapes3d::cube());
}

TEST(StlPly, IcosahedronInEveryEncoding) {
  everyEncodingAgrees(meshbytes::toFloats(generatePolyhedron(PolyhedronKind::Icosahedron, 20, 1)));
}

TEST(StlPly, GeodesicSphereInEveryEncoding) {
  everyEncodingAgrees(meshbytes::toFloats(generatePolyhedron(PolyhedronKind::Geodesic, 1280, 1)));
}

TEST(StlPly, DoublesSurviveAsciiStlAndDoublePly) {
  // the icosahedron's golden ratio is no float: text and double properties keep every bit
  const MeshData m = generatePolyhedron(PolyhedronKind::Icosahedron, 20, 1);
  const ConvexPolyhedron want(m);
  const std::vector<Vec3> queries = queriesFor(want);
  expectSame(
      want,
      parseMesh(MeshFormat::Stl, meshbytes::written([&](std::FILE* f) { writeStl(f, m, true); })),
      queries);
  for (PlyEncoding enc :
       {PlyEncoding::Ascii, PlyEncoding::BinaryLittleEndian, PlyEncoding::BinaryBigEndian})
    expectSame(
        want,
        parseMesh(MeshFormat::Ply, meshbytes::written([&](std::FILE* f) { writePly(f, m, enc); })),
        queries);
  // and the float formats refuse to round them
  EXPECT_THROW(meshbytes::written([&](std::FILE* f) { writeStl(f, m); }), Error);
  EXPECT_THROW(meshbytes::written([&](std::FILE* f) { writePly(f, m, PlyEncoding::Ascii, true); }),
               Error);
}

TEST(StlPly, BinaryStlWeldsExactlyEqualCorners) {
  // two facets share an edge; -0 and +0 are the same corner; 1 + 2^-23 is not 1
  const float next = 1.0f + 0x1p-23f;
  const std::string bytes = meshbytes::binaryStl({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}},
                                                  {{1, 0, 0}, {-0.0, 0, 0}, {0, 0, 1}},
                                                  {{next, 0, 0}, {0, 1, 0}, {0, 0, 1}}});
  const MeshData m = parseMesh(MeshFormat::Stl, bytes);
  ASSERT_EQ(m.vertices.size(), 5u);
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 1, 2, 1, 0, 3, 4, 2, 3}));
  EXPECT_EQ(m.vertices[4].x, static_cast<double>(next));
  EXPECT_TRUE(m.vertexLines.empty());
  EXPECT_TRUE(m.faceLines.empty());
}

TEST(StlPly, AsciiStlByHand) {
  const std::string text =
      "solid part one\r\n"
      "  facet normal 0 0 -1\r\n    outer loop\r\n      vertex 0 0 0\r\n      vertex 0 1 0\r\n"
      "      vertex 1 0 0\r\n    endloop\r\n  endfacet\r\n"
      "endsolid part one\r\n"
      "solid two\n facet normal nan nan nan\n outer loop\n vertex 0 0 0\n vertex 1 0 0\n"
      " vertex 0 0 1\n endloop\n endfacet\n"
      " facet normal 1e0 0 0\n outer loop\n vertex 0 0 0\n vertex 0 0 1\n vertex 0 1 0\n endloop\n"
      " endfacet\n facet normal 1 1 1\n outer loop\n vertex 1 0 0\n vertex 0 1 0\n vertex 0 0 1\n"
      " endloop\n endfacet\nendsolid\n";
  const MeshData m = parseMesh(MeshFormat::Stl, text);
  ASSERT_EQ(m.faceCount(), 4u);
  EXPECT_EQ(m.vertices.size(), 4u);
  EXPECT_EQ(m.faceLines, (std::vector<std::size_t>{2, 11, 18, 25}));
  EXPECT_EQ(m.vertexLines, (std::vector<std::size_t>{4, 5, 6, 15}));
  const ConvexPolyhedron p(m);
  EXPECT_EQ(p.triangles().size(), 4u);
  EXPECT_FALSE(p.wasInverted());
}

TEST(StlPly, BigEndianPlyByHandWithPropertiesToSkip) {
  // a tetrahedron; vertices carry a colour and a list; an element before the faces is skipped;
  // the faces carry a flag after their list, counted by a ushort with uint indices
  meshbytes::Bytes b;
  b.big = true;
  b.text(
      "ply\nformat binary_big_endian 1.0\ncomment by hand\nobj_info nothing\n"
      "element vertex 4\nproperty uchar red\nproperty double x\nproperty list uchar short tags\n"
      "property float y\nproperty int z\n"
      "element edge 2\nproperty int a\nproperty int b\n"
      "element face 4\nproperty list ushort uint vertex_indices\nproperty char flag\nend_header\n");
  const double xs[] = {0, 1, 0, 0}, ys[] = {0, 0, 1, 0};
  const int zs[] = {0, 0, 0, 1};
  for (int i = 0; i < 4; ++i) {
    b.uint(200, 1).f64(xs[i]).uint(static_cast<std::uint64_t>(i), 1);
    for (int t = 0; t < i; ++t) b.uint(0xfffe, 2);
    b.f32(static_cast<float>(ys[i])).uint(static_cast<std::uint32_t>(zs[i]), 4);
  }
  b.uint(0, 4).uint(1, 4).uint(1, 4).uint(2, 4);
  const unsigned faces[4][3] = {{0, 2, 1}, {0, 1, 3}, {0, 3, 2}, {1, 2, 3}};
  for (const auto& f : faces) b.uint(3, 2).uint(f[0], 4).uint(f[1], 4).uint(f[2], 4).uint(0xff, 1);
  const MeshData m = parseMesh(MeshFormat::Ply, b.s);
  ASSERT_EQ(m.vertices.size(), 4u);
  EXPECT_EQ(m.vertices[3].z, 1.0);
  EXPECT_EQ(m.vertices[1].x, 1.0);
  EXPECT_EQ(m.indices, (std::vector<std::uint32_t>{0, 2, 1, 0, 1, 3, 0, 3, 2, 1, 2, 3}));
  EXPECT_EQ(ConvexPolyhedron(m).triangles().size(), 4u);
}

TEST(StlPly, AsciiPlyByHand) {
  const std::string text =
      "ply\r\nformat ascii 1.0\r\ncomment hi\r\nelement vertex 4\r\nproperty int x\r\n"
      "property float y\r\nproperty double z\r\nproperty list uchar float n\r\n"
      "element face 4\r\nproperty list uchar int vertex_index\r\nend_header\r\n"
      "0 0 0 0\r\n1 0 0 2 0.5 -1e3\r\n0 1 0 1 7\r\n0 0 1e0 0\r\n"
      "3 0 2 1\r\n3 0 1 3\r\n3 0 3 2\r\n3 1 2 3\r\n\r\n";
  const MeshData m = parseMesh(MeshFormat::Ply, text);
  EXPECT_EQ(m.vertexLines, (std::vector<std::size_t>{12, 13, 14, 15}));
  EXPECT_EQ(m.faceLines, (std::vector<std::size_t>{16, 17, 18, 19}));
  EXPECT_EQ(ConvexPolyhedron(m).triangles().size(), 4u);
}

TEST(StlPly, PointCloudReadsAsVerticesAndTakesTheHull) {
  const MeshData sphere = meshbytes::toFloats(generatePolyhedron(PolyhedronKind::Geodesic, 320, 1));
  MeshData cloud;
  cloud.vertices = sphere.vertices;
  cloud.vertices.push_back({0, 0, 0});  // an inner point the hull drops
  const std::filesystem::path dir =
      std::filesystem::temp_directory_path() / ("convexloc_cloud_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  const std::string path = (dir / "cloud.PLY").string();
  {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    ASSERT_NE(f, nullptr);
    writePly(f, cloud, PlyEncoding::BinaryLittleEndian, true);
    std::fclose(f);
  }
  const MeshData read = readMesh(path);
  EXPECT_EQ(read.vertices, cloud.vertices);
  EXPECT_EQ(read.faceCount(), 0u);
  try {
    loadPolyhedron(path);
    ADD_FAILURE() << "a point cloud was taken for a polyhedron";
  } catch (const GeometryError& e) {
    EXPECT_THAT(e.what(), HasSubstr("no faces"));
    EXPECT_THAT(e.what(), HasSubstr("--hull"));
  }
  const ConvexPolyhedron hull = loadHull(path);
  EXPECT_EQ(surfaceOf(hull), surfaceOf(ConvexPolyhedron(sphere)));
  std::filesystem::remove_all(dir);
}

TEST(StlPly, FormatsByExtension) {
  EXPECT_EQ(meshFormatOf("a/b.STL"), MeshFormat::Stl);
  EXPECT_EQ(meshFormatOf("b.stl"), MeshFormat::Stl);
  EXPECT_EQ(meshFormatOf("scan.Ply"), MeshFormat::Ply);
  EXPECT_FALSE(meshFormatOf("b.3mf").has_value());
  EXPECT_FALSE(meshFormatOf("ply").has_value());
}

TEST(StlPly, TheExampleFilesInAssets) {
  const std::string assets = CONVEXLOC_ASSETS;
  const ConvexPolyhedron cylinder = loadPolyhedron(assets + "/cylinder-64.stl");
  EXPECT_EQ(cylinder.triangles().size(), 4u * 64 - 4);
  EXPECT_EQ(readMesh(assets + "/cube.ply").faceCount(), 6u);
  const MeshData cloud = readMesh(assets + "/sphere-cloud.ply");
  EXPECT_EQ(cloud.faceCount(), 0u);
  EXPECT_GT(loadHull(assets + "/sphere-cloud.ply").triangles().size(), 100u);
}
