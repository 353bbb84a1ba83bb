// The convexloc tool on polyhedra (.off / .obj), as a user runs it: the 3D half of every
// command on the files in tests/data, bad meshes and bad usage, and the shipped polyhedra.
#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>
#include <vector>

#include "cli_run.hpp"

namespace {

using namespace cli_test;

const char* const kMethods3D[] = {"halfspace", "walk", "cubemap"};
const char* const kKinds3D[] = {"tetrahedron",    "cube",      "octahedron",  "dodecahedron",
                                "icosahedron",    "geodesic",  "sphere-hull", "cube-hull",
                                "ellipsoid-hull", "thin-slab", "offset",      "tiny-faces",
                                "coplanar"};

// the vertices of an OFF file as convexloc writes it ("OFF", "V F 0", V vertex lines, ...),
// one 'x y z' per line
std::string offVertices(const std::string& off) {
  auto lines = linesOf(off);
  if (lines.size() < 2 || lines[0] != "OFF") return "";
  const std::size_t count = std::stoul(lines[1]);
  std::string out;
  for (std::size_t i = 0; i < count && 2 + i < lines.size(); ++i) out += lines[2 + i] + "\n";
  return out;
}

// the vertices of an OBJ file, one 'x y z' per line
std::string objVertices(const std::string& obj) {
  std::string out;
  for (const std::string& line : linesOf(obj))
    if (line.rfind("v ", 0) == 0) out += line.substr(2) + "\n";
  return out;
}

TEST_F(Cli, Classify3dKnownAnswersEveryMethod) {
  const std::string expected = slurp(kData + "/cube3d_expected.txt");
  for (const char* m : kMethods3D) {
    Result r =
        run("classify " + data("cube3d.off") + " " + data("cube3d_points.txt") + " --method " + m);
    EXPECT_EQ(r.code, 0) << m << ": " << r.err;
    EXPECT_EQ(r.out, expected) << "method " << m;
    EXPECT_EQ(r.err, "");
  }
}

TEST_F(Cli, Classify3dExpectedFileCoversEveryAnswer) {
  // the reference answers for the cube [0, 4]^3, by the line numbers of cube3d_points.txt
  auto lines = linesOf(slurp(kData + "/cube3d_expected.txt"));
  ASSERT_EQ(lines.size(), 27u);
  EXPECT_EQ(lines[0], "inside");    // centre
  EXPECT_EQ(lines[2], "boundary");  // vertex (0, 0, 0)
  EXPECT_EQ(lines[5], "boundary");  // edge midpoint (2, 0, 0)
  EXPECT_EQ(lines[8], "boundary");  // face centre (2, 2, 0)
  EXPECT_EQ(lines[12], "outside");  // one ulp outside the face x = 4
  EXPECT_EQ(lines[13], "inside");   // one ulp inside it
  EXPECT_EQ(lines[14], "outside");  // the smallest double below the face y = 0
  EXPECT_EQ(lines[15], "inside");   // the smallest double above it
  EXPECT_EQ(lines[16], "outside");  // one ulp off a vertex
  EXPECT_EQ(lines[19], "outside");  // on a face's plane, past its edge
  EXPECT_EQ(lines[22], "outside");  // far, on the diagonal
}

TEST_F(Cli, Classify3dDefaultMethodIsCubemap) {
  Result a = run("classify " + data("cube3d.off") + " " + data("cube3d_points.txt"));
  Result b =
      run("classify " + data("cube3d.off") + " " + data("cube3d_points.txt") + " -m cubemap");
  EXPECT_EQ(a.code, 0) << a.err;
  EXPECT_EQ(a.out, b.out);
  EXPECT_EQ(a.out, slurp(kData + "/cube3d_expected.txt"));
}

TEST_F(Cli, Classify3dResolutionDoesNotChangeAnswers) {
  const std::string expected = slurp(kData + "/cube3d_expected.txt");
  // 8192, the largest, is coarsened to fit the memory budget; halfspace and walk ignore it
  for (const char* res : {"1", "2", "3", "7", "64", "8192"}) {
    Result r = run("classify " + data("cube3d.off") + " " + data("cube3d_points.txt") +
                   " -m cubemap --resolution " + res);
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out, expected) << "cubemap at resolution " << res;
  }
  for (const char* m : {"halfspace", "walk"}) {
    Result r = run("classify " + data("cube3d.off") + " " + data("cube3d_points.txt") + " -m " + m +
                   " -r 5");
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out, expected) << m;
  }
}

