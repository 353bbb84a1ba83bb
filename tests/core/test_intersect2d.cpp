// Line against polygon: every method against an exact rational reference on the shape
// matrix (tests/core/shapes.hpp), with random and adversarial lines, and clipping against
// the exact intersection rounded to the nearest double.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "convexloc/generate2d.hpp"
#include "convexloc/intersect2d.hpp"
#include "convexloc/locate2d.hpp"
#include "convexloc/polygon.hpp"
#include "reference_lines2d.hpp"
#include "scale.hpp"
#include "shapes2d.hpp"

namespace {

using ref::nearest;
using ref::referenceClip;
using ref::referenceHit;
using ref::side;

using convexloc::BoundaryHit;
using convexloc::ConvexPolygon;
using convexloc::Crossing;
using convexloc::LineHit;
using convexloc::LineIntersector;
using convexloc::LineMethod;
using convexloc::Segment2D;
using convexloc::Vec2;

// === Lines: random and adversarial

std::string show(Vec2 p) {
  char buf[128];
  std::snprintf(buf, sizeof buf, "(%a, %a)", p.x, p.y);
  return buf;
}

// the lines to try on a ring: random ones through the enlarged box, and ones through
// vertices, along edges, one ulp off them, near-parallel to edges, through the middle
std::vector<std::pair<Vec2, Vec2>> linesFor(const std::vector<Vec2>& ring, std::size_t randomCount,
                                            std::uint64_t seed) {
  convexloc::Rng rng(seed);
  const std::size_t n = ring.size();
  double x0 = ring[0].x, x1 = x0, y0 = ring[0].y, y1 = y0;
  for (Vec2 v : ring)
    x0 = std::min(x0, v.x), x1 = std::max(x1, v.x), y0 = std::min(y0, v.y), y1 = std::max(y1, v.y);
  const double wx = (x1 - x0) * 0.2, wy = (y1 - y0) * 0.2;
  auto randomPoint = [&] {
    return Vec2{rng.uniform(x0 - wx, x1 + wx), rng.uniform(y0 - wy, y1 + wy)};
  };
  auto ulp = [](Vec2 p, int dx, int dy) {
    const double inf = std::numeric_limits<double>::infinity();
    return Vec2{dx ? std::nextafter(p.x, dx * inf) : p.x, dy ? std::nextafter(p.y, dy * inf) : p.y};
  };
  const Vec2 middle{x0 * 0.5 + x1 * 0.5, y0 * 0.5 + y1 * 0.5};
  std::vector<std::pair<Vec2, Vec2>> out;
  auto add = [&](Vec2 a, Vec2 b) {
    if (!(a == b) && std::isfinite(a.x) && std::isfinite(a.y) && std::isfinite(b.x) &&
        std::isfinite(b.y)) {
      out.push_back({a, b});
      out.push_back({b, a});
    }
  };
  for (std::size_t k = 0; k < randomCount; ++k) add(randomPoint(), randomPoint());
  const std::size_t step = std::max<std::size_t>(1, n / 32);
  for (std::size_t i = 0; i < n; i += step) {
    const Vec2 v = ring[i], w = ring[(i + 1) % n], u = ring[(i + n - 1) % n];
    add(v, w);                                       // along an edge
    add(v, ring[(i + n / 2) % n]);                   // through two vertices
    add(v, randomPoint());                           // through a vertex
    add(v, middle);                                  // through the middle
    add({v.x + (w.x - u.x), v.y + (w.y - u.y)}, v);  // near the tangent at a vertex
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy) {
        add(ulp(v, dx, dy), w);                 // one ulp off a vertex, towards the next
        add(ulp(v, dx, dy), ulp(w, -dx, -dy));  // one ulp off an edge
      }
    const double shift = (rng.uniform() - 0.5) * (std::fabs(v.x - w.x) + std::fabs(v.y - w.y));
    add({v.x + shift, v.y}, {w.x + shift, w.y});  // near-parallel to an edge
    add({v.x, v.y - shift}, {w.x, w.y - shift});
  }
  return out;
}

