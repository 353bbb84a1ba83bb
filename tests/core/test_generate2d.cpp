// The generators: every kind gives a valid polygon (Degenerate a valid input that normalises to
// a square), the same seed gives the same doubles, and point sets have the promised shape.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/polygon.hpp"
#include "reference2d.hpp"

using namespace convexloc;

namespace {

TEST(GeneratePolygon, EveryKindIsValidAndStrictlyConvexAsGiven) {
  for (PolygonKind kind : kAllPolygonKinds)
    for (std::size_t n : {3, 4, 5, 17, 256, 1000})
      for (std::uint64_t seed : {1, 2, 99}) {
        SCOPED_TRACE(std::string(toString(kind)) + " n=" + std::to_string(n) +
                     " seed=" + std::to_string(seed));
        const std::vector<Vec2> v = generatePolygon(kind, n, seed);
        const ConvexPolygon p(v);
        EXPECT_TRUE(ref::sameCycle(p.vertices(), ref::hull(v)));
        if (kind == PolygonKind::Degenerate) {
          const double k = static_cast<double>(std::max<std::size_t>(1, n / 4));
          EXPECT_EQ(p.size(), 4u);
          EXPECT_GT(p.droppedCount(), 0u);
          EXPECT_TRUE(
              ref::sameCycle(p.vertices(), std::vector<Vec2>{{0, 0}, {k, 0}, {k, k}, {0, k}}));
          continue;
        }
        // counter-clockwise and strictly convex as given: nothing dropped, nothing reversed
        EXPECT_EQ(p.droppedCount(), 0u);
        EXPECT_FALSE(p.wasClockwise());
        EXPECT_TRUE(ref::strictlyConvexTurns(v));
        EXPECT_GE(v.size(), 3u);
        EXPECT_LE(v.size(), kind == PolygonKind::Triangle ? 3u : n);
        if (kind == PolygonKind::Regular || kind == PolygonKind::Ellipse ||
            kind == PolygonKind::Offset || kind == PolygonKind::TinyEdges ||
            kind == PolygonKind::Random) {
          EXPECT_GE(v.size(), n * 9 / 10) << "far fewer vertices than asked for";
        }
      }
}

TEST(GeneratePolygon, DeterministicForASeed) {
  for (PolygonKind kind : kAllPolygonKinds) {
    SCOPED_TRACE(toString(kind));
    EXPECT_EQ(generatePolygon(kind, 100, 7), generatePolygon(kind, 100, 7));
  }
  // the seeded kinds change with the seed
  for (PolygonKind kind : {PolygonKind::Random, PolygonKind::Offset, PolygonKind::Triangle})
    EXPECT_NE(generatePolygon(kind, 100, 7), generatePolygon(kind, 100, 8)) << toString(kind);
}

TEST(GeneratePolygon, KindsHaveTheirShape) {
  // tiny edges: three long edges, the rest about 1e-10 long
  const ConvexPolygon tiny(generatePolygon(PolygonKind::TinyEdges, 1000, 1));
  double shortest = 1e300, longest = 0;
  for (std::size_t i = 0; i < tiny.size(); ++i) {
    Vec2 a = tiny.edgeStart(i), b = tiny.edgeEnd(i);
    double len = std::hypot(b.x - a.x, b.y - a.y);
    shortest = std::min(shortest, len);
    longest = std::max(longest, len);
  }
  EXPECT_GT(longest / shortest, 1e10);
  // offset: around (1e9, -1e9)
  const ConvexPolygon offset(generatePolygon(PolygonKind::Offset, 64, 3));
  EXPECT_NEAR(offset.bounds().lo.x, 1e9 - 1, 2e-3);
  EXPECT_NEAR(offset.bounds().hi.y, -1e9 + 1, 2e-3);
  // sliver: about 2 long and 2e-9 wide
  const ConvexPolygon sliver(generatePolygon(PolygonKind::Sliver, 64, 1));
  EXPECT_LT(sliver.area(), 1e-8);
  EXPECT_GT(sliver.bounds().hi.x - sliver.bounds().lo.x, 1.5);
  // regular: on the unit circle
  for (Vec2 v : generatePolygon(PolygonKind::Regular, 33, 1))
    EXPECT_NEAR(std::hypot(v.x, v.y), 1.0, 1e-15);
}

TEST(GeneratePolygon, RejectsBadSizes) {
  EXPECT_THROW(generatePolygon(PolygonKind::Regular, 2, 1), UsageError);
  EXPECT_THROW(generatePolygon(PolygonKind::Random, 0, 1), UsageError);
  EXPECT_THROW(generatePolygon(PolygonKind::Regular, (std::size_t{1} << 26) + 1, 1), UsageError);
}

TEST(GeneratePolygon, KindNamesRoundTrip) {
  for (PolygonKind kind : kAllPolygonKinds) EXPECT_EQ(parsePolygonKind(toString(kind)), kind);
  EXPECT_EQ(toString(PolygonKind::TinyEdges), "tiny-edges");
  EXPECT_FALSE(parsePolygonKind("square").has_value());
}

TEST(GeneratePoints, UniformInTheEnlargedBoxAndDeterministic) {
  const ConvexPolygon p(generatePolygon(PolygonKind::Random, 50, 4));
  const std::vector<Vec2> a = generatePoints(p, 5000, 9, false);
  EXPECT_EQ(a, generatePoints(p, 5000, 9, false));
  EXPECT_NE(a, generatePoints(p, 5000, 10, false));
  ASSERT_EQ(a.size(), 5000u);
  const Box2 b = p.bounds();
  const double wx = 0.1 * (b.hi.x - b.lo.x), wy = 0.1 * (b.hi.y - b.lo.y);
  std::size_t in = 0, out = 0;
  for (Vec2 q : a) {
    EXPECT_GE(q.x, b.lo.x - wx);
    EXPECT_LE(q.x, b.hi.x + wx);
    EXPECT_GE(q.y, b.lo.y - wy);
    EXPECT_LE(q.y, b.hi.y + wy);
    Location l = ref::locate(p.vertices(), q);
    in += l == Location::Inside;
    out += l == Location::Outside;
  }
  EXPECT_GT(in, 500u);
  EXPECT_GT(out, 500u);
}

TEST(GeneratePoints, NearBoundaryHitsTheBoundaryExactly) {
  for (PolygonKind kind : kAllPolygonKinds) {
    SCOPED_TRACE(toString(kind));
    const ConvexPolygon p(generatePolygon(kind, 40, 5));
    const std::vector<Vec2> pts = generatePoints(p, 4000, 6, true);
    EXPECT_EQ(pts, generatePoints(p, 4000, 6, true));
    ASSERT_EQ(pts.size(), 4000u);
    std::size_t counts[3] = {0, 0, 0};
    for (Vec2 q : pts) ++counts[static_cast<int>(ref::locate(p.vertices(), q))];
    // vertices alone are a fifth of the set; every class shows up
    EXPECT_GT(counts[static_cast<int>(Location::Boundary)], 600u);
    EXPECT_GT(counts[static_cast<int>(Location::Outside)], 100u);
    if (kind != PolygonKind::Degenerate) {
      EXPECT_GT(counts[static_cast<int>(Location::Inside)], 100u);
    }
  }
}

TEST(ConvexHull, MatchesTheReferenceHull) {
  Rng rng(21);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<Vec2> pts;
    const std::size_t n = 3 + rng.below(60);
    for (std::size_t i = 0; i < n; ++i) {
      // a coarse grid makes repeats and collinear triples common
      pts.push_back({static_cast<double>(rng.below(7)), static_cast<double>(rng.below(7))});
    }
    const std::vector<Vec2> h = convexHull(pts);
    const std::vector<Vec2> r = ref::hull(pts);
    if (r.size() >= 3) {
      EXPECT_TRUE(ref::sameCycle(h, r)) << "trial " << trial;
    }
  }
}

}  // namespace
