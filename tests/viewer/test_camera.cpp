// Camera maths: screen <-> world round trips, zoom at the cursor, fitting, matrices.
#include <gtest/gtest.h>

#include <cmath>

#include "logic/view/camera2d.hpp"
#include "logic/view/camera3d.hpp"

namespace cv = convexloc::viewer;

namespace {

cv::Camera2D camera() {
  cv::Camera2D c;
  c.setViewport({1200.0, 800.0});
  c.set({3.0, -2.0}, 57.0);
  return c;
}

}  // namespace

TEST(Camera2D, ScreenWorldRoundTrip) {
  const cv::Camera2D c = camera();
  for (double x : {0.0, 17.5, 600.0, 1199.0})
    for (double y : {0.0, 400.0, 799.5}) {
      const glm::dvec2 s{x, y};
      const glm::dvec2 back = c.toScreen(c.toWorld(s));
      EXPECT_NEAR(back.x, x, 1e-9);
      EXPECT_NEAR(back.y, y, 1e-9);
    }
}

TEST(Camera2D, CentreIsMiddleAndYPointsUp) {
  const cv::Camera2D c = camera();
  const glm::dvec2 m = c.toScreen({3.0, -2.0});
  EXPECT_DOUBLE_EQ(m.x, 600.0);
  EXPECT_DOUBLE_EQ(m.y, 400.0);
  // a point above the centre in the world is higher on the screen (smaller y)
  EXPECT_LT(c.toScreen({3.0, -1.0}).y, 400.0);
  EXPECT_NEAR(c.toScreen({4.0, -2.0}).x - 600.0, 57.0, 1e-12);
}

TEST(Camera2D, ZoomAtCursorKeepsThePointUnderIt) {
  for (double factor : {1.2, 1.0 / 1.2, 10.0, 1e-3}) {
    cv::Camera2D c = camera();
    const glm::dvec2 cursor{913.0, 121.0};
    const glm::dvec2 before = c.toWorld(cursor);
    c.zoomAt(cursor, factor);
    const glm::dvec2 after = c.toWorld(cursor);
    EXPECT_NEAR(after.x, before.x, 1e-9 * std::abs(before.x) + 1e-12);
    EXPECT_NEAR(after.y, before.y, 1e-9 * std::abs(before.y) + 1e-12);
    EXPECT_NEAR(c.scale(), 57.0 * factor, 1e-9 * 57.0 * factor);
  }
}

TEST(Camera2D, ZoomFarFromTheOriginKeepsThePointUnderIt) {
  // a polygon at 1e9: the camera works in doubles, so zooming in stays exact enough
  cv::Camera2D c;
  c.setViewport({1000.0, 1000.0});
  c.set({1e9, -1e9}, 500.0);
  const glm::dvec2 cursor{700.0, 300.0};
  const glm::dvec2 before = c.toWorld(cursor);
  for (int i = 0; i < 20; ++i) c.zoomAt(cursor, 2.0);
  const glm::dvec2 after = c.toWorld(cursor);
  EXPECT_NEAR(after.x, before.x, 1e-6);
  EXPECT_NEAR(after.y, before.y, 1e-6);
}

TEST(Camera2D, PanMovesContentWithTheMouse) {
  cv::Camera2D c = camera();
  const glm::dvec2 w{5.0, 1.0};
  const glm::dvec2 s0 = c.toScreen(w);
  c.pan({30.0, -12.0});
  const glm::dvec2 s1 = c.toScreen(w);
  EXPECT_NEAR(s1.x - s0.x, 30.0, 1e-9);
  EXPECT_NEAR(s1.y - s0.y, -12.0, 1e-9);
}

TEST(Camera2D, FitPutsTheBoxInsideTheAreaCentred) {
  cv::Camera2D c;
  c.setViewport({1400.0, 900.0});
  const convexloc::Box2 box{{-3.0, 10.0}, {5.0, 12.0}};
  const cv::ScreenRect area{{340.0, 0.0}, {1070.0, 900.0}};
  c.fit(box, area, 0.1);
  const glm::dvec2 lo = c.toScreen({box.lo.x, box.lo.y}), hi = c.toScreen({box.hi.x, box.hi.y});
  EXPECT_GE(lo.x, area.lo.x);
  EXPECT_LE(hi.x, area.hi.x);
  EXPECT_GE(hi.y, area.lo.y);  // hi.y is the top: smaller screen y
  EXPECT_LE(lo.y, area.hi.y);
  EXPECT_NEAR(0.5 * (lo.x + hi.x), area.middle().x, 1e-9);
  EXPECT_NEAR(0.5 * (lo.y + hi.y), area.middle().y, 1e-9);
  // the wide box fills the area's width, less the margins
  EXPECT_NEAR(hi.x - lo.x, 730.0 / 1.2, 1e-6);
}