// === The tests

class Intersect2DExact : public testing::TestWithParam<std::size_t> {};

TEST_P(Intersect2DExact, EveryMethodMatchesTheReference) {
  const shapes::ShapeCase& sc = shapes::cases()[GetParam()];
  const ConvexPolygon polygon(sc.input);
  const std::vector<Vec2> ring(polygon.vertices().begin(), polygon.vertices().end());
  const LineIntersector vertices(polygon, LineMethod::Vertices);
  const LineIntersector bisection(polygon, LineMethod::Bisection);
  const LineIntersector dual(polygon, LineMethod::Dual);
  // random lines scaled under the sanitizers (scale.hpp); the adversarial ones all kept
  const auto lines =
      linesFor(ring, testscale::scaled(ring.size() > 1000 ? 100 : 400, 40), GetParam() + 1);
  std::size_t clipped = 0, index = 0;
  // the batch of every method, in one call (blocks, prefetching, a partial last block)
  std::vector<Vec2> flat;
  for (const auto& [p1, p2] : lines) flat.insert(flat.end(), {p1, p2});
  std::vector<std::vector<Crossing>> batches;
  for (const LineIntersector* li : {&vertices, &bisection, &dual}) {
    batches.emplace_back(lines.size());
    li->classify(std::span(flat), std::span(batches.back()));
  }
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const auto& [p1, p2] = lines[k];
    const LineHit want = referenceHit(ring, p1, p2);
    for (const std::vector<Crossing>& b : batches)
      ASSERT_EQ(b[k], want.crossing) << "batch line " << show(p1) << show(p2);
    // the rational clip costs O(N) rationals: every line of a small polygon, some of a large
    const bool checkClip = ring.size() <= 300 || index++ % 16 == 0;
    const std::optional<Segment2D> wantClip =
        checkClip ? referenceClip(ring, p1, p2) : std::nullopt;
    for (const LineIntersector* li : {&vertices, &bisection, &dual}) {
      const std::string where =
          std::string(convexloc::toString(li->method())) + " line " + show(p1) + " -> " + show(p2);
      ASSERT_EQ(li->classify(p1, p2), want.crossing) << where;
      ASSERT_EQ(li->intersect(p1, p2), want) << where;
      ASSERT_EQ(li->trace(p1, p2).crossing, want.crossing) << where;
      const std::optional<Segment2D> got = li->clip(p1, p2);
      if (!checkClip) continue;
      ASSERT_EQ(got.has_value(), wantClip.has_value()) << where;
      if (got) {
        ASSERT_EQ(got->a, wantClip->a) << where;
        ASSERT_EQ(got->b, wantClip->b) << where;
        ++clipped;
      }
    }
  }
  EXPECT_GT(clipped, 0u);
}

INSTANTIATE_TEST_SUITE_P(Shapes, Intersect2DExact, testing::ValuesIn(shapes::caseIndices()),
                         shapes::CaseName());