TEST_F(Cli, Classify3dObjSyntaxAndClockwiseCrlfGiveSameAnswers) {
  // f i/t/n, i//n, i/t, negative indices, repeated and unused vertices, CRLF; and an OFF
  // file oriented clockwise throughout, CRLF, without a final newline
  const std::string expected = slurp(kData + "/cube3d_expected.txt");
  for (const char* shape : {"cube3d_obj_syntax_crlf.obj", "cube3d_clockwise_crlf.off"}) {
    for (const char* m : kMethods3D) {
      Result r = run("classify " + data(shape) + " " + data("cube3d_points.txt") + " -m " + m);
      EXPECT_EQ(r.code, 0) << shape << ": " << r.err;
      EXPECT_EQ(r.out, expected) << shape << " with " << m;
    }
  }
}

TEST_F(Cli, Classify3dReadsStandardInputRedirectedAndPiped) {
  const std::string expected = slurp(kData + "/cube3d_expected.txt");
  Result redirected = run("classify " + data("cube3d.off") + " - < " + data("cube3d_points.txt"));
  EXPECT_EQ(redirected.code, 0) << redirected.err;
  EXPECT_EQ(redirected.out, expected);
  Result piped = run("classify " + data("cube3d.off") + " -", "cat " + data("cube3d_points.txt"));
  EXPECT_EQ(piped.code, 0) << piped.err;
  EXPECT_EQ(piped.out, expected);
  Result empty = run("classify " + data("cube3d.off") + " " + data("points_empty.txt"));
  EXPECT_EQ(empty.code, 0) << empty.err;
  EXPECT_EQ(empty.out, "");
}

TEST_F(Cli, Classify3dThinnestTetrahedronWithoutCentre) {
  // no double lies strictly inside: walk and cubemap test every face, and stay exact
  const std::string expected = slurp(kData + "/tetra3d_thinnest_expected.txt");
  for (const char* m : kMethods3D) {
    Result r = run("classify " + data("tetra3d_thinnest.off") + " " +
                   data("tetra3d_thinnest_points.txt") + " -m " + m);
    EXPECT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out, expected) << m;
  }
  Result info = run("info " + data("tetra3d_thinnest.off") + " -m cubemap");
  ASSERT_EQ(info.code, 0) << info.err;
  EXPECT_NE(info.out.find("centre            none"), std::string::npos) << info.out;
}

