// ConvexPolygon: every rejection names its witness, and normalisation keeps the region: the
// normalised ring is the rational convex hull of the input and every dropped input point
// lies on its boundary.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/polygon.hpp"
#include "reference2d.hpp"
#include "shapes2d.hpp"

using namespace convexloc;
using testing::AllOf;
using testing::HasSubstr;

namespace {

// the GeometryError thrown for `points` (with `lines`), or a failure when none is thrown
GeometryError rejection(const std::vector<Vec2>& points,
                        const std::vector<std::size_t>& lines = {}) {
  try {
    ConvexPolygon polygon(points, lines);
  } catch (const GeometryError& e) {
    return e;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected a GeometryError, got: " << e.what();
    return GeometryError(e.what());
  }
  ADD_FAILURE() << "expected a GeometryError, the polygon was accepted";
  return GeometryError("");
}

// source lines 10, 20, 30, ... for n points
std::vector<std::size_t> linesOf(std::size_t n) {
  std::vector<std::size_t> lines(n);
  for (std::size_t i = 0; i < n; ++i) lines[i] = 10 * (i + 1);
  return lines;
}

// how many times the cyclic sequence s steps down (one for a rotated increasing sequence)
std::size_t cyclicDescents(std::span<const std::uint32_t> s) {
  std::size_t d = 0;
  for (std::size_t i = 0; i < s.size(); ++i) d += s[(i + 1) % s.size()] < s[i];
  return d;
}

// === Rejections

TEST(PolygonRejects, FewerThanThreeVertices) {
  const std::vector<Vec2> none;
  EXPECT_THAT(rejection(none).what(), HasSubstr("at least 3 vertices, got 0"));
  const GeometryError two = rejection({{0, 0}, {1, 1}}, {4, 7});
  EXPECT_THAT(two.what(), HasSubstr("at least 3 vertices, got 2"));
  EXPECT_EQ(two.line(), 7u);
}

TEST(PolygonRejects, ThreePointsTwoDistinct) {
  const GeometryError e = rejection({{0, 0}, {1, 1}, {0, 0}}, linesOf(3));
  EXPECT_THAT(e.what(),
              AllOf(HasSubstr("fewer than 3 distinct vertices"), HasSubstr("2 distinct")));
  EXPECT_EQ(e.line(), 30u);
  EXPECT_THAT(rejection({{2, 5}, {2, 5}, {2, 5}, {2, 5}}).what(),
              AllOf(HasSubstr("fewer than 3 distinct"), HasSubstr("(2, 5)")));
}

TEST(PolygonRejects, AllCollinear) {
  EXPECT_THAT(rejection({{0, 0}, {1, 1}, {3, 3}, {2, 2}}).what(),
              AllOf(HasSubstr("all 4 vertices are collinear"), HasSubstr("no area")));
  // collinear only exactly: one ulp off the line is a (thin) polygon
  EXPECT_NO_THROW(ConvexPolygon(std::vector<Vec2>{{0, 0}, {1, 1}, {3, std::nextafter(3.0, 4.0)}}));
  // huge and tiny magnitudes, exactly collinear
  const double big = std::numeric_limits<double>::max() / 4;
  EXPECT_THAT(rejection({{-big, -big}, {0, 0}, {big, big}}).what(), HasSubstr("collinear"));
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_THAT(rejection({{0, 0}, {tiny, 2 * tiny}, {3 * tiny, 6 * tiny}}).what(),
              HasSubstr("collinear"));
}

TEST(PolygonRejects, ReflexVertexNamedWithItsLine) {
  const std::vector<Vec2> arrow = {{0, 0}, {4, 0}, {4, 4}, {2, 1}, {0, 4}};
  const GeometryError e = rejection(arrow, linesOf(5));
  EXPECT_THAT(e.what(), AllOf(HasSubstr("not convex"), HasSubstr("reflex"), HasSubstr("vertex 4"),
                              HasSubstr("(2, 1)")));
  EXPECT_EQ(e.line(), 40u);
  // the same shape clockwise: still vertex 4 of the input
  const std::vector<Vec2> backwards = {{0, 4}, {2, 1}, {4, 4}, {4, 0}, {0, 0}};
  const GeometryError b = rejection(backwards, linesOf(5));
  EXPECT_THAT(b.what(), AllOf(HasSubstr("reflex"), HasSubstr("vertex 2"), HasSubstr("(2, 1)")));
  EXPECT_EQ(b.line(), 20u);
  // a reflex vertex one ulp inside the chord of its neighbours
  const std::vector<Vec2> dent = {{0, 0}, {2, 0}, {2, 2}, {1, std::nextafter(2.0, 0.0)}, {0, 2}};
  const GeometryError d = rejection(dent, linesOf(5));
  EXPECT_THAT(d.what(), AllOf(HasSubstr("reflex"), HasSubstr("vertex 4")));
  EXPECT_EQ(d.line(), 40u);
}

TEST(PolygonRejects, Bowtie) {
  const GeometryError e = rejection({{0, 0}, {1, 1}, {1, 0}, {0, 1}}, linesOf(4));
  EXPECT_THAT(e.what(), AllOf(HasSubstr("self-intersecting"), HasSubstr("crosses"),
                              HasSubstr("vertex 1"), HasSubstr("vertex 3")));
  EXPECT_EQ(e.line(), 30u);
}

TEST(PolygonRejects, PentagramWindsTwice) {
  std::vector<Vec2> star;
  for (int k = 0; k < 5; ++k) {
    double t = 2 * 3.14159265358979323846 * (2 * k % 5) / 5;
    star.push_back({std::cos(t), std::sin(t)});
  }
  const GeometryError e = rejection(star, linesOf(5));
  EXPECT_THAT(e.what(), AllOf(HasSubstr("self-intersecting"),
                              HasSubstr("winds around more than once"), HasSubstr("vertex ")));
  EXPECT_GT(e.line(), 0u);
  // a square traversed twice also winds twice
  EXPECT_THAT(rejection({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}, {1, 0}, {1, 1}, {0, 1}}).what(),
              HasSubstr("more than once"));
}