// the regular 2^16-gon: the dual's proposal is the extreme vertex or next to it
TEST(Intersect2DDual, RegularLargeClimbsLittle) {
  const ConvexPolygon polygon(shapes::regular(1 << 16));
  const LineIntersector dual(polygon, LineMethod::Dual);
  const std::vector<Vec2> ring(polygon.vertices().begin(), polygon.vertices().end());
  convexloc::Rng rng(5);
  std::uint32_t worst = 0;
  for (int k = 0; k < 20000; ++k) {
    const Vec2 p1{rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2)};
    const Vec2 p2{rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2)};
    const convexloc::LineTrace t = dual.trace(p1, p2);
    ASSERT_GE(t.cell, 0);
    ASSERT_GE(t.opposite, 0);
    ASSERT_FALSE(t.bisected);
    // the opposite cell is the one of -w: it holds c* - (b - c*), the point b mirrored
    const Vec2 c = *dual.dualLocator()->centre();
    const Vec2 d{p2.x - p1.x, p2.y - p1.y};
    const double m = std::max(std::fabs(d.x), std::fabs(d.y));
    ASSERT_EQ(t.opposite, dual.dualLocator()->cellIndex({c.x + d.y / m, c.y - d.x / m}));
    worst = std::max(worst, t.climbSteps);
    if (k < 40) {
      ASSERT_EQ(t.crossing, referenceHit(ring, p1, p2).crossing);
    }
  }
  EXPECT_LE(worst, 4u);
  const convexloc::LineStats s = dual.stats();
  EXPECT_EQ(s.vertices, ring.size());
  EXPECT_GT(s.cells, 0u);
  ASSERT_NE(dual.dualLocator(), nullptr);
  // the dual polygon is centrally symmetric: its locator's centre lies at the origin
  ASSERT_TRUE(dual.dualLocator()->centre().has_value());
  EXPECT_LT(std::fabs(dual.dualLocator()->centre()->x), 1e-12);
  EXPECT_LT(std::fabs(dual.dualLocator()->centre()->y), 1e-12);
}

// Turning angles spanning many orders of magnitude (points of a parabola at t = +-2^-k): the
// dual's cells near its axis list long runs of vertices, so windows cannot confirm and the
// climb over the ring and bisection take over; every answer, one by one and in a batch,
// still matches the reference.
TEST(Intersect2DDual, UnevenTurningFallsBackExactly) {
  std::vector<Vec2> points;
  for (int k = 40; k >= 0; --k) points.push_back({-std::ldexp(1.0, -k), std::ldexp(1.0, -2 * k)});
  for (int k = 0; k <= 40; ++k) points.push_back({std::ldexp(1.0, -k), std::ldexp(1.0, -2 * k)});
  points.push_back({0, 0});
  const ConvexPolygon polygon(convexloc::convexHull(points));
  const std::vector<Vec2> ring(polygon.vertices().begin(), polygon.vertices().end());
  const LineIntersector dual(polygon, LineMethod::Dual);
  auto lines = linesFor(ring, 400, 11);
  convexloc::Rng rng(12);
  for (int k = 0; k < 400; ++k) {  // nearly horizontal lines: the crowded cells
    const double y = std::ldexp(rng.uniform(), -static_cast<int>(rng.uniform() * 60));
    lines.push_back({{-2, y}, {2, y * (1 + rng.uniform() * 1e-3)}});
  }
  std::vector<Vec2> flat;
  for (const auto& [p1, p2] : lines) flat.insert(flat.end(), {p1, p2});
  std::vector<Crossing> batch(lines.size());
  dual.classify(std::span(flat), std::span(batch));
  std::size_t fallbacks = 0;
  for (std::size_t k = 0; k < lines.size(); ++k) {
    const auto& [p1, p2] = lines[k];
    const LineHit want = referenceHit(ring, p1, p2);
    ASSERT_EQ(dual.classify(p1, p2), want.crossing) << show(p1) << show(p2);
    ASSERT_EQ(batch[k], want.crossing) << show(p1) << show(p2);
    ASSERT_EQ(dual.intersect(p1, p2), want) << show(p1) << show(p2);
    const convexloc::LineTrace t = dual.trace(p1, p2);
    fallbacks += t.bisected || t.climbSteps > 2;
  }
  EXPECT_GT(fallbacks, 0u);  // the climb past the windows was exercised
}

// the crossing from the two extremes' signs, for every pair of signs
TEST(Intersect2DCrossing, FromSigns) {
  for (int high = -1; high <= 1; ++high)
    for (int low = -1; low <= high; ++low) {
      const Crossing want = (low > 0 || high < 0)   ? Crossing::Misses
                            : (low < 0 && high > 0) ? Crossing::Crosses
                                                    : Crossing::Touches;
      EXPECT_EQ(convexloc::crossingOf(high, low), want) << high << " " << low;
    }
}

