// Snapping: a point snapped onto a vertex or an edge lies exactly on the polygon's boundary,
// checked by core's locators and by rational arithmetic independent of orient2d.
#include <gtest/gtest.h>

#include <boost/multiprecision/cpp_int.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

#include "convexloc/locate2d.hpp"
#include "convexloc/polygon.hpp"
#include "logic/app/interaction.hpp"
#include "logic/app/model.hpp"
#include "logic/draw/snap_indicator.hpp"
#include "logic/view/snap.hpp"

namespace cv = convexloc::viewer;
using convexloc::Location;
using convexloc::Vec2;

namespace {

using Rational = boost::multiprecision::cpp_rational;

// the exact cross product (b - a) x (q - a), in rationals made from the doubles
Rational exactCross(Vec2 a, Vec2 b, Vec2 q) {
  const Rational ax(a.x), ay(a.y), bx(b.x), by(b.y), qx(q.x), qy(q.y);
  return (bx - ax) * (qy - ay) - (by - ay) * (qx - ax);
}

// q on the closed segment a-b, decided in rationals
bool exactlyOnSegment(Vec2 a, Vec2 b, Vec2 q) {
  return exactCross(a, b, q) == 0 && std::min(a.x, b.x) <= q.x && q.x <= std::max(a.x, b.x) &&
         std::min(a.y, b.y) <= q.y && q.y <= std::max(a.y, b.y);
}

const std::vector<Vec2> kSquare{{0, 0}, {2, 0}, {2, 2}, {0, 2}};

}  // namespace

TEST(Snap, NearAVertexGivesItsExactDoubles) {
  const std::vector<Vec2> ring{{0.1, 0.2}, {0.7, 0.25}, {0.4, 0.9}};
  const cv::Snap s = cv::snapPoint({0.7004, 0.2497}, {ring, {}, 0.0, {}}, 0.01);
  EXPECT_EQ(s.kind, cv::SnapKind::Vertex);
  EXPECT_EQ(s.index, 1u);
  EXPECT_EQ(s.point, ring[1]);
  const convexloc::ConvexPolygon poly(ring);
  EXPECT_EQ(convexloc::Locator2D(poly, convexloc::Method2D::Polar).locate(s.point),
            Location::Boundary);
}

TEST(Snap, OntoAnAxisAlignedEdgeLiesOnIt) {
  const cv::Snap s = cv::snapPoint({1.3, 0.004}, {kSquare, {}, 0.0, {}}, 0.01);
  EXPECT_EQ(s.kind, cv::SnapKind::Edge);
  EXPECT_EQ(s.index, 0u);
  EXPECT_EQ(s.point.y, 0.0);
  EXPECT_NEAR(s.point.x, 1.3, 1e-12);
  const cv::Snap v = cv::snapPoint({2.003, 0.7}, {kSquare, {}, 0.0, {}}, 0.01);
  EXPECT_EQ(v.kind, cv::SnapKind::Edge);
  EXPECT_EQ(v.point.x, 2.0);
}

TEST(Snap, OntoARationalEdgeLiesExactlyOnIt) {
  // the edge from (0,0) to (3,1): y = x / 3 has exact double points all along it
  const std::vector<Vec2> ring{{0, 0}, {3, 1}, {0, 2}};
  const cv::Snap s = cv::snapPoint({1.5, 0.502}, {ring, {}, 0.0, {}}, 0.01);
  ASSERT_EQ(s.kind, cv::SnapKind::Edge);
  EXPECT_TRUE(exactlyOnSegment(ring[0], ring[1], s.point));
  EXPECT_NEAR(s.point.x, 1.5, 1e-3);
}