TEST(Camera2D, ClipMatrixAgreesWithToScreen) {
  const cv::Camera2D c = camera();
  const glm::dvec2 origin{2.5, -1.0};
  const glm::mat4 m = c.clipFromLocal(origin);
  for (glm::dvec2 w : {glm::dvec2{3.0, -2.0}, glm::dvec2{4.25, 0.5}, glm::dvec2{-7.0, 3.0}}) {
    const glm::vec4 clip = m * glm::vec4(static_cast<float>(w.x - origin.x),
                                         static_cast<float>(w.y - origin.y), 0.0f, 1.0f);
    const glm::dvec2 s = c.toScreen(w);
    EXPECT_NEAR((clip.x * 0.5 + 0.5) * 1200.0, s.x, 1e-3);
    EXPECT_NEAR((0.5 - clip.y * 0.5) * 800.0, s.y, 1e-3);
  }
}

TEST(Camera3D, FitLooksAtTheMiddleOfTheArea) {
  cv::Camera3D c;
  c.setViewport({1200.0, 800.0});
  const cv::Bounds3 box{{-1.0, -2.0, 0.0}, {3.0, 2.0, 1.0}};
  const cv::ScreenRect area{{300.0, 0.0}, {900.0, 800.0}};
  c.fit(box, area);
  const cv::Projected p = c.toScreen(box.middle());
  ASSERT_TRUE(p.visible());
  EXPECT_NEAR(p.screen.x, area.middle().x, 1e-6);
  EXPECT_NEAR(p.screen.y, area.middle().y, 1e-6);
  // every corner is on screen, inside the area
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 q{k & 1 ? box.hi.x : box.lo.x, k & 2 ? box.hi.y : box.lo.y,
                       k & 4 ? box.hi.z : box.lo.z};
    const cv::Projected s = c.toScreen(q);
    ASSERT_TRUE(s.visible());
    EXPECT_GE(s.screen.x, area.lo.x - 1e-6);
    EXPECT_LE(s.screen.x, area.hi.x + 1e-6);
    EXPECT_GE(s.screen.y, area.lo.y - 1e-6);
    EXPECT_LE(s.screen.y, area.hi.y + 1e-6);
  }
}

TEST(Camera3D, RayThroughAProjectedPointHitsIt) {
  cv::Camera3D c;
  c.setViewport({1000.0, 700.0});
  c.set({1.0, 2.0, 3.0}, 9.0, 0.8, 0.3);
  for (glm::dvec3 p :
       {glm::dvec3{1.0, 2.0, 3.0}, glm::dvec3{2.0, 1.5, 3.5}, glm::dvec3{0.0, 3.0, 2.0}}) {
    const cv::Projected s = c.toScreen(p);
    ASSERT_TRUE(s.visible());
    const cv::Ray3 r = c.rayThrough(s.screen);
    // the distance from p to the ray's line
    const glm::dvec3 d = p - r.origin;
    const double along = glm::dot(d, r.direction);
    EXPECT_GT(along, 0.0);
    EXPECT_NEAR(glm::length(d - along * r.direction), 0.0, 1e-9 * glm::length(d));
  }
}

TEST(Camera3D, OrbitKeepsDistanceAndTarget) {
  cv::Camera3D c;
  c.set({0.5, 0.5, 0.5}, 4.0, 0.1, 0.2);
  c.orbit({120.0, -40.0});
  EXPECT_DOUBLE_EQ(c.distance(), 4.0);
  EXPECT_NEAR(glm::length(c.eye() - c.target()), 4.0, 1e-12);
  // the view basis stays orthonormal
  EXPECT_NEAR(glm::dot(c.forward(), c.right()), 0.0, 1e-12);
  EXPECT_NEAR(glm::dot(c.forward(), c.up()), 0.0, 1e-12);
  EXPECT_NEAR(glm::length(c.up()), 1.0, 1e-12);
  // pitch stays short of the poles
  c.orbit({0.0, 10000.0});
  EXPECT_LT(std::abs(c.pitch()), 1.5708);
}
