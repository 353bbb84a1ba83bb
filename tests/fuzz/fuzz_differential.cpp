// Fuzz target: small shapes from the fuzzer's bytes, every method against an exact reference.
//
// Byte 0 picks the dimension (high bit: 3D) and the coordinate encoding (see
// fuzz_support.hpp), byte 1 the grid resolution and how the shape is made (2D: the points as
// given or their convexHull; 3D: core's exact hullOf, its exact smallHull, or the box of two
// points), byte 2 the point count; the next bytes are the points, the rest query points. The
// queries also include every vertex, every edge midpoint and the one-ulp neighbours of both. A
// shape core rejects is fine; a shape it accepts must be exactly what it promises, and every method
// must give the exact answer for every query.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "check2d.hpp"
#include "check3d.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/generate3d.hpp"
#include "fuzz_support.hpp"

namespace {

using namespace fuzz;

// 2D: a polygon from up to 32 vertices, queried at up to 64 points plus the hard ones
void differential2D(ByteSource& src, Encoding encoding) {
  const std::uint8_t config = src.byte();
  const std::uint32_t resolution = resolutionFrom(config & 7);
  const bool hull = (config & 8) != 0;
  const std::size_t count = 3 + src.byte() % 30;
  CoordinateReader coords(src, encoding);
  std::vector<Vec2> input;
  for (std::size_t i = 0; i < count; ++i) input.push_back(coords.point());
  if (hull) {
    std::vector<Vec2> h = convexloc::convexHull(input);
    if (h.size() < 3) return;
    input = std::move(h);
  }
  std::vector<ConvexPolygon> poly;
  try {
    poly.emplace_back(input);
  } catch (const convexloc::GeometryError&) {
    if (hull) fail("the strictly convex hull of the input was rejected as a polygon");
    return;
  }
  checkPolygon(poly.front(), input);
  std::vector<Vec2> queries;
  while (!src.empty() && queries.size() < 64) queries.push_back(coords.point());
  addHardPoints(queries, poly.front().vertices());
  checkMethods(poly.front(), queries, resolution);
}

// true when every point lies on one plane (or fewer than 4 are distinct), exactly
bool coplanar(const std::vector<Vec3>& p) {
  for (std::size_t i = 1; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j)
      for (std::size_t k = j + 1; k < p.size(); ++k)
        if (exactOrient3d(p[0], p[i], p[j], p[k]) != 0) return false;
  return true;
}

// the box spanned by two corners, as 6 quadrilaterals counter-clockwise from outside
convexloc::MeshData box(Vec3 a, Vec3 b) {
  Vec3 lo{std::min(a.x, b.x), std::min(a.y, b.y), std::min(a.z, b.z)};
  Vec3 hi{std::max(a.x, b.x), std::max(a.y, b.y), std::max(a.z, b.z)};
  convexloc::MeshData m;
  for (int i = 0; i < 8; ++i)
    m.addVertex({i & 1 ? hi.x : lo.x, i & 2 ? hi.y : lo.y, i & 4 ? hi.z : lo.z});
  for (auto f : {std::array<std::uint32_t, 4>{0, 2, 3, 1},
                 {4, 5, 7, 6},
                 {0, 1, 5, 4},
                 {2, 6, 7, 3},
                 {0, 4, 6, 2},
                 {1, 3, 7, 5}})
    m.addFace(std::span<const std::uint32_t>(f));
  return m;
}

// 3D: a polyhedron from up to 16 points (core's exact hull, its exact small hull, or the box
// of two of them), queried at up to 48 points plus the hard ones; the hull must hold every
// point it was made from
void differential3D(ByteSource& src, Encoding encoding) {
  const std::uint8_t config = src.byte();
  const std::uint32_t resolution = resolution3dFrom(config & 7);
  const int mode = (config >> 3) % 3;
  const std::size_t count = 4 + src.byte() % 13;
  CoordinateReader coords(src, encoding);
  std::vector<Vec3> input;
  for (std::size_t i = 0; i < count; ++i) input.push_back(coords.point3());
  std::optional<ConvexPolyhedron> poly;
  try {
    if (mode == 0) {
      poly.emplace(ConvexPolyhedron::hullOf(input));
    } else if (mode == 1) {
      convexloc::MeshData mesh = convexloc::smallHull(input);
      if (mesh.faceCount() == 0) return;
      poly.emplace(mesh);
    } else {
      poly.emplace(box(input[0], input[1]));
    }
  } catch (const convexloc::GeometryError& e) {
    // the exact hull exists whenever the points are not all on one plane, at any magnitude
    // (tests/data/fuzz/differential/hull_at_1e154_winds_once: a needle from 1e-222 to 1e154)
    if (mode == 0 && !coplanar(input))
      fail(std::string("hullOf rejected points that are not coplanar: ") + e.what());
    // a box is a valid polyhedron unless it is flat
    if (mode == 2 && input[0].x != input[1].x && input[0].y != input[1].y &&
        input[0].z != input[1].z)
      fail(std::string("a box with volume was rejected: ") + e.what());
    return;
  }
  checkPolyhedron(*poly);
  if (mode == 0) {
    const auto v = poly->vertices();
    for (const auto& t : poly->triangles())
      for (const Vec3& p : input)
        if (exactOrient3d(v[t[0]], v[t[1]], v[t[2]], p) < 0)
          fail("an input point " + show(p) + " lies outside its hull");
  }
  std::vector<Vec3> queries;
  while (!src.empty() && queries.size() < 48) queries.push_back(coords.point3());
  addHardPoints3d(queries, *poly);
  checkMethods3d(*poly, queries, resolution);
}

}  // namespace

// CONVEXLOC_FUZZ_DIMENSION=2 or 3 keeps a campaign to one dimension (default: both)
int onlyDimension() {
  const char* env = std::getenv("CONVEXLOC_FUZZ_DIMENSION");
  return env ? std::atoi(env) : 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const int only = onlyDimension();
  ByteSource src(data, size);
  const std::uint8_t head = src.byte();
  const Encoding encoding = static_cast<Encoding>((head & 0x7f) % kEncodings);
  if ((only == 2 && (head & 0x80)) || (only == 3 && !(head & 0x80))) return 0;
  if (head & 0x80)
    differential3D(src, encoding);
  else
    differential2D(src, encoding);
  return 0;
}