namespace {

// Random hulls, cursors near their edges: the snapped point is on the boundary by the
// rational check and by two exact locators. Returns how many snaps stayed on the edge.
int snapNearEdges(bool dyadic, int& trials) {
  std::mt19937_64 rng(dyadic ? 64 : 19);
  std::uniform_real_distribution<double> coord(-1.0, 1.0), t(0.05, 0.95), off(-1e-3, 1e-3);
  // dyadic: multiples of 1/64, whose edges hold many doubles
  const auto pick = [&] { return dyadic ? std::round(coord(rng) * 64.0) / 64.0 : coord(rng); };
  int onEdge = 0;
  trials = 0;
  for (int round = 0; round < 200; ++round) {
    std::vector<Vec2> pts;
    for (int k = 0; k < 6; ++k) pts.push_back({pick(), pick()});
    const convexloc::ConvexPolygon poly = convexloc::ConvexPolygon::hullOf(pts);
    const std::vector<Vec2> ring(poly.vertices().begin(), poly.vertices().end());
    const convexloc::Locator2D halfplane(poly, convexloc::Method2D::Halfplane);
    const convexloc::Locator2D polar(poly, convexloc::Method2D::Polar);
    for (std::size_t e = 0; e < ring.size(); ++e, ++trials) {
      const Vec2 a = ring[e], b = ring[(e + 1) % ring.size()];
      const double u = t(rng);
      const Vec2 cursor{a.x + u * (b.x - a.x) + off(rng), a.y + u * (b.y - a.y) + off(rng)};
      const cv::Snap s = cv::snapPoint(cursor, {ring, {}, 0.0, {}}, 0.01);
      EXPECT_NE(s.kind, cv::SnapKind::None);
      if (s.kind == cv::SnapKind::Edge) {
        ++onEdge;
        EXPECT_TRUE(exactlyOnSegment(a, b, s.point));
        EXPECT_LE(std::hypot(s.point.x - cursor.x, s.point.y - cursor.y), 0.01);
      } else {
        EXPECT_EQ(s.kind, cv::SnapKind::Vertex);
        EXPECT_EQ(s.point, ring[s.index]);
        // near the vertex itself, or the edge's end where the edge holds no double near
        const bool near = std::hypot(s.point.x - cursor.x, s.point.y - cursor.y) <= 0.01;
        EXPECT_TRUE(near || s.fromEdge == e);
      }
      EXPECT_EQ(halfplane.locate(s.point), Location::Boundary);
      EXPECT_EQ(polar.locate(s.point), Location::Boundary);
    }
  }
  return onEdge;
}

}  // namespace

TEST(Snap, EverySnapNearAnEdgeIsOnTheBoundaryExactly) {
  // generic doubles: an edge may hold no double near the cursor, and the snap then takes
  // the nearer end; either way the point is exactly on the boundary
  int trials = 0;
  snapNearEdges(false, trials);
  EXPECT_GT(trials, 400);
}

TEST(Snap, EdgesOfShortDoublesKeepTheSnapOnTheEdge) {
  int trials = 0;
  const int onEdge = snapNearEdges(true, trials);
  EXPECT_GT(onEdge, trials * 9 / 10);
}

TEST(Snap, VertexBeforeCentreBeforeEdgeBeforeGrid) {
  const cv::SnapTargets t{kSquare, Vec2{1.0, 1.0}, 0.5, {}};
  EXPECT_EQ(cv::snapPoint({0.05, 0.02}, t, 0.1).kind, cv::SnapKind::Vertex);
  EXPECT_EQ(cv::snapPoint({1.02, 0.98}, t, 0.1).kind, cv::SnapKind::Centre);
  EXPECT_EQ(cv::snapPoint({1.02, 0.98}, t, 0.1).point, (Vec2{1.0, 1.0}));
  EXPECT_EQ(cv::snapPoint({0.77, 0.03}, t, 0.1).kind, cv::SnapKind::Edge);
  const cv::Snap g = cv::snapPoint({0.52, 1.47}, t, 0.1);
  EXPECT_EQ(g.kind, cv::SnapKind::Grid);
  EXPECT_EQ(g.point, (Vec2{0.5, 1.5}));
}

TEST(Snap, FarFromEverythingTheCursorStays) {
  const cv::Snap s = cv::snapPoint({0.7, 1.3}, {kSquare, Vec2{1.0, 1.0}, 0.0, {}}, 0.1);
  EXPECT_EQ(s.kind, cv::SnapKind::None);
  EXPECT_EQ(s.point, (Vec2{0.7, 1.3}));
}

