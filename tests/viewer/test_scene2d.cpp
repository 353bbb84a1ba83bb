// The 2D scene's state transitions: shapes, methods, sprays, probes, drags, errors.
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

#include "convexloc/generate2d.hpp"
#include "logic/app/model.hpp"
#include "logic/base/format.hpp"
#include "logic/scene/presets.hpp"
#include "logic/scene/scene2d.hpp"

namespace cv = convexloc::viewer;
using convexloc::Location;
using convexloc::Method2D;
using convexloc::Vec2;

namespace {

// a file in the test's temporary directory with `text` in it
std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

const std::vector<Vec2> kSquare{{0, 0}, {2, 0}, {2, 2}, {0, 2}};

}  // namespace

TEST(Scene2D, DefaultSceneIsPolarWithAClassifiedSpray) {
  const cv::Scene2D s;
  EXPECT_EQ(s.method(), Method2D::Polar);
  EXPECT_GE(s.polygon().size(), 3u);
  EXPECT_FALSE(s.cells().empty());
  EXPECT_TRUE(s.centre().has_value());
  ASSERT_FALSE(s.points().empty());
  EXPECT_EQ(s.points().size(), s.classes().size());
  EXPECT_EQ(s.counts()[0] + s.counts()[1] + s.counts()[2], s.points().size());
  EXPECT_GT(s.counts()[static_cast<int>(Location::Inside)], 0u);
  EXPECT_GT(s.counts()[static_cast<int>(Location::Outside)], 0u);
  // every class is core's answer
  for (std::size_t i = 0; i < s.points().size(); i += 97)
    EXPECT_EQ(s.classes()[i], s.locator().locate(s.points()[i]));
}

TEST(Scene2D, InvalidShapeKeepsTheLastValidOne) {
  cv::Scene2D s;
  ASSERT_TRUE(s.setShape(kSquare, "square"));
  const auto versions = s.versions();
  const std::vector<Vec2> reflex{{0, 0}, {2, 0}, {1, 0.5}, {2, 2}, {0, 2}};
  EXPECT_FALSE(s.setShape(reflex, "arrow"));
  EXPECT_EQ(s.label(), "square");
  EXPECT_EQ(s.polygon().size(), 4u);
  EXPECT_NE(s.error().find("not convex"), std::string::npos) << s.error();
  EXPECT_EQ(s.versions().shape, versions.shape);
}

TEST(Scene2D, FileErrorsNameTheFileAndLine) {
  cv::Scene2D s;
  const std::string bad = writeTemp("viewer_bad.txt", "0 0\n1 0\n1 x\n");
  EXPECT_FALSE(s.loadFile(bad));
  EXPECT_NE(s.error().find(bad + ":3:"), std::string::npos) << s.error();
  const std::string reflex = writeTemp("viewer_reflex.txt", "0 0\n2 0\n1 0.5\n2 2\n0 2\n");
  EXPECT_FALSE(s.loadFile(reflex));
  EXPECT_NE(s.error().find(reflex + ":3:"), std::string::npos) << s.error();
  EXPECT_FALSE(s.loadFile(::testing::TempDir() + "no_such_file.txt"));
  EXPECT_NE(s.error().find("no_such_file.txt"), std::string::npos);
  const std::string good = writeTemp("viewer_good.txt", "# a triangle\n0 0\n1 0\n0 1\n");
  EXPECT_TRUE(s.loadFile(good));
  EXPECT_EQ(s.polygon().size(), 3u);
  EXPECT_EQ(s.label(), "viewer_good.txt");
}

TEST(Scene2D, MethodAndResolutionRebuildTheCells) {
  cv::Scene2D s;
  ASSERT_TRUE(s.setShape(kSquare, "square"));
  const auto v0 = s.versions().structure;
  s.setMethod(Method2D::Uniform);
  EXPECT_GT(s.versions().structure, v0);
  EXPECT_TRUE(s.setResolution(7));
  EXPECT_EQ(s.cells().size(), 7u);
  EXPECT_EQ(s.effectiveResolution(), 7u);
  s.setMethod(Method2D::Polar);
  EXPECT_TRUE(s.setResolution(3));
  EXPECT_EQ(s.cells().size(), 24u);
  s.setMethod(Method2D::Halfplane);
  EXPECT_TRUE(s.cells().empty());
  EXPECT_FALSE(s.centre().has_value());
  // each method keeps its own resolution
  s.setMethod(Method2D::Uniform);
  EXPECT_EQ(s.cells().size(), 7u);
  // a resolution core refuses keeps the locator and reports why
  EXPECT_FALSE(s.setResolution(1u << 30));
  EXPECT_EQ(s.cells().size(), 7u);
  EXPECT_FALSE(s.error().empty());
}