TEST_F(Cli, Classify3dRejectsBadMeshes) {
  const Rejection cases[] = {
      {"mesh3d_open.off",
       "mesh3d_open.off:13: the surface is open: edge 5-4 from (4, 0, 4) to (0, 0, 4) belongs to "
       "face 1 only"},
      {"mesh3d_nonmanifold.off",
       "mesh3d_nonmanifold.off:15: not a manifold: edge 1-0 from (1, 0, 0) to (0, 0, 0) is shared "
       "by 4 triangles"},
      {"mesh3d_mixed_orientation.off",
       "mesh3d_mixed_orientation.off:14: inconsistent orientation: face 1 and face 2"},
      {"mesh3d_reflex.off",
       "mesh3d_reflex.off:19: not convex: reflex edge 5-8 from (4, 0, 4) to (2, 2, 3)"},
      {"mesh3d_flat.off", "mesh3d_flat.off: zero volume: all 3 vertices are coplanar"},
      {"mesh3d_two_pieces.off", "mesh3d_two_pieces.off:15: the surface has 2 separate pieces"},
      {"mesh3d_index_out_of_range.off",
       "mesh3d_index_out_of_range.off:13: vertex index 8 is out of range: the file has 8 vertices"},
      {"mesh3d_negative_out_of_range.obj",
       "mesh3d_negative_out_of_range.obj:7: vertex reference -5 points before the first vertex"},
      {"mesh3d_zero_index.obj",
       "mesh3d_zero_index.obj:7: vertex reference 0: OBJ numbers vertices from 1"},
      {"mesh3d_nan.off", "mesh3d_nan.off:5: not a number: 'nan'"},
      {"mesh3d_inf.obj", "mesh3d_inf.obj:4: not a number: '-inf'"},
      {"mesh3d_huge_header.off",
       "mesh3d_huge_header.off:3: the OFF header announces 1000000000000 faces; at most"},
      {"mesh3d_garbage.off", "mesh3d_garbage.off:9: a face starts with its vertex count"},
      {"mesh3d_garbage.obj", "mesh3d_garbage.obj: the mesh has no faces"},
      {"mesh3d_bad_face.obj", "mesh3d_bad_face.obj:8: not a vertex reference: 'two'"},
      {"mesh3d_bad_vertex.obj", "mesh3d_bad_vertex.obj:3: not a number: 'zero'"},
      {"mesh3d_short_vertex.obj", "mesh3d_short_vertex.obj:3: a vertex needs 3 coordinates"},
      {"mesh3d_face_too_short.off",
       "mesh3d_face_too_short.off:9: a face needs at least 3 vertices, this one has 2"},
      {"mesh3d_trailing_text.off",
       "mesh3d_trailing_text.off:11: unexpected text after the last face"},
      {"mesh3d_no_faces.off", "mesh3d_no_faces.off:5: the mesh has no faces"},
      {"mesh3d_empty.off", "mesh3d_empty.off:1: empty OFF file"},
      {"no_such_mesh3d.obj", "no_such_mesh3d.obj: cannot open: No such file or directory"},
  };
  for (const Rejection& c : cases) {
    SCOPED_TRACE(c.file);
    for (const char* m : kMethods3D)
      expectRejected(run("classify " + data(c.file) + " " + data("cube3d_points.txt") + " -m " + m),
                     c.message);
    expectRejected(run("info " + data(c.file)), c.message);
    expectRejected(run("generate points --shape " + data(c.file) + " --count 10"), c.message);
  }
}

TEST_F(Cli, Classify3dRejectsADirectoryNamedLikeAMesh) {
  const std::string dir = scratch("folder.off");
  fs::create_directory(dir);
  expectRejected(run("classify " + q(dir) + " " + data("cube3d_points.txt")),
                 "folder.off: cannot open: it is a directory");
  expectRejected(run("classify " + data("cube3d.off") + " " + q(kData)),
                 "cannot open: it is a directory");
}

TEST_F(Cli, Classify3dRejectsBadPoints) {
  const Rejection cases[] = {
      {"points3d_bad_line_late.txt",
       "points3d_bad_line_late.txt:5002: unexpected text after 3 numbers: 'oops'"},
      {"points3d_two_numbers.txt", "points3d_two_numbers.txt:3: expected 3 numbers, found 2"},
      {"points3d_four_numbers.txt", "points3d_four_numbers.txt:2: expected 3 numbers, found more"},
      {"points3d_nan.txt", "points3d_nan.txt:2: not a number: 'nan'"},
      {"polygon_garbage.txt", "polygon_garbage.txt:1: not a number"},
  };
  for (const Rejection& c : cases) {
    SCOPED_TRACE(c.file);
    for (const char* m : kMethods3D)
      expectRejected(run("classify " + data("cube3d.off") + " " + data(c.file) + " -m " + m),
                     c.message);
  }
}

TEST_F(Cli, Classify3dBadLineLateOnStandardInputWritesNothing) {
  expectRejected(
      run("classify " + data("cube3d.off") + " -", "cat " + data("points3d_bad_line_late.txt")),
      "<stdin>:5002: unexpected text after 3 numbers");
  expectRejected(
      run("classify " + data("cube3d.off") + " - < " + data("points3d_bad_line_late.txt")),
      "<stdin>:5002: unexpected text after 3 numbers");
}