TEST(PolygonRejects, SpikeDoublingBack) {
  const GeometryError e = rejection({{0, 0}, {4, 0}, {2, 0}, {2, 3}}, linesOf(4));
  EXPECT_THAT(e.what(),
              AllOf(HasSubstr("doubles back"), HasSubstr("vertex 2"), HasSubstr("(4, 0)")));
  EXPECT_EQ(e.line(), 20u);
  // a needle out of a square's corner and back
  const GeometryError n = rejection({{0, 0}, {4, 0}, {4, 4}, {6, 6}, {4, 4}, {0, 4}}, linesOf(6));
  EXPECT_THAT(n.what(),
              AllOf(HasSubstr("doubles back"), HasSubstr("vertex 4"), HasSubstr("(6, 6)")));
  EXPECT_EQ(n.line(), 40u);
}

TEST(PolygonRejects, NonFiniteCoordinates) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  const GeometryError a = rejection({{0, 0}, {nan, 1}, {0, 1}}, linesOf(3));
  EXPECT_THAT(a.what(), AllOf(HasSubstr("vertex 2"), HasSubstr("not a finite number")));
  EXPECT_EQ(a.line(), 20u);
  const GeometryError b = rejection({{0, 0}, {1, 0}, {1, 1}, {0, -inf}}, linesOf(4));
  EXPECT_THAT(b.what(), AllOf(HasSubstr("vertex 4"), HasSubstr("not a finite number")));
  EXPECT_EQ(b.line(), 40u);
  EXPECT_THAT(rejection({{inf, 0}, {1, 0}, {1, 1}}).what(), HasSubstr("vertex 1"));
}

TEST(PolygonRejects, LinesOfTheWrongSize) {
  const std::vector<Vec2> square = {{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  const std::vector<std::size_t> lines = {1, 2};
  EXPECT_THROW(ConvexPolygon(square, lines), UsageError);
}

TEST(PolygonRejects, ErrorsAreConvexlocErrors) {
  try {
    ConvexPolygon polygon(std::vector<Vec2>{{0, 0}, {1, 1}});
    FAIL() << "accepted two points";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()), "");
  }
}

// === Acceptance and normalisation