TEST(Snap, ADraggedVertexSkipsItselfAndItsOwnEdges) {
  // vertex 1 (2,0) dragged near itself and along its own edges snaps to none of them, but
  // to the opposite edges and other vertices
  const cv::SnapTargets t{kSquare, {}, 0.0, 1u};
  EXPECT_EQ(cv::snapPoint({2.01, 0.01}, t, 0.05).kind, cv::SnapKind::None);
  EXPECT_EQ(cv::snapPoint({1.0, 0.01}, t, 0.05).kind, cv::SnapKind::None);
  const cv::Snap onDiagonalEnd = cv::snapPoint({0.02, 1.99}, t, 0.05);
  EXPECT_EQ(onDiagonalEnd.kind, cv::SnapKind::Vertex);
  EXPECT_EQ(onDiagonalEnd.index, 3u);
  const cv::Snap opposite = cv::snapPoint({0.01, 1.0}, t, 0.05);
  EXPECT_EQ(opposite.kind, cv::SnapKind::Edge);
  EXPECT_EQ(opposite.index, 3u);
  EXPECT_EQ(opposite.point.x, 0.0);
}

TEST(Snap, TheIndicatorSaysWhenAnEdgeHoldsNoDoubleNear) {
  EXPECT_EQ(cv::snapText({{}, cv::SnapKind::Vertex, 4, 3u}, 6),
            "vertex 4 (edge 3-4 holds no double here)");
  EXPECT_EQ(cv::snapText({{}, cv::SnapKind::Edge, 5, {}}, 6), "edge 5-0");
  EXPECT_EQ(cv::snapText({{}, cv::SnapKind::Vertex, 2, {}}, 6), "vertex 2");
  EXPECT_EQ(cv::snapText({{}, cv::SnapKind::Centre, 0, {}}, 6), "centre");
}

TEST(Snap, NiceGridSteps) {
  EXPECT_DOUBLE_EQ(cv::niceGridStep(0.13), 0.2);
  EXPECT_DOUBLE_EQ(cv::niceGridStep(3.0), 5.0);
  EXPECT_DOUBLE_EQ(cv::niceGridStep(7.0), 10.0);
  EXPECT_DOUBLE_EQ(cv::niceGridStep(100.0), 100.0);
  EXPECT_EQ(cv::niceGridStep(0.0), 0.0);
}

// === The gestures snap

namespace {

// the box (0,0)-(4,3) fitted into a 1000x800 viewport
cv::Model boxModel() {
  cv::Model m;
  m.scene2d.setShape(std::vector<Vec2>{{0, 0}, {4, 0}, {4, 3}, {0, 3}}, "box");
  m.camera2d.setViewport({1000.0, 800.0});
  m.fit({{0.0, 0.0}, {1000.0, 800.0}});
  return m;
}

// a press and a release at `pos` (a click), with Alt held or not
void clickAt(cv::Interaction& ia, cv::Model& m, glm::dvec2 pos, bool alt = false) {
  cv::PointerInput in;
  in.pos = pos;
  in.alt = alt;
  in.pressed[0] = in.down[0] = true;
  ia.update(in, m);
  in.pressed[0] = in.down[0] = false;
  in.released[0] = true;
  ia.update(in, m);
}

// a left drag from `from` to `to` in ten moves
void dragFromTo(cv::Interaction& ia, cv::Model& m, glm::dvec2 from, glm::dvec2 to, bool alt) {
  cv::PointerInput in;
  in.pos = from;
  in.alt = alt;
  in.pressed[0] = in.down[0] = true;
  ia.update(in, m);
  in.pressed[0] = false;
  for (int k = 1; k <= 10; ++k) {
    const glm::dvec2 next = from + (to - from) * (k / 10.0);
    in.delta = next - in.pos;
    in.pos = next;
    ia.update(in, m);
  }
  in.down[0] = false;
  in.released[0] = true;
  in.delta = {0.0, 0.0};
  ia.update(in, m);
}

}  // namespace