TEST(Scene2D, SprayCountsAndFilters) {
  cv::Scene2D s;
  ASSERT_TRUE(s.setShape(kSquare, "square"));
  s.spray({5000, 3, false});
  EXPECT_EQ(s.points().size(), 5000u);
  // the box grown by 10% on each side: the square covers 1/1.44 of it
  const double inside = static_cast<double>(s.counts()[0]) / 5000.0;
  EXPECT_NEAR(inside, 1.0 / 1.44, 0.05);
  s.spray({2000, 3, true});
  EXPECT_GT(s.counts()[static_cast<int>(Location::Boundary)], 0u);
  s.clearSpray();
  EXPECT_TRUE(s.points().empty());
  EXPECT_EQ(s.counts()[0] + s.counts()[1] + s.counts()[2], 0u);
}

TEST(Scene2D, PlacedPointCarriesCoresTrace) {
  cv::Scene2D s;
  ASSERT_TRUE(s.setShape(kSquare, "square"));
  for (Method2D m : convexloc::kAllMethods2D) {
    s.setMethod(m);
    s.place({1.0, 0.5});
    ASSERT_TRUE(s.probe());
    EXPECT_EQ(s.probe()->trace.result, Location::Inside);
    EXPECT_EQ(s.probe()->trace.method, m);
    s.place({2.0, 1.0});
    EXPECT_EQ(s.probe()->trace.result, Location::Boundary);
    s.place({3.0, 1.0});
    EXPECT_EQ(s.probe()->trace.result, Location::Outside);
  }
  // a new method traces the same point again
  s.setMethod(Method2D::Polar);
  EXPECT_EQ(s.probe()->trace.method, Method2D::Polar);
  s.clearProbe();
  EXPECT_FALSE(s.probe());
}

TEST(Scene2D, HoverFindsTheCellUnderTheCursor) {
  cv::Scene2D s;
  ASSERT_TRUE(s.setShape(kSquare, "square"));
  s.setMethod(Method2D::Uniform);
  ASSERT_TRUE(s.setResolution(4));
  s.hover(Vec2{1.0, 1.2});
  ASSERT_GE(s.hoveredCell(), 0);
  EXPECT_EQ(s.cells()[static_cast<std::size_t>(s.hoveredCell())].index, 2u);
  s.hover(Vec2{5.0, 5.0});
  EXPECT_EQ(s.hoveredCell(), -1);
  s.hover(std::nullopt);
  EXPECT_EQ(s.hoveredCell(), -1);
}

TEST(Scene2D, ValidDragMovesTheVertexAndKeepsThePoints) {
  cv::Scene2D s;
  ASSERT_TRUE(s.setShape(kSquare, "square"));
  s.spray({1000, 5, false});
  const std::vector<Vec2> before(s.points().begin(), s.points().end());
  s.beginDrag(2);
  EXPECT_TRUE(s.dragTo({3.0, 3.0}));
  ASSERT_TRUE(s.drag());
  EXPECT_FALSE(s.drag()->rejected);
  const auto v = s.polygon().vertices();
  EXPECT_NE(std::find(v.begin(), v.end(), Vec2{3.0, 3.0}), v.end());
  EXPECT_EQ(s.polygon().vertex(s.drag()->vertex), (Vec2{3.0, 3.0}));
  // the spray stays, classified against the edited polygon
  EXPECT_TRUE(std::equal(before.begin(), before.end(), s.points().begin()));
  for (std::size_t i = 0; i < before.size(); i += 37)
    EXPECT_EQ(s.classes()[i], s.locator().locate(before[i]));
  s.endDrag();
  EXPECT_FALSE(s.drag());
  EXPECT_TRUE(s.error().empty());
}

TEST(Scene2D, InvalidDragKeepsTheLastValidShapeAndSaysWhy) {
  cv::Scene2D s;
  ASSERT_TRUE(s.setShape(kSquare, "square"));
  s.beginDrag(2);
  ASSERT_TRUE(s.dragTo({2.5, 2.5}));
  const auto shape = s.versions().shape;
  // pulled inside: vertex 2 becomes reflex
  EXPECT_FALSE(s.dragTo({0.5, 0.5}));
  ASSERT_TRUE(s.drag());
  EXPECT_TRUE(s.drag()->rejected);
  EXPECT_FALSE(s.drag()->message.empty());
  EXPECT_EQ(s.versions().shape, shape);
  EXPECT_EQ(s.polygon().vertex(s.drag()->vertex), (Vec2{2.5, 2.5}));
  // onto its neighbours' segment from (2, 0) to (0, 2): the vertex would be dropped; refused
  EXPECT_FALSE(s.dragTo({1.0, 1.0}));
  EXPECT_TRUE(s.drag()->rejected);
  // releasing a rejected drag leaves the error for the user
  s.endDrag();
  EXPECT_NE(s.error().find("last valid shape"), std::string::npos) << s.error();
  EXPECT_EQ(s.polygon().size(), 4u);
}