TEST_F(Cli, Classify3dBadLineAfterMegabytesOfAnswersWritesNothing) {
  const std::string shape = data("cube3d.off");
  const std::string points =
      runTo("generate points --shape " + shape + " --count 300000 --seed 5", "many3d.txt");
  std::ofstream(points, std::ios::app) << "1 2\n";
  expectRejected(run("classify " + shape + " " + q(points)),
                 "many3d.txt:300002: expected 3 numbers, found 2");
  expectRejected(run("classify " + shape + " -", "cat " + q(points)),
                 "<stdin>:300002: expected 3 numbers, found 2");
}

TEST_F(Cli, BadUsage3dExitsTwoWithUsage) {
  const std::string shape = data("cube3d.off"), points = data("cube3d_points.txt");
  // a polygon's method for a polyhedron, and the other way round, name the right choices
  for (const char* m : {"halfplane", "wedge", "slab", "uniform", "polar"}) {
    expectUsage(
        run("classify " + shape + " " + points + " --method " + m),
        std::string("method '") + m +
            "' is for polygons; for a polyhedron (.off/.obj/.stl/.ply) choose one of halfspace, "
            "walk, cubemap");
    expectUsage(run("info " + shape + " -m " + m), "is for polygons");
  }
  for (const char* m : kMethods3D) {
    expectUsage(
        run("classify " + data("hexagon.txt") + " " + data("hexagon_points.txt") + " -m " + m),
        std::string("method '") + m +
            "' is for polyhedra (.off/.obj/.stl/.ply); for a polygon choose one of halfplane, "
            "wedge, slab, uniform, polar");
    expectUsage(run("info " + data("hexagon.txt") + " -m " + m), "is for polyhedra");
  }
  expectUsage(run("classify " + shape + " " + points + " --method octree"),
              "unknown method 'octree' for a polyhedron; choose one of halfspace, walk, cubemap");
  expectUsage(run("classify " + shape + " " + points + " --resolution 8193"), "at most 8192");
  expectUsage(run("classify " + shape + " " + points + " --resolution -1"), "--resolution");
  expectUsage(run("info " + shape + " --resolution 100000"), "at most 8192");
  expectUsage(run("info " + shape + " -m cubemap -r 100000"), "at most 8192");
  expectUsage(run("generate polyhedron"), "--kind is required");
  expectUsage(run("generate polyhedron --kind blob"),
              "unknown polyhedron kind 'blob'; choose one of tetrahedron, cube");
  expectUsage(run("generate polyhedron --kind geodesic --n 3"), "at least 4");
  expectUsage(run("generate polyhedron --kind geodesic --n 100000000"), "at most 2^24");
  expectUsage(run("generate polyhedron --kind sphere-hull --n 10000000"), "at most 2^22");
  expectUsage(run("generate polyhedron --kind cube --n -5"), "--n");
  expectUsage(run("generate polyhedron --kind cube --format 3mf"),
              "unknown format '3mf'; choose off, obj, ply or stl");
  expectUsage(run("generate points --shape " + shape + " --count -1"), "--count");
}

// the value after `label` on the line of a report that starts with it ("  label  value")
std::string reportValue(const std::string& report, const std::string& label) {
  for (const std::string& line : linesOf(report)) {
    if (line.rfind("  " + label + " ", 0) != 0) continue;
    std::size_t at = line.find_first_not_of(' ', label.size() + 2);
    return at == std::string::npos ? "" : line.substr(at);
  }
  return "";
}

