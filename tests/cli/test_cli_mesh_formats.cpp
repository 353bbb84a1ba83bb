// The convexloc tool on STL and PLY files and with --hull: every command reads the shipped
// .stl and .ply files and the formats `generate` writes with the same answers as the OFF of
// the same shape; a point cloud needs --hull and says so; --hull takes the convex hull of any
// shape file's points (polygon or polyhedron) in classify, info and intersect.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

#include "cli_run.hpp"

namespace {

using namespace cli_test;

const char* const kMethods3D[] = {"halfspace", "walk", "cubemap"};

class CliFormats : public Cli {
 protected:
  // `classify SHAPE POINTS -m METHOD [extra]`: its stdout, checked to succeed
  std::string classify(const std::string& shape, const std::string& points, const char* method,
                       const std::string& extra = "") {
    const std::string args = "classify " + q(shape) + " " + q(points) + " -m " + method +
                             (extra.empty() ? "" : " " + extra);
    const Result r = run(args);
    EXPECT_EQ(r.code, 0) << args << "\n" << r.err;
    EXPECT_EQ(r.err, "");
    return r.out;
  }
};

TEST_F(CliFormats, GeneratedPlyAndStlClassifyAsTheOff) {
  for (const char* kind : {"icosahedron", "geodesic", "cube-hull"}) {
    SCOPED_TRACE(kind);
    const std::string gen = std::string("generate polyhedron --kind ") + kind + " --n 500 --seed 3";
    const std::string off = runTo(gen, "shape.off");
    const std::string ply = runTo(gen + " --format ply", "shape.ply");
    const std::string stl = runTo(gen + " --format stl", "shape.STL");
    const std::string points = runTo(
        "generate points --near-boundary --count 3000 --seed 4 --shape " + q(off), "points.txt");
    for (const char* m : kMethods3D) {
      const std::string want = classify(off, points, m);
      EXPECT_EQ(classify(ply, points, m), want) << m;
      EXPECT_EQ(classify(stl, points, m), want) << m;
      // the hull of a convex polyhedron's vertices is the polyhedron
      EXPECT_EQ(classify(ply, points, m, "--hull"), want) << m;
    }
  }
}

TEST_F(CliFormats, ShippedStlAndPlyFilesWork) {
  const std::string cylinder = kAssets + "/cylinder-64.stl";
  Result info = run("info " + q(cylinder));
  EXPECT_EQ(info.code, 0) << info.err;
  EXPECT_NE(info.out.find("128 kept of 128 read"), std::string::npos) << info.out;
  const std::string points = runTo(
      "generate points --near-boundary --count 2000 --seed 9 --shape " + q(cylinder), "p.txt");
  const std::string want = classify(cylinder, points, "halfspace");
  EXPECT_EQ(classify(cylinder, points, "cubemap"), want);
  EXPECT_EQ(classify(cylinder, points, "walk", "--hull"), want);
  // the PLY cube and the OFF cube
  const std::string cubePoints = kAssets + "/cube-points-3d.txt";
  EXPECT_EQ(classify(kAssets + "/cube.ply", cubePoints, "cubemap"),
            classify(kAssets + "/cube.off", cubePoints, "cubemap"));
}

TEST_F(CliFormats, APointCloudNeedsHull) {
  const std::string cloud = kAssets + "/sphere-cloud.ply";
  for (const std::string& cmd :
       {"info " + q(cloud), "classify " + q(cloud) + " " + q(kAssets + "/cube-points-3d.txt"),
        "intersect " + q(cloud) + " /dev/null"}) {
    SCOPED_TRACE(cmd);
    expectRejected(run(cmd), cloud + ": the mesh has no faces, only 800 vertices");
    expectRejected(run(cmd), "--hull");
  }
  Result info = run("info " + q(cloud) + " --hull");
  EXPECT_EQ(info.code, 0) << info.err;
  EXPECT_NE(info.out.find("600 kept of 800 read"), std::string::npos) << info.out;
  // the 200 inner points are inside their hull, the 600 on the sphere on its boundary
  std::ofstream(scratch("origin.txt")) << "0 0 0\n2 0 0\n";
  EXPECT_EQ(classify(cloud, scratch("origin.txt"), "cubemap", "--hull"), "inside\noutside\n");
  // a plane through the centre crosses it; one beyond the sphere misses it
  std::ofstream(scratch("planes.txt")) << "0 0 0 1 0 0 0 1 0\n0 0 5 1 0 5 0 1 5\n";
  Result planes = run("intersect " + q(cloud) + " " + q(scratch("planes.txt")) + " --hull");
  EXPECT_EQ(planes.code, 0) << planes.err;
  EXPECT_EQ(planes.out, "crosses\nmisses\n");
}

TEST_F(CliFormats, HullOfPolygonPointsInAnyOrder) {
  // a square's corners in a crossing order, and points inside it and on its edges
  std::ofstream(scratch("cloud.txt")) << "0 0\n1 1\n1 0\n0 1\n0.5 0.5\n0.25 0.75\n";
  std::ofstream(scratch("pts.txt")) << "0.5 0.5\n1 0.5\n2 2\n";
  expectRejected(run("classify " + q(scratch("cloud.txt")) + " " + q(scratch("pts.txt"))), "");
  Result r = run("classify " + q(scratch("cloud.txt")) + " " + q(scratch("pts.txt")) + " --hull");
  EXPECT_EQ(r.code, 0) << r.err;
  EXPECT_EQ(r.out, "inside\nboundary\noutside\n");
  std::ofstream(scratch("lines.txt")) << "0 2 1 2\n0 0.5 1 0.5\n";
  Result l =
      run("intersect " + q(scratch("cloud.txt")) + " " + q(scratch("lines.txt")) + " --hull");
  EXPECT_EQ(l.code, 0) << l.err;
  EXPECT_EQ(l.out, "misses\ncrosses\n");
  Result info = run("info " + q(scratch("cloud.txt")) + " --hull");
  EXPECT_EQ(info.code, 0) << info.err;
}

TEST_F(CliFormats, AnXyzScanIsAPointCloudForHull) {
  // the corners of [0, 2]^3 and points on its faces and edges, with intensity and colour
  std::ofstream(scratch("scan.xyz")) << "0 0 0 9 1 2 3\n2 0 0 9 1 2 3\n0 2 0 9 1 2 3\n"
                                        "2 2 0 9 1 2 3\n0 0 2 9 1 2 3\n2 0 2 9 1 2 3\n"
                                        "0 2 2 9 1 2 3\n2 2 2 9 1 2 3\n1 1 2 9 1 2 3\n"
                                        "1 0 0 9 1 2 3\n2 1 1 9 1 2 3\n";
  std::ofstream(scratch("probe.txt")) << "1 1 1\n1 1 2\n3 1 1\n";
  const std::string args = "classify " + q(scratch("scan.xyz")) + " " + q(scratch("probe.txt"));
  expectRejected(run(args), "--hull");
  const Result hull = run(args + " --hull");
  EXPECT_EQ(hull.code, 0) << hull.err;
  EXPECT_EQ(hull.out, "inside\nboundary\noutside\n");
  const Result info = run("info " + q(scratch("scan.xyz")) + " --hull");
  EXPECT_EQ(info.code, 0) << info.err;
  EXPECT_NE(info.out.find("vertices          8 kept of 11 read"), std::string::npos) << info.out;
  EXPECT_NE(info.out.find("6 plane faces"), std::string::npos) << info.out;
  std::ofstream(scratch("short.pts")) << "3\n0 0 0 7\n1 0 0 7\n";
  expectRejected(run("info " + q(scratch("short.pts")) + " --hull"),
                 scratch("short.pts") + ":1: the point count on this line says 3");
}

TEST_F(CliFormats, ARoundedCubeIsRefusedWithAHintAndReadWithHull) {
  // a cube turned about (1, 2, 3), its coordinates printed to 7 digits: the squares are no
  // longer exactly planar
  const double c = std::cos(0.7), s = std::sin(0.7), n = std::sqrt(14.0);
  const double u[3] = {1 / n, 2 / n, 3 / n};
  std::string off = "OFF\n8 6 0\n";
  for (int i = 0; i < 8; ++i) {
    const double p[3] = {i & 4 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 1 ? 1.0 : -1.0};
    const double d = u[0] * p[0] + u[1] * p[1] + u[2] * p[2];
    const double x[3] = {u[1] * p[2] - u[2] * p[1], u[2] * p[0] - u[0] * p[2],
                         u[0] * p[1] - u[1] * p[0]};
    for (int k = 0; k < 3; ++k) {
      char buf[32];
      std::snprintf(buf, sizeof buf, "%.7g ", p[k] * c + x[k] * s + u[k] * d * (1 - c));
      off += buf;
    }
    off += "\n";
  }
  off += "4 0 1 3 2\n4 4 6 7 5\n4 0 4 5 1\n4 2 3 7 6\n4 0 2 6 4\n4 1 5 7 3\n";
  std::ofstream(scratch("rounded.off")) << off;
  std::ofstream(scratch("centre.txt")) << "0 0 0\n3 0 0\n";
  const std::string args = "classify " + q(scratch("rounded.off")) + " " + q(scratch("centre.txt"));
  const Result plain = run(args);
  expectRejected(plain, "is not planar");
  expectRejected(plain, "off the plane");
  expectRejected(plain, "--hull");
  const Result hull = run(args + " --hull");
  EXPECT_EQ(hull.code, 0) << hull.err;
  EXPECT_EQ(hull.out, "inside\noutside\n");
}

TEST_F(CliFormats, BadStlAndPlyNameTheLineOrTheByte) {
  std::ofstream(scratch("bad.stl"), std::ios::binary)
      << "solid x\nfacet normal 0 0 1\nvertex 0 0 0\n";
  expectRejected(run("info " + q(scratch("bad.stl"))),
                 scratch("bad.stl") + ":3: expected 'outer loop'");
  std::string binary(80, ' ');
  binary += std::string("\x05\x00\x00\x00", 4);
  std::ofstream(scratch("short.stl"), std::ios::binary) << binary;
  expectRejected(run("info " + q(scratch("short.stl"))),
                 scratch("short.stl") + ": byte 80: the header announces 5 facets");
  std::ofstream(scratch("bad.ply"), std::ios::binary)
      << "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n";
  expectRejected(run("info " + q(scratch("bad.ply"))),
                 scratch("bad.ply") + ":3: element 'vertex' has no property 'y'");
  expectRejected(run("info " + q(scratch("bad.ply")) + " --hull"), "no property 'y'");
}

}  // namespace
