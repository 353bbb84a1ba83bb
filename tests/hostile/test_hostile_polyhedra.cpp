// Extreme polyhedra located with every 3D method against the exact reference, in the core
// and through the real convexloc: near the largest double (every difference overflows),
// subnormal, far from the origin, and with coordinates 10^300 apart in scale.
#include <gtest/gtest.h>

#include <array>
#include <charconv>
#include <cmath>
#include <limits>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "check3d.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/polyhedron.hpp"
#include "fuzz_support.hpp"
#include "tool.hpp"

namespace {

using convexloc::ConvexPolyhedron;
using convexloc::MeshData;
using convexloc::Vec3;

constexpr double kMax = std::numeric_limits<double>::max();
constexpr double kTiny = std::numeric_limits<double>::denorm_min();

// === Extreme polyhedra, every method against the exact reference

// Validates `mesh`, then checks the polyhedron and every method (two cubemap resolutions)
// at `extra` points plus the vertices, edges, faces and their one-ulp neighbours.
void checkEveryMethod(const MeshData& mesh, std::vector<Vec3> extra) {
  ConvexPolyhedron poly(mesh);
  fuzz::checkPolyhedron(poly);
  fuzz::addHardPoints3d(extra, poly);
  for (std::uint32_t resolution : {0u, 1u, 64u}) fuzz::checkMethods3d(poly, extra, resolution);
}

// the tetrahedron on alternate corners of the box [-s, s]^3, moved by `at`
MeshData tetrahedron(double s, Vec3 at = {}) {
  MeshData m;
  for (Vec3 p : {Vec3{s, s, s}, Vec3{s, -s, -s}, Vec3{-s, s, -s}, Vec3{-s, -s, s}})
    m.addVertex({at.x + p.x, at.y + p.y, at.z + p.z});
  for (auto f : {std::array<std::uint32_t, 3>{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}})
    m.addFace(std::span<const std::uint32_t>(f));
  return m;
}

// n random points spread over exponents lo..hi, either sign
std::vector<Vec3> spread(std::size_t n, int lo, int hi, std::uint64_t seed) {
  convexloc::Rng rng(seed);
  auto one = [&] {
    double v =
        std::ldexp(1 + rng.uniform(),
                   lo + static_cast<int>(rng.below(static_cast<std::uint64_t>(hi - lo + 1))));
    return rng.below(2) ? -v : v;
  };
  std::vector<Vec3> out;
  for (std::size_t i = 0; i < n; ++i) out.push_back({one(), one(), one()});
  return out;
}

TEST(HostileMesh, ExtremePolyhedraAreExactWithEveryMethod) {
  const std::size_t n = hostile::scaled(2000, 300);
  // near the largest double: every difference overflows
  checkEveryMethod(tetrahedron(kMax), spread(n, 1000, 1023, 1));
  // subnormal: the tetrahedron 2 ulps of zero across
  checkEveryMethod(tetrahedron(kTiny), spread(n, -1074, -1070, 2));
  // a unit tetrahedron far out at 1e300
  checkEveryMethod(tetrahedron(1e290, {1e300, -1e300, 1e300}), spread(n, 960, 1000, 3));
  // scales 10^300 apart: a double cone with a 1e150 base and a 1e-150 apex height
  MeshData cone;
  for (Vec3 p : {Vec3{-1e150, -1e-150, 0}, Vec3{1e150, -1e-150, 0}, Vec3{0, 1e150, 0},
                 Vec3{0, 0, 1e-150}, Vec3{0, 0, -1e150}})
    cone.addVertex(p);
  for (auto f : {std::array<std::uint32_t, 3>{0, 1, 3},
                 {1, 2, 3},
                 {2, 0, 3},
                 {0, 2, 4},
                 {2, 1, 4},
                 {1, 0, 4}})
    cone.addFace(std::span<const std::uint32_t>(f));
  checkEveryMethod(cone, spread(n, -500, 500, 4));
  // a box 1e-150 thick and 2e150 wide
  MeshData slab;
  for (int i = 0; i < 8; ++i)
    slab.addVertex({i & 1 ? 1e150 : -1e150, i & 2 ? 1e150 : -1e150, i & 4 ? 1e-150 : 0});
  for (auto f : {std::array<std::uint32_t, 4>{0, 2, 3, 1},
                 {4, 5, 7, 6},
                 {0, 1, 5, 4},
                 {2, 6, 7, 3},
                 {0, 4, 6, 2},
                 {1, 3, 7, 5}})
    slab.addFace(std::span<const std::uint32_t>(f));
  checkEveryMethod(slab, spread(n, -520, 520, 5));
}

// Regression (found by the differential fuzz target): an axis-aligned box 1.8e308 long,
// 7e160 wide and 2.8e169 high was rejected as "not convex: the surface winds 2 times":
// validation summed solid angles at one common scale, where the thin directions vanish in
// rounding. Each axis now gets its own scale (the winding number does not change).
TEST(HostileMesh, ABoxThinAlongTwoAxesIsValid) {
  const Vec3 lo{-0x1.facb0a22f1ddep-895, 0x1.1350f2e09f903p-303, -0x1.d5d0f5712f61bp+562};
  const Vec3 hi{0x1.fffffffffc7f2p+1023, 0x1.4aa3bb13f1a94p+534, -0x1.e9901p-817};
  MeshData box;
  for (int i = 0; i < 8; ++i)
    box.addVertex({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
  for (auto f : {std::array<std::uint32_t, 4>{0, 2, 3, 1},
                 {4, 5, 7, 6},
                 {0, 1, 5, 4},
                 {2, 6, 7, 3},
                 {0, 4, 6, 2},
                 {1, 3, 7, 5}})
    box.addFace(std::span<const std::uint32_t>(f));
  checkEveryMethod(box, {{1e300, 1e150, -1e160}, {1e300, 1e161, -1e160}, {-1, 1e150, -1e160}});
}

// the same kinds of polyhedra through the real convexloc, from OFF files
TEST(HostileCli3D, ExtremeCoordinatesEveryMethod) {
  using hostile::runTool;
  using hostile::TempDir;
  using hostile::ToolRun;
  using hostile::writeFile;
  const char* const kMethods3D[] = {"halfspace", "walk", "cubemap"};
  auto text = [](double v) {
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return std::string(buf, end);
  };
  struct Case {
    const char* name;
    std::vector<Vec3> v;  // a tetrahedron, in either orientation
  };
  auto corners = [](double s, Vec3 at) {
    std::vector<Vec3> out;
    for (Vec3 p : {Vec3{1, 1, 1}, Vec3{1, -1, -1}, Vec3{-1, 1, -1}, Vec3{-1, -1, 1}})
      out.push_back({at.x + s * p.x, at.y + s * p.y, at.z + s * p.z});
    return out;
  };
  const Case cases[] = {
      {"near the largest double", corners(kMax, {})},
      {"subnormal", corners(2 * kTiny, {})},
      {"1e290 wide at 1e300", corners(1e290, {1e300, 1e300, -1e300})},
      {"scales 10^300 apart",
       {{1e150, 1e-150, 0}, {-1e150, 1e-150, 0}, {0, -1e-150, 1e-150}, {0, 1e-150, -1e150}}}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.name);
    TempDir dir;
    const std::vector<Vec3>& v = c.v;
    std::string off = "OFF\n4 4 0\n";
    for (Vec3 p : v) off += text(p.x) + " " + text(p.y) + " " + text(p.z) + "\n";
    off += "3 0 1 2\n3 0 2 3\n3 0 3 1\n3 1 3 2\n";
    writeFile(dir.file("t.off"), off);
    // the vertices, their neighbours, edge midpoints, the centroid, and some far points
    std::vector<Vec3> q;
    for (std::size_t i = 0; i < 4; ++i) {
      q.push_back(v[i]);
      fuzz::addNeighbours3d(q, v[i]);
      for (std::size_t j = i + 1; j < 4; ++j)
        q.push_back({v[i].x / 2 + v[j].x / 2, v[i].y / 2 + v[j].y / 2, v[i].z / 2 + v[j].z / 2});
    }
    q.push_back({v[0].x / 4 + v[1].x / 4 + v[2].x / 4 + v[3].x / 4,
                 v[0].y / 4 + v[1].y / 4 + v[2].y / 4 + v[3].y / 4,
                 v[0].z / 4 + v[1].z / 4 + v[2].z / 4 + v[3].z / 4});
    q.push_back({0, 0, 0});
    q.push_back({kMax, -kMax, kMax});
    std::string points;
    for (Vec3 p : q) points += text(p.x) + " " + text(p.y) + " " + text(p.z) + "\n";
    writeFile(dir.file("q.txt"), points);
    // the reference: the tetrahedron's own faces, oriented by the sign at its centroid
    std::vector<std::array<std::uint32_t, 3>> faces = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
    if (fuzz::exactOrient3d(v[0], v[1], v[2], v[3]) < 0)
      for (auto& f : faces) std::swap(f[1], f[2]);
    std::string want;
    for (Vec3 p : q)
      want += std::string(
                  convexloc::toString(fuzz::exactLocate3d(std::span<const Vec3>(v), faces, p))) +
              "\n";
    for (const char* m : kMethods3D) {
      ToolRun r = runTool({"classify", dir.file("t.off"), dir.file("q.txt"), "--method", m});
      EXPECT_EQ(r.status, 0) << m << ": " << r.err;
      EXPECT_EQ(r.out, want) << m;
    }
  }
}

}  // namespace