TEST_F(Cli, Info3dTableShowsEveryMethodAndThePolyhedron) {
  Result r = run("info " + data("cube3d.off"));
  ASSERT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.err, "");
  EXPECT_EQ(r.out.rfind("Shape " + kData + "/cube3d.off\n\nPolyhedron\n", 0), 0u) << r.out;
  EXPECT_EQ(reportValue(r.out, "vertices"), "8 kept of 8 read");
  EXPECT_EQ(reportValue(r.out, "faces"),
            "6 read, 12 triangles, 6 plane faces (coplanar triangles merged)");
  EXPECT_EQ(reportValue(r.out, "orientation"), "counter-clockwise seen from outside, as given");
  EXPECT_EQ(reportValue(r.out, "bounding box"), "x 0 .. 4,  y 0 .. 4,  z 0 .. 4");
  EXPECT_EQ(reportValue(r.out, "volume"), "64");
  EXPECT_EQ(reportValue(r.out, "area"), "96");
  for (const char* m : kMethods3D)
    EXPECT_NE(r.out.find(std::string("\n  ") + m + " "), std::string::npos) << m;
  for (const char* key :
       {"O(F)", "O(sqrt F)", "O(1)", "cells", "entries", "bytes/face", "build", "--method cubemap"})
    EXPECT_NE(r.out.find(key), std::string::npos) << key << " in\n" << r.out;
  EXPECT_EQ(r.out.find("edges"), std::string::npos) << "a polyhedron's report counts faces";
}

TEST_F(Cli, Info3dOneMethodInDetail) {
  Result c = run("info " + data("cube3d.off") + " --method cubemap --resolution 3");
  ASSERT_EQ(c.code, 0) << c.err;
  EXPECT_NE(c.out.find("Method cubemap\n"), std::string::npos) << c.out;
  EXPECT_EQ(reportValue(c.out, "centre"), "(2, 2, 2)");
  EXPECT_EQ(reportValue(c.out, "grid"), "3 x 3 per cube face (54 base cells)");
  EXPECT_EQ(reportValue(c.out.substr(c.out.find("Method")), "faces"), "6 (12 triangles)");
  for (const char* key : {"quadtree", "cells", "entries", "faces per cell    max", "crowded cells",
                          "memory", "bytes per face", "build time", "faces per cell    cells"})
    EXPECT_NE(c.out.find(key), std::string::npos) << key << " in\n" << c.out;
  // the histogram counts every cell once
  std::size_t total = 0;
  bool inHistogram = false;
  for (const std::string& line : linesOf(c.out)) {
    if (line == "  faces per cell    cells") {
      inHistogram = true;
      continue;
    }
    if (!inHistogram) continue;
    std::istringstream in(line);
    std::string bucket;
    std::size_t count = 0;
    if (in >> bucket >> count) total += count;
  }
  EXPECT_EQ(std::to_string(total), reportValue(c.out, "cells")) << c.out;

  Result w = run("info " + data("cube3d.off") + " -m walk");
  ASSERT_EQ(w.code, 0) << w.err;
  EXPECT_EQ(reportValue(w.out, "centre"), "(2, 2, 2)");
  EXPECT_EQ(reportValue(w.out, "cells"), "none: this method keeps no table of cells");
  Result h = run("info " + data("cube3d.off") + " -m halfspace");
  ASSERT_EQ(h.code, 0) << h.err;
  EXPECT_EQ(reportValue(h.out, "cells"), "none: this method keeps no table of cells");
  EXPECT_NE(h.out.find("bytes per face"), std::string::npos);
}

TEST_F(Cli, Info3dSaysWhatValidationChanged) {
  Result obj = run("info " + data("cube3d_obj_syntax_crlf.obj"));
  ASSERT_EQ(obj.code, 0) << obj.err;
  EXPECT_EQ(reportValue(obj.out, "vertices"), "8 kept of 11 read");
  EXPECT_EQ(reportValue(obj.out, "dropped"),
            "2 equal to an earlier one (merged), 1 used by no face");
  EXPECT_EQ(reportValue(obj.out, "faces"),
            "12 read, 12 triangles, 6 plane faces (coplanar triangles merged)");
  Result cw = run("info " + data("cube3d_clockwise_crlf.off") + " -m halfspace");
  ASSERT_EQ(cw.code, 0) << cw.err;
  EXPECT_EQ(reportValue(cw.out, "orientation"),
            "clockwise seen from outside in the file (reversed)");
  EXPECT_EQ(reportValue(cw.out, "volume"), "64");
}