TEST(Scene2D, ARefusedDragNamesTheVertexInShortestDigits) {
  cv::Scene2D s;
  ASSERT_TRUE(s.setShape(kSquare, "square"));
  s.beginDrag(2);
  // below the diagonal from (2, 0) to (0, 2): reflex
  EXPECT_FALSE(s.dragTo({0.1 + 0.2, 0.7}));
  ASSERT_TRUE(s.drag());
  const std::string& m = s.drag()->message;
  EXPECT_NE(m.find("vertex 2 (0.30000000000000004, 0.7)"), std::string::npos) << m;
  EXPECT_EQ(m.find("0.69999999999999996"), std::string::npos) << m;
  s.endDrag();
  EXPECT_EQ(s.error().find("0.69999999999999996"), std::string::npos) << s.error();
}

TEST(Format, ShortestCoordinatesRewritesOnlyNumberTuples) {
  EXPECT_EQ(cv::shortestCoordinates("reflex vertex 3 (0.10000000000000001, 2)"),
            "reflex vertex 3 (0.1, 2)");
  EXPECT_EQ(cv::shortestCoordinates("at (1.5, -2.0000000000000000, 3e-320) and (x, y)"),
            "at (1.5, -2, 3e-320) and (x, y)");
  EXPECT_EQ(cv::shortestCoordinates("(one) (1) (1, 2, 3, 4) (2,"), "(one) (1) (1, 2, 3, 4) (2,");
}

TEST(Format, ATypedNumberIsReadWholeOrRefused) {
  EXPECT_EQ(cv::parseNumber("0.1"), 0.1);
  EXPECT_EQ(cv::parseNumber(" -2.5e-3 "), -2.5e-3);
  EXPECT_EQ(cv::parseNumber("1e9"), 1e9);
  EXPECT_EQ(cv::parseNumber("0.30000000000000004"), 0.1 + 0.2);
  EXPECT_EQ(cv::parseNumber("4.9e-324"), 4.9e-324);  // the smallest subnormal reads
  EXPECT_EQ(cv::parseNumber("1.2,0.5"), std::nullopt);
  EXPECT_EQ(cv::parseNumber("0.5x"), std::nullopt);
  EXPECT_EQ(cv::parseNumber(""), std::nullopt);
  EXPECT_EQ(cv::parseNumber("inf"), std::nullopt);
  EXPECT_EQ(cv::parseNumber("nan"), std::nullopt);
  EXPECT_EQ(cv::parseNumber("0x10"), std::nullopt);
  EXPECT_EQ(cv::parseNumber("1e999"), std::nullopt);
}

TEST(Scene2D, CompareTimesEveryMethodAndTheyAgree) {
  cv::Scene2D s;
  s.spray({20000, 9, false});
  const auto rows = s.compare(0.02);
  ASSERT_EQ(rows.size(), 5u);
  for (const auto& r : rows) {
    EXPECT_GT(r.points, 0u);
    EXPECT_GT(r.nsPerPoint, 0.0);
    EXPECT_EQ(r.disagreements, 0u) << toString(r.method);
  }
}

TEST(Model, BadFilesKeepTheSceneAndReportTheError) {
  cv::Model m;
  const std::string label = m.scene2d.label();
  const auto serial = m.errorSerial();
  EXPECT_FALSE(m.open(::testing::TempDir() + "missing_polygon.txt"));
  EXPECT_GT(m.errorSerial(), serial);
  EXPECT_NE(m.error().find("missing_polygon.txt"), std::string::npos);
  EXPECT_EQ(m.scene2d.label(), label);
  const std::string good = writeTemp("viewer_open.txt", "0 0\n4 0\n4 1\n");
  EXPECT_TRUE(m.open(good));
  ASSERT_FALSE(m.recent.empty());
  EXPECT_EQ(m.recent.front(), good);
  EXPECT_TRUE(m.takeFitRequest());
  EXPECT_FALSE(m.takeFitRequest());
}

TEST(Model, EveryPlanarPresetBuildsWithEveryMethod) {
  for (const cv::Preset& p : cv::presets()) {
    if (p.solid) continue;
    cv::Model m;
    ASSERT_TRUE(m.applyPreset(p.name)) << p.name << ": " << m.error();
    for (Method2D method : convexloc::kAllMethods2D) {
      m.scene2d.setMethod(method);
      EXPECT_EQ(m.scene2d.method(), method) << p.name;
    }
  }
  cv::Model m;
  EXPECT_FALSE(m.applyPreset("no-such-preset"));
  EXPECT_NE(m.error().find("no-such-preset"), std::string::npos);
}

