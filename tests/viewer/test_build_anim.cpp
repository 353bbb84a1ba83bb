// The build animation's counts, and the split view's second scene.
#include <gtest/gtest.h>

#include <vector>

#include "logic/scene/scene2d.hpp"
#include "logic/scene/scene3d.hpp"
#include "logic/scene/second_view.hpp"
#include "logic/teach/build_anim.hpp"

namespace cv = convexloc::viewer;
using convexloc::Method2D;
using convexloc::Vec2;

namespace {

// the counts the brief asks for, straight from the cells' lists
std::vector<std::size_t> listedBelow(const std::vector<convexloc::Cell2D>& cells, std::size_t k) {
  std::vector<std::size_t> counts;
  for (const convexloc::Cell2D& c : cells) {
    std::size_t n = 0;
    for (const std::uint32_t e : c.edges) n += e < k ? 1 : 0;
    counts.push_back(n);
  }
  return counts;
}

}  // namespace

TEST(BuildAnim, CountsAtEachStepAreTheListedEdgesBelowIt) {
  for (const Method2D m : {Method2D::Polar, Method2D::Uniform, Method2D::Slab}) {
    cv::Scene2D scene;
    scene.generate(convexloc::PolygonKind::Random, 40, 3);
    scene.setMethod(m);
    const auto& cells = scene.cells();
    ASSERT_FALSE(cells.empty());
    const cv::BuildOrder order(cells, scene.polygon().size());
    ASSERT_EQ(order.steps(), scene.polygon().size());
    for (std::size_t k = 0; k <= order.steps(); ++k)
      EXPECT_EQ(order.countsAt(k), listedBelow(cells, k)) << toString(m) << " step " << k;
    // at the last step every cell holds what core lists
    const std::vector<std::size_t> all = order.countsAt(order.steps());
    for (std::size_t c = 0; c < cells.size(); ++c) EXPECT_EQ(all[c], cells[c].edges.size());
  }
}

TEST(BuildAnim, CubeMapCellsReceiveTheirFaces) {
  cv::Scene3D scene;
  scene.setMethod(convexloc::Method3D::Cubemap);
  const auto& cells = scene.cells();
  ASSERT_FALSE(cells.empty());
  const std::size_t f = scene.polyhedron().faceCount();
  const cv::BuildOrder order(cells, f);
  ASSERT_EQ(order.steps(), f);
  ASSERT_EQ(cv::buildStepCount(scene), f);
  for (const std::size_t k : {std::size_t{0}, f / 3, f}) {
    const std::vector<std::size_t> counts = order.countsAt(k);
    for (std::size_t c = 0; c < cells.size(); ++c) {
      std::size_t n = 0;
      for (const std::uint32_t face : cells[c].faces) n += face < k ? 1 : 0;
      EXPECT_EQ(counts[c], n);
    }
  }
  cv::DrawList step;
  cv::buildAnimation3D(scene, 1, 0x3f, cv::paletteFor(cv::Theme::Dark), step);
  ASSERT_EQ(step.labels.size(), 1u);
  EXPECT_EQ(step.labels[0].text.rfind("f0 added: 1 of ", 0), 0u);
}

TEST(BuildAnim, EachEdgeFlashesInTheCellsListingIt) {
  cv::Scene2D scene;
  scene.setMethod(Method2D::Polar);
  const auto& cells = scene.cells();
  const cv::BuildOrder order(cells, scene.polygon().size());
  for (std::size_t e = 0; e < order.steps(); ++e)
    for (std::size_t c = 0; c < cells.size(); ++c) {
      const bool lists =
          std::find(cells[c].edges.begin(), cells[c].edges.end(), e) != cells[c].edges.end();
      const bool flashes =
          std::find(order.cellsOf(e).begin(), order.cellsOf(e).end(), c) != order.cellsOf(e).end();
      EXPECT_EQ(lists, flashes);
    }
}

TEST(BuildAnim, DrawsTheStepAndNothingWithoutCells) {
  cv::Scene2D scene;
  scene.setMethod(Method2D::Uniform);
  const cv::Palette& pal = cv::paletteFor(cv::Theme::Dark);
  cv::DrawList first, none;
  cv::buildAnimation2D(scene, 1, pal, first);
  EXPECT_FALSE(first.fills.empty());
  ASSERT_EQ(first.labels.size(), 1u);
  EXPECT_NE(first.labels[0].text.find("1 of " + std::to_string(scene.polygon().size())),
            std::string::npos);
  scene.setMethod(Method2D::Halfplane);
  cv::buildAnimation2D(scene, 3, pal, none);
  EXPECT_TRUE(none.empty());
}

TEST(BuildAnim, PlaybackAdvancesAndStopsAtTheEnd) {
  cv::BuildPlayback b;
  b.active = true;
  b.show(0, 10);
  b.playing = true;
  b.edgesPerSecond = 4.0;
  b.advance(0.5, 10);
  EXPECT_EQ(b.step, 2u);
  b.advance(100.0, 10);
  EXPECT_EQ(b.step, 10u);
  EXPECT_FALSE(b.playing);
  b.show(99, 10);
  EXPECT_EQ(b.step, 10u);
}