// the "bytes/face" column of a 3D info table, one value per method
std::vector<double> bytesPerFace(const std::string& table) {
  std::vector<double> out;
  for (const std::string& line : linesOf(table)) {
    std::istringstream in(line);
    std::string method;
    in >> method;
    bool known = false;
    for (const char* m : kMethods3D) known = known || method == m;
    if (!known) continue;
    // method query cells entries max mean crowded bytes bytes/face build unit
    std::vector<std::string> f;
    for (std::string w; in >> w;) f.push_back(w);
    if (f.size() >= 9) out.push_back(std::stod(f[f.size() - 3]));
  }
  return out;
}

TEST_F(Cli, Info3dAtMost128BytesPerFace) {
  // the tiny-faces preset (face areas differ by more than 10^10) and a geodesic sphere of
  // 10^6 faces, both made by the tool itself
  const std::pair<const char*, const char*> shapes[] = {{"tiny-faces", "64"},
                                                        {"tiny-faces", "1000"},
                                                        {"tiny-faces", "50000"},
                                                        {"geodesic", "1000000"}};
  for (const auto& [kind, n] : shapes) {
    SCOPED_TRACE(std::string(kind) + " " + n);
    const std::string shape = runTo("generate polyhedron --kind " + std::string(kind) + " --n " + n,
                                    std::string(kind) + "-" + n + ".off");
    Result r = run("info " + q(shape));
    ASSERT_EQ(r.code, 0) << r.err;
    auto b = bytesPerFace(r.out);
    ASSERT_EQ(b.size(), 3u) << r.out;
    // 128 bytes per triangle plus 32 KiB, the bound README gives; per triangle alone from
    // 10^4 triangles (below, a locator keeping triangles beside merged faces may use the 32 KiB)
    const double faces = std::stod(n) < 10000 ? std::stod(n) : 0.0;
    for (double v : b) EXPECT_LE(v, faces > 0 ? 128.0 + 32768.0 / faces : 128.0) << r.out;
  }
}

TEST_F(Cli, GeneratedPolyhedronVerticesAreAllBoundary) {
  for (const char* kind : kKinds3D) {
    SCOPED_TRACE(kind);
    for (const char* format : {"off", "obj"}) {
      const std::string ext = std::string(".") + format;
      const std::string shape = runTo(std::string("generate polyhedron --kind ") + kind +
                                          " --n 200 --seed 3 --format " + format,
                                      "shape" + ext);
      const std::string text = slurp(shape);
      const std::string vertices =
          std::string(format) == "off" ? offVertices(text) : objVertices(text);
      std::ofstream(scratch("vertices.txt"), std::ios::binary) << vertices;
      const std::size_t count = linesOf(vertices).size();
      ASSERT_GE(count, 4u) << text.substr(0, 200);
      for (const char* m : kMethods3D) {
        Result r = run("classify " + q(shape) + " " + q(scratch("vertices.txt")) + " -m " + m);
        ASSERT_EQ(r.code, 0) << format << " " << m << ": " << r.err;
        auto answers = linesOf(r.out);
        ASSERT_EQ(answers.size(), count) << m;
        for (const auto& a : answers) EXPECT_EQ(a, "boundary") << format << " " << m;
      }
    }
  }
}

TEST_F(Cli, GeneratePolyhedronIsDeterministic) {
  Result a = run("generate polyhedron --kind sphere-hull --n 300 --seed 9");
  Result b = run("generate polyhedron --kind sphere-hull --n 300 --seed 9");
  Result c = run("generate polyhedron --kind sphere-hull --n 300 --seed 10");
  Result o = run("generate polyhedron --kind sphere-hull --n 300 --seed 9 --format obj");
  ASSERT_EQ(a.code, 0) << a.err;
  EXPECT_EQ(a.out.rfind("OFF\n", 0), 0u) << "OFF is the default format";
  EXPECT_EQ(a.out, b.out);
  EXPECT_NE(a.out, c.out);
  EXPECT_EQ(offVertices(a.out), objVertices(o.out)) << "OFF and OBJ hold the same vertices";
  Result d = run("generate polyhedron --kind dodecahedron");
  ASSERT_EQ(d.code, 0) << d.err;
  EXPECT_EQ(linesOf(offVertices(d.out)).size(), 20u);
}

