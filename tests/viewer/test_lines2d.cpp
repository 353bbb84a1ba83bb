// The 2D Lines mode: the line's state follows core's LineIntersector, the dual inset maps
// the dual plane beside the polygon, the command line's --line turns the mode on.
#include <gtest/gtest.h>

#include <string>
#include <string_view>
#include <vector>

#include "convexloc/crossing.hpp"
#include "logic/app/interaction.hpp"
#include "logic/dual/lines2d.hpp"
#include "logic/app/model.hpp"
#include "logic/app/options.hpp"

namespace cv = convexloc::viewer;
using convexloc::Box2;
using convexloc::Crossing;
using convexloc::Vec2;

namespace {

const std::vector<Vec2> kSquare{{0, 0}, {2, 0}, {2, 2}, {0, 2}};

// a scene holding the square, and the Lines mode on over it
struct SquareLines {
  cv::Scene2D scene;
  cv::Lines2D lines;
  SquareLines() {
    EXPECT_TRUE(scene.setShape(kSquare, "square"));
    lines.setEnabled(true);
    lines.sync(scene);
  }
};

}  // namespace

TEST(Lines2D, OffUntilEnabledAndBuildsNothingMeanwhile) {
  cv::Scene2D scene;
  cv::Lines2D lines;
  EXPECT_FALSE(lines.enabled());
  lines.sync(scene);
  EXPECT_EQ(lines.intersector(), nullptr);
  EXPECT_TRUE(lines.setLine({0, 0}, {1, 1}));
  EXPECT_FALSE(lines.line().has_value());  // nothing to answer with yet
  lines.setEnabled(true);
  lines.sync(scene);
  ASSERT_NE(lines.intersector(), nullptr);
  EXPECT_TRUE(lines.line().has_value());  // the line asked is answered once built
}

TEST(Lines2D, ReportsCoresAnswersForCrossingTouchingMissing) {
  SquareLines s;
  ASSERT_TRUE(s.lines.setLine({-1, 1}, {3, 1}));
  const auto& crossing = s.lines.line();
  ASSERT_TRUE(crossing);
  EXPECT_EQ(crossing->hit.crossing, Crossing::Crosses);
  EXPECT_EQ(crossing->hit, s.lines.intersector()->intersect({-1, 1}, {3, 1}));
  ASSERT_TRUE(crossing->entry && crossing->exit && crossing->clipped);
  EXPECT_EQ(*crossing->entry, (Vec2{0, 1}));
  EXPECT_EQ(*crossing->exit, (Vec2{2, 1}));
  EXPECT_EQ(crossing->clipped->a, (Vec2{0, 1}));
  EXPECT_EQ(crossing->clipped->b, (Vec2{2, 1}));
  EXPECT_GE(crossing->trace.cell, 0);
  EXPECT_EQ(crossing->vertices, 4u);

  ASSERT_TRUE(s.lines.setLine({-1, 3}, {3, -1}));  // through (2, 0) and (0, 2): a diagonal
  EXPECT_EQ(s.lines.line()->hit.crossing, Crossing::Crosses);
  ASSERT_TRUE(s.lines.setLine({-1, 0}, {3, 0}));  // along the bottom edge
  EXPECT_EQ(s.lines.line()->hit.crossing, Crossing::Touches);
  ASSERT_TRUE(s.lines.setLine({-1, 1}, {1, 3}));  // through the corner (0, 2) only
  EXPECT_EQ(s.lines.line()->hit.crossing, Crossing::Touches);
  ASSERT_TRUE(s.lines.setLine({-1, 5}, {5, 5}));
  const auto& missing = s.lines.line();
  EXPECT_EQ(missing->hit.crossing, Crossing::Misses);
  EXPECT_FALSE(missing->entry);
  EXPECT_FALSE(missing->clipped);
}

TEST(Lines2D, EqualPointsAreIgnoredAndClearForgets) {
  SquareLines s;
  ASSERT_TRUE(s.lines.setLine({-1, 1}, {3, 1}));
  const auto v = s.lines.version();
  EXPECT_FALSE(s.lines.setLine({1, 1}, {1, 1}));
  EXPECT_EQ(s.lines.version(), v);
  ASSERT_TRUE(s.lines.line());
  s.lines.clearLine();
  EXPECT_FALSE(s.lines.line());
  EXPECT_GT(s.lines.version(), v);
}