// Lines at every angle through a vertex of the regular 4096-gon, along its edges, one ulp off
// both, and through the centre, at three scales: the one-line path (direction cells of w and
// -w side by side, windows confirmed without branches) agrees with the batch, the trace and
// the reference, and the trace's proposals come from the cells of w and -w.
TEST(Intersect2DDual, DirectionCellsAgreeEverywhere) {
  for (int e : {0, 700, -700}) {
    std::vector<Vec2> input = shapes::regular(4096);
    for (Vec2& v : input) v = {std::ldexp(v.x, e), std::ldexp(v.y, e)};
    const ConvexPolygon polygon(input);
    const std::vector<Vec2> ring(polygon.vertices().begin(), polygon.vertices().end());
    const LineIntersector dual(polygon, LineMethod::Dual);
    std::vector<std::pair<Vec2, Vec2>> lines;
    for (std::size_t i = 0; i < ring.size(); i += 37) {
      const std::size_t n = ring.size();
      const Vec2 a = ring[i], b = ring[(i + 1) % n], c = ring[(i + 5) % n];
      const Vec2 before = ring[(i + n - 1) % n];
      const Vec2 off{std::nextafter(a.x, 2 * a.x), a.y};
      lines.push_back({a, b});    // along an edge
      lines.push_back({off, b});  // one ulp off it
      lines.push_back({a, c});    // through two vertices
      lines.push_back({a, {a.x + (b.x - before.x), a.y + (b.y - before.y)}});  // touching at a
      lines.push_back({{0, 0}, a});                                            // through the centre
    }
    std::vector<Vec2> flat;
    for (const auto& [p1, p2] : lines) flat.insert(flat.end(), {p1, p2});
    std::vector<Crossing> batch(lines.size());
    dual.classify(std::span(flat), std::span(batch));
    for (std::size_t k = 0; k < lines.size(); ++k) {
      const auto& [p1, p2] = lines[k];
      const LineHit want = referenceHit(ring, p1, p2);
      ASSERT_EQ(dual.classify(p1, p2), want.crossing) << show(p1) << show(p2);
      ASSERT_EQ(dual.classify(p2, p1), want.crossing) << show(p2) << show(p1);
      ASSERT_EQ(batch[k], want.crossing) << show(p1) << show(p2);
      const convexloc::LineTrace t = dual.trace(p1, p2);
      ASSERT_EQ(t.crossing, want.crossing) << show(p1) << show(p2);
      ASSERT_FALSE(t.bisected);
      ASSERT_LE(t.climbSteps, 2u);  // each proposal is its extreme or next to it
    }
  }
}

// the batch over every length around its blocks, against one line at a time
TEST(Intersect2DDual, BatchLengthsAgreeWithSingle) {
  const ConvexPolygon polygon(shapes::regular(1000));
  const LineIntersector dual(polygon, LineMethod::Dual);
  convexloc::Rng rng(8);
  std::vector<Vec2> flat;
  for (int k = 0; k < 2 * 70; ++k) flat.push_back({rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2)});
  for (std::size_t count : {0, 1, 15, 16, 17, 33, 70}) {
    std::vector<Crossing> out(count, Crossing::Touches);
    dual.classify(std::span(flat).first(2 * count), std::span(out));
    for (std::size_t k = 0; k < count; ++k)
      ASSERT_EQ(out[k], dual.classify(flat[2 * k], flat[2 * k + 1])) << count << " " << k;
  }
}