TEST(PolygonAccepts, DropsRepeatsAndCollinearVertices) {
  const std::vector<Vec2> input = {{0, 0}, {0, 0}, {1, 0}, {2, 0}, {2, 0}, {2, 1},
                                   {2, 2}, {1, 2}, {0, 2}, {0, 1}, {0, 0}};
  const ConvexPolygon p(input);
  EXPECT_EQ(p.size(), 4u);
  EXPECT_EQ(p.droppedCount(), 7u);
  EXPECT_FALSE(p.wasClockwise());
  const std::vector<Vec2> square = {{0, 0}, {2, 0}, {2, 2}, {0, 2}};
  EXPECT_TRUE(ref::sameCycle(p.vertices(), square));
  EXPECT_EQ(p.bounds().lo, (Vec2{0, 0}));
  EXPECT_EQ(p.bounds().hi, (Vec2{2, 2}));
  EXPECT_DOUBLE_EQ(p.area(), 4.0);
}

TEST(PolygonAccepts, ReversesClockwiseInput) {
  const std::vector<Vec2> input = {{0, 0}, {0, 3}, {2, 3}, {2, 0}};
  const ConvexPolygon p(input);
  EXPECT_TRUE(p.wasClockwise());
  EXPECT_EQ(p.droppedCount(), 0u);
  EXPECT_TRUE(ref::sameCycle(p.vertices(), ref::hull(input)));
  EXPECT_DOUBLE_EQ(p.area(), 6.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_EQ(p.edgeStart(i), p.vertex(i));
    EXPECT_EQ(p.edgeEnd(i), p.vertex((i + 1) % p.size()));
  }
}

TEST(PolygonAccepts, StartingInsideAnEdge) {
  // the first vertex sits on the edge from the last to the second: it must go
  const ConvexPolygon p(std::vector<Vec2>{{1, 0}, {2, 0}, {2, 2}, {0, 2}, {0, 0}});
  EXPECT_EQ(p.size(), 4u);
  EXPECT_EQ(p.droppedCount(), 1u);
  EXPECT_TRUE(ref::sameCycle(p.vertices(), std::vector<Vec2>{{2, 0}, {2, 2}, {0, 2}, {0, 0}}));
}

TEST(PolygonAccepts, ThinButNotFlat) {
  // one ulp off collinear: a valid triangle, no point dropped
  const ConvexPolygon p(std::vector<Vec2>{{0, 0}, {1, 1}, {1, 1 - 0x1p-53}});
  EXPECT_EQ(p.size(), 3u);
  EXPECT_TRUE(p.wasClockwise());
}

// Normalisation of every shape of the matrix against the reference: the ring is the rational
// hull of the input, its turns are strictly left, every input point lies on its boundary,
// and the bookkeeping (sources, dropped count, orientation) agrees.
TEST(PolygonNormalisation, EqualsTheRationalHullOnEveryShape) {
  for (const shapes::ShapeCase& shape : shapes::cases()) {
    SCOPED_TRACE(shape.name);
    const ConvexPolygon p(shape.input);
    const std::vector<Vec2> hull = ref::hull(shape.input);
    ASSERT_GE(hull.size(), 3u);
    EXPECT_TRUE(ref::sameCycle(p.vertices(), hull));
    EXPECT_TRUE(ref::strictlyConvexTurns(p.vertices()));
    std::size_t offBoundary = 0;
    for (Vec2 q : shape.input) offBoundary += ref::locate(hull, q) != Location::Boundary;
    EXPECT_EQ(offBoundary, 0u);
    EXPECT_EQ(p.droppedCount(), shape.input.size() - p.size());
    std::span<const std::uint32_t> src = p.sourceIndex();
    ASSERT_EQ(src.size(), p.size());
    for (std::size_t k = 0; k < p.size(); ++k) {
      ASSERT_LT(src[k], shape.input.size());
      EXPECT_EQ(shape.input[src[k]], p.vertex(k));
    }
    // the kept vertices appear in input order, or in reverse order when it was clockwise
    if (p.wasClockwise()) {
      std::vector<std::uint32_t> back(src.rbegin(), src.rend());
      EXPECT_EQ(cyclicDescents(back), 1u);
    } else {
      EXPECT_EQ(cyclicDescents(src), 1u);
    }
    Box2 box{p.vertex(0), p.vertex(0)};
    for (Vec2 v : shape.input) {
      box.lo = {std::min(box.lo.x, v.x), std::min(box.lo.y, v.y)};
      box.hi = {std::max(box.hi.x, v.x), std::max(box.hi.y, v.y)};
    }
    EXPECT_EQ(p.bounds().lo, box.lo);
    EXPECT_EQ(p.bounds().hi, box.hi);
  }
}

}  // namespace