TEST(Model, CollinearAndDuplicatePresetIsNormalised) {
  cv::Model m;
  ASSERT_TRUE(m.applyPreset("collinear-duplicate"));
  EXPECT_EQ(m.scene2d.polygon().size(), 4u);
  EXPECT_GT(m.scene2d.polygon().droppedCount(), 0u);
}

TEST(Model, ApplyOptions) {
  cv::Options o;
  o.generate = "regular";
  o.n = 12;
  o.method = "uniform";
  o.resolution = 5;
  o.spray = 1234;
  o.seed = 4;
  o.show = "outside";
  o.probe = Vec2{0.0, 0.0};
  cv::Model m;
  EXPECT_EQ(m.apply(o), "");
  EXPECT_EQ(m.scene2d.polygon().size(), 12u);
  EXPECT_EQ(m.scene2d.method(), Method2D::Uniform);
  EXPECT_EQ(m.scene2d.cells().size(), 5u);
  EXPECT_EQ(m.scene2d.points().size(), 1234u);
  EXPECT_EQ(m.settings.visibleMask & cv::classBit(Location::Inside), 0u);
  ASSERT_TRUE(m.scene2d.probe());
  EXPECT_EQ(m.scene2d.probe()->trace.result, Location::Inside);
  cv::Options bad;
  bad.method = "telepathy";
  EXPECT_NE(m.apply(bad).find("telepathy"), std::string::npos);
}

TEST(Scene2D, ChosenResolutionsStayDefaultOnesGoWithTheDefaultShape) {
  cv::Scene2D s;
  EXPECT_EQ(s.resolution(), 8u);  // the default scene's polar slabs per octant
  ASSERT_TRUE(s.generate(convexloc::PolygonKind::Regular, 400, 1));
  EXPECT_EQ(s.resolution(), 0u);            // core's choice for a new shape
  EXPECT_EQ(s.effectiveResolution(), 25u);  // (400 + 15) / 16
  ASSERT_TRUE(s.setResolution(5));
  ASSERT_TRUE(s.generate(convexloc::PolygonKind::Regular, 60, 1));
  EXPECT_EQ(s.resolution(), 5u);
  // an edit keeps it too
  s.beginDrag(0);
  s.dragTo({1.2, 0.0});
  s.endDrag();
  EXPECT_EQ(s.resolution(), 5u);
}

TEST(Model, AskedViewReplacesTheFitOnce) {
  cv::Model m;
  cv::Options o;
  o.view = cv::AskedView{{1e9, -1e9}, 1e-6};
  m.apply(o);
  m.camera2d.setViewport({1000.0, 800.0});
  const cv::ScreenRect area{{200.0, 0.0}, {1000.0, 800.0}};
  m.fit(area);
  const glm::dvec2 mid = m.camera2d.toWorld(area.middle());
  EXPECT_NEAR(mid.x, 1e9, 1e-9 * 1e9);
  EXPECT_NEAR(mid.y, -1e9, 1e-9 * 1e9);
  EXPECT_NEAR(m.camera2d.scale(), 800.0 / 1e-6, 1e-3 * 800.0 / 1e-6);
  m.fit(area);  // the next fit is the shape's again
  EXPECT_LT(m.camera2d.scale(), 1e6);
}

TEST(Model, TheFitHoldsAPlacedPointNearThePolygon) {
  cv::Model m;
  m.camera2d.setViewport({1000.0, 800.0});
  const cv::ScreenRect area{{200.0, 0.0}, {1000.0, 800.0}};
  const convexloc::Box2 b = m.scene2d.polygon().bounds();
  // a point half a polygon above it (a slide's probe): in view after the fit
  const convexloc::Vec2 near{0.5 * (b.lo.x + b.hi.x), b.hi.y + 0.5 * (b.hi.y - b.lo.y)};
  m.scene2d.place(near);
  m.fit(area);
  const glm::dvec2 s = m.camera2d.toScreen({near.x, near.y});
  EXPECT_GE(s.x, area.lo.x);
  EXPECT_LE(s.x, area.hi.x);
  EXPECT_GE(s.y, area.lo.y);
  EXPECT_LE(s.y, area.hi.y);
  // one far away does not shrink the polygon to a dot
  m.scene2d.place({b.hi.x + 1e6, b.hi.y});
  m.fit(area);
  const glm::dvec2 lo = m.camera2d.toScreen({b.lo.x, b.lo.y});
  const glm::dvec2 hi = m.camera2d.toScreen({b.hi.x, b.hi.y});
  EXPECT_GT(std::abs(hi.x - lo.x), 300.0);
}
