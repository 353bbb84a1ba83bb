// Fuzz target: small shapes from the fuzzer's bytes, every method against an exact reference.
//
// Byte 0 picks the dimension and the coordinate encoding (see fuzz_support.hpp), byte 1 the
// grid resolution and whether the vertices go through convexHull first (so that most inputs
// make a valid shape), byte 2 the vertex count; the next bytes are the vertices, the rest
// query points. The queries also include every vertex, every edge midpoint and the one-ulp
// neighbours of both. A shape core rejects is fine; a shape it accepts must be exactly what
// it promises, and every method must give the exact answer for every query.
#include <cstddef>
#include <cstdint>
#include <vector>

#include "check2d.hpp"
#include "convexloc/generate2d.hpp"
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

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ByteSource src(data, size);
  const std::uint8_t head = src.byte();
  const Encoding encoding = static_cast<Encoding>((head & 0x7f) % kEncodings);
  differential2D(src, encoding);
  return 0;
}