TEST(Lines2D, FollowsTheShapeAndKeepsTheLine) {
  SquareLines s;
  ASSERT_TRUE(s.lines.setLine({-1, 3}, {5, 3}));
  EXPECT_EQ(s.lines.line()->hit.crossing, Crossing::Misses);
  const std::vector<Vec2> tall{{0, 0}, {2, 0}, {2, 4}, {0, 4}};
  ASSERT_TRUE(s.scene.setShape(tall, "tall"));
  s.lines.sync(s.scene);
  ASSERT_TRUE(s.lines.line());
  EXPECT_EQ(s.lines.line()->hit.crossing, Crossing::Crosses);
}

TEST(Lines2D, DualViewShowsCoresDualAndTheCellOfB) {
  SquareLines s;
  ASSERT_TRUE(s.lines.setLine({-1, 1}, {3, 1}));
  // the dual of a square: its four unit normals (antipodes coincide with them)
  EXPECT_EQ(s.lines.dualVertices().size(), 4u);
  EXPECT_FALSE(s.lines.dualCells().empty());
  const auto c = s.lines.dualCentre();
  const auto b = s.lines.dualPoint();
  ASSERT_TRUE(c && b);
  // b = c* + w / |w|_max with w = (0, 4), the line's normal
  EXPECT_EQ(*b, (Vec2{c->x, c->y + 1.0}));
  // core's cell for the line is the cell the dual locator puts b in
  EXPECT_EQ(s.lines.intersector()->dualLocator()->cellIndex(*b), s.lines.line()->trace.cell);
}

TEST(DualInset, SitsRightOfThePolygonAndMapsBothWays) {
  const Box2 bounds{{0, 0}, {4, 2}};
  const cv::DualInset in = cv::makeDualInset(bounds, {0.5, -0.25}, 1.2);
  // the primal frame holds the polygon; the inset is a square to its right, not touching
  EXPECT_LT(in.primal.lo.x, 0.0);
  EXPECT_GT(in.primal.hi.x, 4.0);
  EXPECT_GT(in.frame.lo.x, in.primal.hi.x);
  EXPECT_DOUBLE_EQ(in.frame.hi.x - in.frame.lo.x, in.frame.hi.y - in.frame.lo.y);
  // the dual square of half-side 1.2 around the middle fills the inset
  const glm::dvec2 mid = in.toWorld({0.5, -0.25});
  EXPECT_DOUBLE_EQ(mid.x, 0.5 * (in.frame.lo.x + in.frame.hi.x));
  EXPECT_DOUBLE_EQ(mid.y, 0.5 * (in.frame.lo.y + in.frame.hi.y));
  EXPECT_NEAR(in.toWorld({1.7, -0.25}).x, in.frame.hi.x, 1e-12);
  const Vec2 back = in.toDual(in.toWorld({0.9, 0.3}));
  EXPECT_NEAR(back.x, 0.9, 1e-12);
  EXPECT_NEAR(back.y, 0.3, 1e-12);
  const Box2 all = in.both();
  EXPECT_EQ(all.lo.x, in.primal.lo.x);
  EXPECT_EQ(all.hi.x, in.frame.hi.x);
}

TEST(Lines2D, InspectorTellsTheCellTheClimbAndTheAnswer) {
  SquareLines s;
  ASSERT_TRUE(s.lines.setLine({-1, 1}, {3, 1}));
  const auto lines = cv::describeLine(*s.lines.line(), s.lines.dualVertices(),
                                      s.lines.intersector()->dualLocator());
  std::string all;
  for (const cv::TraceLine& l : lines) all += l.text + "\n";
  EXPECT_NE(all.find("dual cell"), std::string::npos) << all;
  EXPECT_NE(all.find("proposes vertex"), std::string::npos) << all;
  EXPECT_NE(all.find("the line crosses"), std::string::npos) << all;
  EXPECT_NE(all.find("entry at edge 3 (3-0)"), std::string::npos) << all;
  EXPECT_NE(all.find("clipped"), std::string::npos) << all;
}