TEST(SnapGestures, AClickNearAnEdgeLandsOnItAndAltPlacesFreely) {
  cv::Model m = boxModel();
  cv::Interaction ia;
  // 4 pixels inside the bottom edge, away from the grid's points
  const glm::dvec2 near = m.camera2d.toScreen({1.37, 0.0}) + glm::dvec2(0.0, -4.0);
  clickAt(ia, m, near);
  ASSERT_TRUE(m.scene2d.probe());
  EXPECT_EQ(m.scene2d.probe()->point.y, 0.0);
  EXPECT_EQ(m.scene2d.probe()->trace.result, Location::Boundary);
  clickAt(ia, m, near, true);
  EXPECT_GT(m.scene2d.probe()->point.y, 0.0);
  EXPECT_EQ(m.scene2d.probe()->trace.result, Location::Inside);
}

TEST(SnapGestures, AClickOnAVertexHandlePlacesThePointOnTheVertex) {
  cv::Model m = boxModel();
  cv::Interaction ia;
  clickAt(ia, m, m.camera2d.toScreen({4.0, 3.0}) + glm::dvec2(3.0, -2.0));
  ASSERT_TRUE(m.scene2d.probe());
  EXPECT_EQ(m.scene2d.probe()->point, (Vec2{4.0, 3.0}));
  EXPECT_EQ(m.scene2d.probe()->trace.result, Location::Boundary);
  EXPECT_EQ(m.scene2d.polygon().size(), 4u);  // and the shape is as it was
}

TEST(SnapGestures, ADraggedVertexSnapsToTheGridUnlessAltIsHeld) {
  cv::Model m = boxModel();
  cv::Interaction ia;
  const glm::dvec2 corner = m.camera2d.toScreen({4.0, 3.0});
  const glm::dvec2 target = m.camera2d.toScreen({5.0, 4.0}) + glm::dvec2(3.0, 2.0);
  dragFromTo(ia, m, corner, target, false);
  const auto has = [&](Vec2 q) {
    const auto v = m.scene2d.polygon().vertices();
    return std::find(v.begin(), v.end(), q) != v.end();
  };
  EXPECT_TRUE(has({5.0, 4.0}));
  ASSERT_FALSE(m.scene2d.drag());
  // with Alt the vertex goes where the pointer is, off the grid
  const glm::dvec2 back = m.camera2d.toScreen({5.0, 4.0});
  const glm::dvec2 further = m.camera2d.toScreen({5.5, 4.5}) + glm::dvec2(3.0, 2.0);
  dragFromTo(ia, m, back, further, true);
  EXPECT_FALSE(has({5.0, 4.0}));
  EXPECT_FALSE(has({5.5, 4.5}));
  EXPECT_FALSE(m.scene2d.probe());
  EXPECT_EQ(m.scene2d.polygon().size(), 4u);
}

TEST(SnapGestures, ALineDrawnBetweenTwoVerticesGoesThroughThemExactly) {
  cv::Model m = boxModel();
  m.setLinesMode(true);
  m.fit({{0.0, 0.0}, {1000.0, 800.0}});
  cv::Interaction ia;
  // from near (4,0) to near (4,3): the line holds the right edge, so it touches
  dragFromTo(ia, m, m.camera2d.toScreen({4.0, 0.0}) + glm::dvec2(3.0, 3.0),
             m.camera2d.toScreen({4.0, 3.0}) + glm::dvec2(-2.0, 4.0), false);
  ASSERT_TRUE(m.lines2d.line());
  EXPECT_EQ(m.lines2d.line()->p1, (Vec2{4.0, 0.0}));
  EXPECT_EQ(m.lines2d.line()->p2, (Vec2{4.0, 3.0}));
  EXPECT_EQ(m.lines2d.line()->hit.crossing, convexloc::Crossing::Touches);
}

TEST(SnapGestures, TheIndicatorShowsWhatAClickWouldSnapTo) {
  cv::Model m = boxModel();
  cv::Interaction ia;
  cv::PointerInput in;
  in.pos = m.camera2d.toScreen({0.0, 3.0}) + glm::dvec2(12.0, 0.0);  // beyond the handle
  ia.update(in, m);
  ASSERT_TRUE(m.scene2d.snapMark());
  EXPECT_EQ(m.scene2d.snapMark()->kind, cv::SnapKind::Edge);
  in.alt = true;
  ia.update(in, m);
  EXPECT_FALSE(m.scene2d.snapMark());
}