TEST_F(Cli, GeneratePoints3dCountAndDeterminism) {
  const std::string shape = data("cube3d.off");
  for (const char* count : {"0", "1", "1000", "70000"}) {
    Result r = run("generate points --shape " + shape + " --count " + count + " --seed 4");
    ASSERT_EQ(r.code, 0) << r.err;
    auto lines = dataLines(r.out);
    EXPECT_EQ(lines.size(), std::stoul(count));
    for (const auto& l : lines) {
      std::istringstream in(l);
      double x = 0, y = 0, z = 0;
      ASSERT_TRUE(in >> x >> y >> z) << l;
      // uniform points lie in the bounding box grown by 10%
      for (double v : {x, y, z}) {
        EXPECT_GE(v, -0.4);
        EXPECT_LE(v, 4.4);
      }
    }
  }
  Result a = run("generate points --shape " + shape + " --count 500 --seed 4 --near-boundary");
  Result b = run("generate points --shape " + shape + " --count 500 --seed 4 --near-boundary");
  Result c = run("generate points --shape " + shape + " --count 500 --seed 5 --near-boundary");
  EXPECT_EQ(a.out, b.out);
  EXPECT_NE(dataLines(a.out), dataLines(c.out));
}

TEST_F(Cli, Generated3dPointsClassifyAlikeWithEveryMethod) {
  for (const char* kind : {"sphere-hull", "thin-slab", "offset", "tiny-faces", "coplanar"}) {
    SCOPED_TRACE(kind);
    const std::string shape = runTo(
        std::string("generate polyhedron --kind ") + kind + " --n 2000 --seed 2", "shape.off");
    const std::string points =
        runTo("generate points --shape " + q(shape) + " --count 20000 --seed 8 --near-boundary",
              "points.txt");
    std::string first;
    for (const char* m : kMethods3D) {
      Result r = run("classify " + q(shape) + " " + q(points) + " -m " + m);
      ASSERT_EQ(r.code, 0) << r.err;
      EXPECT_EQ(linesOf(r.out).size(), 20000u);
      if (first.empty())
        first = r.out;
      else
        EXPECT_EQ(r.out, first) << m << " disagrees with halfspace";
    }
    for (const char* a : {"inside\n", "boundary\n", "outside\n"})
      EXPECT_NE(first.find(a), std::string::npos) << a;
  }
}

TEST_F(Cli, Classify3dStreamsAPipeOfManyPoints) {
  const std::string shape = data("cube3d.off");
  Result r = run("classify " + shape + " -",
                 q(kBin) + " generate points --shape " + shape + " --count 250000 --seed 1");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(linesOf(r.out).size(), 250000u);
}

// === the shipped polyhedra

TEST_F(Cli, ShippedPolyhedraWork) {
  for (const char* m : kMethods3D) {
    Result r = run("classify " + q(kAssets + "/cube.off") + " " +
                   q(kAssets + "/cube-points-3d.txt") + " -m " + m);
    ASSERT_EQ(r.code, 0) << r.err;
    EXPECT_EQ(r.out,
              "inside\ninside\nboundary\nboundary\nboundary\nboundary\noutside\ninside\n"
              "outside\noutside\n")
        << m;
  }
  for (const char* f : {"cube.off", "icosahedron.obj"}) {
    Result i = run("info " + q(kAssets + "/" + f));
    EXPECT_EQ(i.code, 0) << f << ": " << i.err;
  }
  // the icosahedron's own vertices are on its surface
  const std::string vertices = objVertices(slurp(kAssets + "/icosahedron.obj"));
  std::ofstream(scratch("ico.txt"), std::ios::binary) << vertices;
  Result r = run("classify " + q(kAssets + "/icosahedron.obj") + " " + q(scratch("ico.txt")));
  ASSERT_EQ(r.code, 0) << r.err;
  for (const auto& a : linesOf(r.out)) EXPECT_EQ(a, "boundary");
  EXPECT_EQ(linesOf(r.out).size(), 12u);
}

}  // namespace