TEST(Lines2D, CommandLineTurnsTheModeOn) {
  const std::vector<std::string_view> args{"--line", "-3", "1", "3", "2"};
  const cv::ParsedOptions parsed = cv::parseOptions(args);
  ASSERT_TRUE(parsed.error.empty()) << parsed.error;
  ASSERT_TRUE(parsed.options.line);
  EXPECT_EQ(parsed.options.line->first, (Vec2{-3, 1}));
  EXPECT_EQ(parsed.options.line->second, (Vec2{3, 2}));
  cv::Model model;
  EXPECT_EQ(model.apply(parsed.options), "");
  EXPECT_TRUE(model.lines2d.enabled());
  ASSERT_TRUE(model.lines2d.line());
  EXPECT_EQ(model.lines2d.line()->p1, (Vec2{-3, 1}));

  for (const std::vector<std::string_view>& bad :
       {std::vector<std::string_view>{"--line", "1", "2", "3"},
        std::vector<std::string_view>{"--line", "1", "2", "1", "2"},
        std::vector<std::string_view>{"--line", "1", "x", "3", "4"}})
    EXPECT_FALSE(cv::parseOptions(bad).error.empty());
}

TEST(Lines2D, ADragInTheSceneDrawsTheLineAndAClickKeepsIt) {
  cv::Model m;
  ASSERT_TRUE(m.scene2d.setShape(kSquare, "square"));
  m.setLinesMode(true);
  m.camera2d.setViewport({1000.0, 800.0});
  m.fit({{0.0, 0.0}, {1000.0, 800.0}});
  cv::Interaction ia;
  const glm::dvec2 from{100.0, 400.0}, to{400.0, 380.0};
  cv::PointerInput in;
  in.pos = from;
  in.down[0] = in.pressed[0] = true;
  ia.update(in, m);
  EXPECT_EQ(ia.gesture(), cv::Interaction::Gesture::DrawLine);
  in.pressed[0] = false;
  in.delta = to - from;
  in.pos = to;
  ia.update(in, m);
  in.down[0] = false;
  in.released[0] = true;
  in.delta = {0.0, 0.0};
  ia.update(in, m);
  EXPECT_EQ(ia.gesture(), cv::Interaction::Gesture::None);
  ASSERT_TRUE(m.lines2d.line());
  const glm::dvec2 a = m.camera2d.toWorld(from), b = m.camera2d.toWorld(to);
  EXPECT_EQ(m.lines2d.line()->p1, (Vec2{a.x, a.y}));
  EXPECT_EQ(m.lines2d.line()->p2, (Vec2{b.x, b.y}));
  EXPECT_EQ(m.lines2d.line()->hit,
            m.lines2d.intersector()->intersect(m.lines2d.line()->p1, m.lines2d.line()->p2));
  // a click (no drag) keeps the line, and places no point
  cv::PointerInput click;
  click.pos = {500.0, 500.0};
  click.down[0] = click.pressed[0] = true;
  ia.update(click, m);
  click.down[0] = click.pressed[0] = false;
  click.released[0] = true;
  ia.update(click, m);
  EXPECT_EQ(m.lines2d.line()->p1, (Vec2{a.x, a.y}));
  EXPECT_FALSE(m.scene2d.probe());
  // turned off, a drag pans again
  m.setLinesMode(false);
  in = {};
  in.pos = from;
  in.down[0] = in.pressed[0] = true;
  ia.update(in, m);
  EXPECT_EQ(ia.gesture(), cv::Interaction::Gesture::Pending);
}

TEST(Lines2D, FitHoldsBothFramesAndTheGivenLine) {
  cv::Model m;
  cv::Options o;
  o.line = std::pair<Vec2, Vec2>{{-40.0, 0.0}, {40.0, 1.0}};
  EXPECT_EQ(m.apply(o), "");
  m.camera2d.setViewport({1000.0, 800.0});
  m.fit({{0.0, 0.0}, {1000.0, 800.0}});
  const cv::DualInset& in = m.lines2d.inset();
  EXPECT_LE(in.primal.lo.x, -40.0);
  for (const glm::dvec2 corner :
       {glm::dvec2{in.primal.lo.x, in.primal.lo.y}, glm::dvec2{in.frame.hi.x, in.frame.hi.y}}) {
    const glm::dvec2 px = m.camera2d.toScreen(corner);
    EXPECT_GE(px.x, -0.5);
    EXPECT_LE(px.x, 1000.5);
    EXPECT_GE(px.y, -0.5);
    EXPECT_LE(px.y, 800.5);
  }
}