TEST(SplitView, SecondCellsEqualALocatorBuiltForThatMethod) {
  cv::Scene2D main;
  main.generate(convexloc::PolygonKind::Random, 24, 5);
  main.setMethod(Method2D::Halfplane);
  main.place({0.1, 0.2});
  cv::SecondView second;
  second.setEnabled(true);
  second.setMethod(Method2D::Polar);
  second.sync(main);
  const convexloc::Locator2D reference(main.polygon(), Method2D::Polar);
  const auto expected = reference.cells();
  const auto& got = second.scene().cells();
  ASSERT_EQ(got.size(), expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    EXPECT_EQ(got[i].edges, expected[i].edges);
    EXPECT_EQ(got[i].outline.size(), expected[i].outline.size());
  }
  // the same placed point, traced by the second method
  ASSERT_TRUE(second.scene().probe().has_value());
  EXPECT_EQ(second.scene().probe()->trace.method, Method2D::Polar);
  EXPECT_EQ(second.scene().probe()->trace.result, main.probe()->trace.result);
  EXPECT_EQ(cv::SecondView::traceCaption(main).rfind("halfplane: ", 0), 0u);
}

TEST(SplitView, FollowsTheShapeAndThePoint) {
  cv::Scene2D main;
  cv::SecondView second;
  second.setMethod(Method2D::Wedge);
  second.sync(main);
  main.generate(convexloc::PolygonKind::Regular, 12, 1);
  main.clearProbe();
  second.sync(main);
  EXPECT_EQ(second.scene().polygon().size(), 12u);
  EXPECT_FALSE(second.scene().probe().has_value());
  main.place({5.0, 5.0});
  second.sync(main);
  ASSERT_TRUE(second.scene().probe().has_value());
  EXPECT_EQ(second.scene().probe()->trace.result, convexloc::Location::Outside);
  // the hovered point follows; the cell under it is the second method's own
  main.hover(Vec2{0.1, 0.1});
  second.sync(main);
  ASSERT_TRUE(second.scene().hoverPoint().has_value());
  EXPECT_EQ(second.scene().hoverPoint()->x, 0.1);
  EXPECT_GE(second.scene().hoveredCell(), 0);
}

TEST(SplitView, HalvesAndTheRightCamera) {
  cv::SecondView v;
  v.setEnabled(true);
  v.setArea({{100.0, 0.0}, {900.0, 600.0}});
  EXPECT_EQ(v.left().hi.x, 500.0);
  EXPECT_EQ(v.right().lo.x, 500.0);
  cv::Camera2D cam;
  cam.setViewport({1000.0, 600.0});
  cam.set({0.0, 0.0}, 50.0);
  const cv::Camera2D right = v.rightCamera(cam);
  // the same world point sits 400 px further right
  EXPECT_NEAR(right.toScreen({1.0, 2.0}).x - cam.toScreen({1.0, 2.0}).x, 400.0, 1e-9);
  EXPECT_NEAR(v.toLeft(glm::dvec2(700.0, 10.0)).x, 300.0, 1e-9);
  EXPECT_NEAR(v.toLeft(glm::dvec2(300.0, 10.0)).x, 300.0, 1e-9);
  EXPECT_FALSE(v.stacked());
  EXPECT_EQ(v.divider()[0], glm::dvec2(500.0, 0.0));
  EXPECT_EQ(v.divider()[1], glm::dvec2(500.0, 600.0));
}

// an upright slide's room (a phone held upright): the halves one over the other, the second camera
// and the pointer moved down and up by half the area's height
TEST(SplitView, AnUprightAreaStacksTheHalves) {
  cv::SecondView v;
  v.setEnabled(true);
  v.setArea({{0.0, 100.0}, {400.0, 900.0}});
  EXPECT_FALSE(v.stacked());  // the live window keeps its halves side by side
  v.allowStacking(true);
  ASSERT_TRUE(v.stacked());
  EXPECT_EQ(v.left().hi, glm::dvec2(400.0, 500.0));
  EXPECT_EQ(v.right().lo, glm::dvec2(0.0, 500.0));
  EXPECT_EQ(v.divider()[0], glm::dvec2(0.0, 500.0));
  EXPECT_EQ(v.divider()[1], glm::dvec2(400.0, 500.0));
  cv::Camera2D cam;
  cam.setViewport({400.0, 1000.0});
  cam.set({0.0, 0.0}, 50.0);
  const cv::Camera2D lower = v.rightCamera(cam);
  const glm::dvec2 shift = lower.toScreen({1.0, 2.0}) - cam.toScreen({1.0, 2.0});
  EXPECT_NEAR(shift.x, 0.0, 1e-9);
  EXPECT_NEAR(shift.y, 400.0, 1e-9);
  EXPECT_EQ(v.toLeft(glm::dvec2(150.0, 700.0)), glm::dvec2(150.0, 300.0));
  EXPECT_EQ(v.toLeft(glm::dvec2(150.0, 300.0)), glm::dvec2(150.0, 300.0));
}
