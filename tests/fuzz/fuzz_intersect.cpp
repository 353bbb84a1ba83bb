// Fuzz target: lines against polygons and planes against polyhedra, every method against an
// exact reference; and the LINES reader (4 or 9 numbers per row) on arbitrary text.
//
// Byte 0: the high bit picks 3D, the next bit the reader, the rest the coordinate encoding
// (fuzz_support.hpp). 2D: up to 24 points whose strictly convex hull is the polygon, then
// lines through pairs of the following points, of vertices, and of their one-ulp
// neighbours; each method's crossing, entry and exit must match the reference from every
// vertex's exact side, and its clip the exact Cyrus-Beck clip rounded to nearest. 3D: the exact
// hull of up to 12 points, planes through triples; both methods must match every vertex's
// exact side.
#include <gmpxx.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/intersect2d.hpp"
#include "convexloc/intersect3d.hpp"
#include "convexloc/polygon.hpp"
#include "convexloc/polyhedron.hpp"
#include "convexloc/text_reader.hpp"
#include "fuzz_support.hpp"
#include "reference_lines2d.hpp"

namespace {

using namespace fuzz;
using convexloc::BoundaryHit;
using convexloc::Crossing;
using convexloc::LineHit;
using convexloc::Segment2D;
using ref::referenceClip;
using ref::referenceHit;

void intersect2D(ByteSource& src, Encoding encoding) {
  const std::size_t count = 3 + src.byte() % 22;
  CoordinateReader coords(src, encoding);
  std::vector<Vec2> input;
  for (std::size_t i = 0; i < count; ++i) input.push_back(coords.point());
  const std::vector<Vec2> hull = convexloc::convexHull(input);
  if (hull.size() < 3) return;
  const convexloc::ConvexPolygon polygon(hull);
  const std::vector<Vec2> v(polygon.vertices().begin(), polygon.vertices().end());
  std::vector<Vec2> points;
  while (!src.empty() && points.size() < 24) points.push_back(coords.point());
  for (std::size_t i = 0; i < v.size() && i < 8; ++i) addNeighbours(points, v[i]);
  std::vector<convexloc::LineIntersector> methods;
  for (convexloc::LineMethod m : convexloc::kAllLineMethods) methods.emplace_back(polygon, m);
  std::vector<Vec2> lines;  // the batch: every line tried, against the reference's crossings
  std::vector<Crossing> wants;
  for (std::size_t i = 0; i + 1 < points.size() && i < 40; ++i) {
    const Vec2 p1 = points[i], p2 = points[(i * 7 + 3) % points.size()];
    if (p1 == p2) continue;
    const LineHit want = referenceHit(v, p1, p2);
    lines.insert(lines.end(), {p1, p2});
    wants.push_back(want.crossing);
    const std::optional<Segment2D> clip = referenceClip(v, p1, p2);
    for (const convexloc::LineIntersector& li : methods) {
      const std::string where = std::string(toString(li.method())) + " " + show(p1) + show(p2);
      if (li.classify(p1, p2) != want.crossing) fail("crossing differs: " + where);
      if (!(li.intersect(p1, p2) == want)) fail("entry or exit differs: " + where);
      const std::optional<Segment2D> got = li.clip(p1, p2);
      if (got.has_value() != clip.has_value() || (got && !(*got == *clip)))
        fail("clip differs: " + where);
    }
  }
  for (const convexloc::LineIntersector& li : methods) {
    std::vector<Crossing> got(wants.size());
    li.classify(std::span<const Vec2>(lines), std::span<Crossing>(got));
    if (got != wants) fail("batch crossing differs: " + std::string(toString(li.method())));
  }
}

void intersect3D(ByteSource& src, Encoding encoding) {
  const std::size_t count = 4 + src.byte() % 9;
  CoordinateReader coords(src, encoding);
  std::vector<Vec3> input;
  for (std::size_t i = 0; i < count; ++i) input.push_back(coords.point3());
  std::optional<convexloc::ConvexPolyhedron> p;
  try {
    p.emplace(convexloc::ConvexPolyhedron::hullOf(input));
  } catch (const convexloc::GeometryError&) {
    return;
  }
  const auto v = p->vertices();
  std::vector<Vec3> points;
  while (!src.empty() && points.size() < 24) points.push_back(coords.point3());
  points.insert(points.end(), v.begin(), v.end());
  const convexloc::PlaneIntersector vertices(*p, convexloc::PlaneMethod::Vertices);
  const convexloc::PlaneIntersector dual(*p, convexloc::PlaneMethod::Dual);
  std::vector<Vec3> planes;  // the batch: every plane tried, against the exact crossings
  std::vector<Crossing> wants;
  for (std::size_t i = 0; i < points.size() && i < 40; ++i) {
    const Vec3 a = points[i], b = points[(i * 5 + 1) % points.size()],
               c = points[(i * 11 + 2) % points.size()];
    if (convexloc::collinear(a, b, c)) continue;
    bool above = false, below = false, on = false;
    for (const Vec3 w : v) {
      const int s = exactOrient3d(a, b, c, w);
      above |= s > 0, below |= s < 0, on |= s == 0;
    }
    const Crossing want = above && below ? Crossing::Crosses
                                         : (on ? Crossing::Touches : Crossing::Misses);
    if (vertices.classify(a, b, c) != want || dual.classify(a, b, c) != want)
      fail("plane crossing differs: " + show(a) + show(b) + show(c));
    planes.insert(planes.end(), {a, b, c});
    wants.push_back(want);
  }
  for (const convexloc::PlaneIntersector* pi : {&vertices, &dual}) {
    std::vector<Crossing> got(wants.size());
    pi->classify(std::span<const Vec3>(planes), std::span<Crossing>(got));
    if (got != wants) fail("batch plane crossing differs: " + std::string(toString(pi->method())));
  }
}

// the LINES reader: rows of 4 or 9 numbers, every one finite, lines numbered upwards
void readLines(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return;
  const int numbers = (data[0] & 1) ? 9 : 4;
  MemFile file(data + 1, size - 1);
  convexloc::RowReader reader(file.get(), numbers);
  double row[9];
  std::size_t last = 0;
  try {
    while (reader.next(row)) {
      for (int k = 0; k < numbers; ++k)
        if (!std::isfinite(row[k])) fail("a row holds a number that is not finite");
      if (reader.line() <= last) fail("row line numbers do not increase");
      last = reader.line();
    }
  } catch (const convexloc::ParseError& e) {
    if (e.line() <= last) fail("ParseError names a line before the last row");
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ByteSource src(data, size);
  const std::uint8_t head = src.byte();
  if (head & 0x40) {
    if (size > 0) readLines(data + 1, size - 1);
    return 0;
  }
  const Encoding encoding = static_cast<Encoding>((head & 0x3f) % kEncodings);
  if (head & 0x80)
    intersect3D(src, encoding);
  else
    intersect2D(src, encoding);
  return 0;
}