// an integer lattice polygon: lines exactly parallel to edges and exactly through vertices
TEST(Intersect2DExactLattice, ParallelAndThroughVertices) {
  const ConvexPolygon polygon(std::vector<Vec2>{{0, 0}, {4, 1}, {6, 3}, {5, 6}, {2, 7}, {-1, 4}});
  const std::vector<Vec2> ring(polygon.vertices().begin(), polygon.vertices().end());
  std::vector<std::pair<Vec2, Vec2>> lines;
  for (double x1 = -3; x1 <= 8; x1 += 1)
    for (double y1 = -2; y1 <= 9; y1 += 1)
      for (Vec2 d : {Vec2{4, 1}, Vec2{2, 2}, Vec2{-1, 3}, Vec2{-3, 1}, Vec2{1, 0}, Vec2{0, 1}})
        lines.push_back({{x1, y1}, {x1 + d.x, y1 + d.y}});
  for (LineMethod m : convexloc::kAllLineMethods) {
    const LineIntersector li(polygon, m);
    for (const auto& [p1, p2] : lines) {
      ASSERT_EQ(li.intersect(p1, p2), referenceHit(ring, p1, p2)) << show(p1) << show(p2);
      const auto got = li.clip(p1, p2), want = referenceClip(ring, p1, p2);
      ASSERT_EQ(got.has_value(), want.has_value());
      if (got) {
        EXPECT_EQ(got->a, want->a);
        EXPECT_EQ(got->b, want->b);
      }
    }
  }
}

// clipping: a segment through one vertex only gives it twice; the segment's own direction
TEST(Intersect2DClip, PointsAndDirection) {
  const ConvexPolygon square(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  for (LineMethod m : convexloc::kAllLineMethods) {
    const LineIntersector li(square, m);
    auto c = li.clip({-1, 1}, {1, -1});  // through the corner (0, 0) only
    ASSERT_TRUE(c);
    EXPECT_EQ(*c, (Segment2D{{0, 0}, {0, 0}}));
    c = li.clip({2, 0.5}, {-1, 0.5});  // crossing, right to left
    ASSERT_TRUE(c);
    EXPECT_EQ(*c, (Segment2D{{1, 0.5}, {0, 0.5}}));
    c = li.clip({0.25, 0.5}, {0.75, 0.5});  // inside
    ASSERT_TRUE(c);
    EXPECT_EQ(*c, (Segment2D{{0.25, 0.5}, {0.75, 0.5}}));
    EXPECT_FALSE(li.clip({2, 0.5}, {3, 0.5}));  // on the line, beyond the exit
    c = li.clip({2, 1}, {-2, 1});               // along the top edge, right to left
    ASSERT_TRUE(c);
    EXPECT_EQ(*c, (Segment2D{{1, 1}, {0, 1}}));
    c = li.clip({1, 0.5}, {3, 0.5});  // starts on the boundary, leaves at once
    ASSERT_TRUE(c);
    EXPECT_EQ(*c, (Segment2D{{1, 0.5}, {1, 0.5}}));
    EXPECT_EQ(li.classify({2, 0}, {2, 1}), Crossing::Misses);
    EXPECT_EQ(li.classify({1, 5}, {1, 6}), Crossing::Touches);
  }
}

// the exact intersection rounded once, including halfway cases and subnormal results
TEST(Intersect2DClip, RoundedIntersectionIsNearest) {
  // the line y = x against the segment x = 1/3 .. : the point (1/3, 1/3) rounded
  const Vec2 p = convexloc::roundedIntersection({0, 0}, {1, 1}, {1.0 / 3, -1}, {1.0 / 3, 1});
  EXPECT_EQ(p.x, 1.0 / 3);
  EXPECT_EQ(p.y, 1.0 / 3);
  // a subnormal crossing: y = 0 against the segment from (0, -1) to (2^-1074 * 3, 1): x = 1.5
  // units of the smallest subnormal, a tie, rounded to even (2 units)
  const double tiny = std::numeric_limits<double>::denorm_min();
  const Vec2 q = convexloc::roundedIntersection({-1, 0}, {1, 0}, {0, -1}, {3 * tiny, 1});
  EXPECT_EQ(q.x, 2 * tiny);
  EXPECT_EQ(q.y, 0.0);
}

TEST(Intersect2DNames, RoundTrip) {
  for (LineMethod m : convexloc::kAllLineMethods)
    EXPECT_EQ(convexloc::parseLineMethod(convexloc::toString(m)), m);
  EXPECT_FALSE(convexloc::parseLineMethod("polar"));
  EXPECT_EQ(convexloc::costOf(LineMethod::Dual), "O(1)");
}

}  // namespace
