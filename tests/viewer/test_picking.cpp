// Picking: the cell under a point by core's outlines, the vertex and the point near the cursor.
#include <gtest/gtest.h>

#include "convexloc/generate2d.hpp"
#include "convexloc/locate2d.hpp"
#include "logic/view/picking.hpp"

namespace cv = convexloc::viewer;
using convexloc::Vec2;

namespace {

convexloc::ConvexPolygon polygon() {
  const auto v = convexloc::generatePolygon(convexloc::PolygonKind::Random, 40, 3);
  return convexloc::ConvexPolygon(v);
}

// the mean of an outline's corners: inside a convex cell, away from its sides
Vec2 middleOf(const std::vector<Vec2>& outline) {
  Vec2 m{};
  for (Vec2 p : outline) {
    m.x += p.x / static_cast<double>(outline.size());
    m.y += p.y / static_cast<double>(outline.size());
  }
  return m;
}

}  // namespace

TEST(Picking, OutlineContainsIsClosed) {
  const std::vector<Vec2> square{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_TRUE(cv::outlineContains(square, {0.5, 0.5}));
  EXPECT_TRUE(cv::outlineContains(square, {1.0, 0.5}));
  EXPECT_TRUE(cv::outlineContains(square, {0.0, 0.0}));
  EXPECT_FALSE(cv::outlineContains(square, {1.0001, 0.5}));
  EXPECT_FALSE(cv::outlineContains(std::vector<Vec2>{{0, 0}, {1, 1}}, {0.5, 0.5}));
}

TEST(Picking, PolarCellUnderAPointIsTheOneCoreMapsItTo) {
  const auto poly = polygon();
  const convexloc::PolarLocator polar(poly, 6);
  const auto cells = polar.cells();
  ASSERT_EQ(cells.size(), 48u);
  for (const auto& c : cells) {
    const Vec2 m = middleOf(c.outline);
    const std::ptrdiff_t picked = cv::pickCell(cells, m);
    ASSERT_GE(picked, 0);
    EXPECT_EQ(cells[static_cast<std::size_t>(picked)].index, c.index);
    // and the cell core's own index function gives the same answer there
    EXPECT_EQ(polar.cellIndex(m), static_cast<std::int64_t>(c.index));
  }
}

TEST(Picking, UniformSlabUnderAPointMatchesItsYRange) {
  const auto poly = polygon();
  const convexloc::UniformLocator uniform(poly, 25);
  const auto cells = uniform.cells();
  ASSERT_EQ(cells.size(), 25u);
  const convexloc::Box2 b = poly.bounds();
  for (int k = 0; k < 25; ++k) {
    const double y = b.lo.y + (k + 0.5) * (b.hi.y - b.lo.y) / 25.0;
    const std::ptrdiff_t picked = cv::pickCell(cells, {0.5 * (b.lo.x + b.hi.x), y});
    ASSERT_GE(picked, 0);
    EXPECT_EQ(cells[static_cast<std::size_t>(picked)].index, static_cast<std::uint32_t>(k));
    EXPECT_EQ(uniform.slabOf(y), static_cast<std::uint32_t>(k));
  }
  // outside the box: no cell
  EXPECT_EQ(cv::pickCell(cells, {b.hi.x + 1.0, b.hi.y + 1.0}), -1);
}

TEST(Picking, WedgeFanTriangles) {
  const auto poly = polygon();
  const convexloc::WedgeLocator wedge(poly);
  const auto cells = wedge.cells();
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const std::ptrdiff_t picked = cv::pickCell(cells, middleOf(cells[i].outline));
    EXPECT_EQ(picked, static_cast<std::ptrdiff_t>(i));
  }
}

TEST(Picking, NearestVertexWithinTheRadius) {
  cv::Camera2D cam;
  cam.setViewport({800.0, 600.0});
  cam.set({0.0, 0.0}, 100.0);
  const std::vector<Vec2> v{{0, 0}, {1, 0}, {1, 1}, {0, 1}};
  EXPECT_EQ(cv::pickVertex(v, cam, cam.toScreen({1.03, 0.98}), 9.0), 2);
  EXPECT_EQ(cv::pickVertex(v, cam, cam.toScreen({0.5, 0.5}), 9.0), -1);
  EXPECT_EQ(cv::pickVertex(v, cam, cam.toScreen({0.0, 0.06}), 9.0), 0);
}

TEST(Picking, PointPickRespectsTheVisibleClasses) {
  cv::Camera2D cam;
  cam.setViewport({800.0, 600.0});
  cam.set({0.0, 0.0}, 100.0);
  using L = convexloc::Location;
  const std::vector<Vec2> pts{{0.0, 0.0}, {0.02, 0.0}, {2.0, 2.0}};
  const std::vector<L> cls{L::Inside, L::Outside, L::Inside};
  const glm::dvec2 cursor = cam.toScreen({0.019, 0.0});
  EXPECT_EQ(cv::pickPoint(pts, cls, cv::kAllClasses, cam, cursor, 5.0), 1);
  EXPECT_EQ(cv::pickPoint(pts, cls, cv::classBit(L::Inside), cam, cursor, 5.0), 0);
  EXPECT_EQ(cv::pickPoint(pts, cls, cv::classBit(L::Boundary), cam, cursor, 5.0), -1);
}
