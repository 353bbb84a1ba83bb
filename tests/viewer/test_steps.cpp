// The query step by step: the steps told for each method on known shapes (a regular
// octagon, a cube), the paper-faithful trace's edge test, the step cursor and player,
// --step and --paper, and numbers that never break across lines.
#include <gtest/gtest.h>

#include <algorithm>

#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "convexloc/generate3d.hpp"
#include "convexloc/locate2d.hpp"
#include "convexloc/locate3d.hpp"
#include "logic/app/model.hpp"
#include "logic/app/options.hpp"
#include "logic/base/format.hpp"
#include "logic/draw/structure2d.hpp"
#include "logic/draw/structure3d.hpp"
#include "logic/narration/steps.hpp"

namespace cv = convexloc::viewer;
using namespace convexloc;

namespace {

// the regular octagon of circumradius 1 from vertex (1, 0), its y mirror-symmetric in doubles
ConvexPolygon octagon() {
  const double r = std::sqrt(0.5);
  const double cosines[8] = {1, r, 0, -r, -1, -r, 0, r};  // sin(k pi/4) = cos((k - 2) pi/4)
  std::vector<Vec2> v;
  for (int k = 0; k < 8; ++k) v.push_back({cosines[k], cosines[(k + 6) % 8]});
  return ConvexPolygon(v);
}

// the captions of a step model
std::vector<std::string> captions(const cv::StepModel& m) {
  std::vector<std::string> out;
  for (const cv::Step& s : m.steps) out.push_back(s.caption);
  return out;
}

// the steps focused on `focus`
std::size_t countFocus(const cv::StepModel& m, cv::StepFocus focus) {
  std::size_t n = 0;
  for (const cv::Step& s : m.steps) n += s.focus == focus;
  return n;
}

// every caption and code line is one line
void expectOneLineEach(const cv::StepModel& m) {
  for (const cv::Step& s : m.steps) EXPECT_EQ(s.caption.find('\n'), std::string::npos) << s.caption;
  for (const std::string& c : m.code) EXPECT_EQ(c.find('\n'), std::string::npos) << c;
  ASSERT_FALSE(m.steps.empty());
  EXPECT_EQ(m.steps.back().focus, cv::StepFocus::Result);
  for (const cv::Step& s : m.steps) {
    EXPECT_GE(s.line, 0);
    EXPECT_LT(s.line, static_cast<int>(m.code.size()));
  }
}

}  // namespace

TEST(Steps, SlabShowsEachProbeOfTheBinarySearch) {
  const ConvexPolygon poly = octagon();
  const Vec2 p{0.1, 0.0};
  const cv::StepModel m = cv::buildSteps(SlabLocator(poly).trace(p), p, poly);
  expectOneLineEach(m);
  const std::vector<std::string> c = captions(m);
  ASSERT_GE(c.size(), 7u);
  EXPECT_EQ(c[0], "probe 1: y(2) = 0 <= x.y: go up");
  EXPECT_EQ(c[1], "probe 2: y(4) = 1 > x.y: go down");
  EXPECT_EQ(c[2], "probe 3: y(3) = 0.707107 > x.y: go down");
  EXPECT_EQ(c[3], "slab 2 (between y(2) and y(3))");
  // y(k) is the k-th of the sorted distinct vertex y, whatever vertex has it
  std::vector<double> ys;
  for (std::size_t i = 0; i < poly.size(); ++i) ys.push_back(poly.vertex(i).y);
  std::sort(ys.begin(), ys.end());
  ys.erase(std::unique(ys.begin(), ys.end()), ys.end());
  for (const convexloc::SlabProbe& probe : SlabLocator(poly).trace(p).probes)
    EXPECT_EQ(probe.y, ys.at(static_cast<std::size_t>(probe.rank)));
  EXPECT_EQ(m.steps[0].focus, cv::StepFocus::Search);
  EXPECT_EQ(m.steps[0].item, 2);
  EXPECT_EQ(m.steps[0].line, 1);
  EXPECT_EQ(m.steps[3].focus, cv::StepFocus::Cell);
  EXPECT_EQ(countFocus(m, cv::StepFocus::Edge), 2u);
  EXPECT_EQ(c.back(), "result: INSIDE");
}

TEST(Steps, SlabOutsideTheBoxStopsThere) {
  const ConvexPolygon poly = octagon();
  const Vec2 p{3.0, 0.0};
  const cv::StepModel m = cv::buildSteps(SlabLocator(poly).trace(p), p, poly);
  ASSERT_EQ(m.steps.size(), 2u);
  EXPECT_EQ(m.steps[0].focus, cv::StepFocus::Box);
  EXPECT_EQ(m.steps[1].caption, "result: OUTSIDE");
}

TEST(Steps, UniformShowsEquationFourWithItsNumbers) {
  const ConvexPolygon poly = octagon();
  const Vec2 p{0.0, 0.3};
  const cv::StepModel m = cv::buildSteps(UniformLocator(poly, 4).trace(p), p, poly);
  expectOneLineEach(m);
  ASSERT_GE(m.steps.size(), 3u);
  EXPECT_EQ(m.steps[0].caption, "eq. (4): floor((0.3 - -1) / 0.5) = floor(2.6)");
  EXPECT_EQ(m.steps[0].focus, cv::StepFocus::Index);
  EXPECT_EQ(m.steps[0].item, 2);
  EXPECT_EQ(m.steps[1].caption, "slab 2 of 4");
  EXPECT_NE(m.code[1].find("eq. 4"), std::string::npos);
}

TEST(Steps, PolarShowsTheOctantTheRatioAndTheSlab) {
  const ConvexPolygon poly = octagon();
  const PolarLocator polar(poly, 4);
  ASSERT_TRUE(polar.centre().has_value());
  const Vec2 c = *polar.centre();
  const Vec2 p{c.x + 0.5, c.y + 0.215};
  const Trace2D t = polar.trace(p);
  const cv::StepModel m = cv::buildSteps(t, p, poly);
  expectOneLineEach(m);
  ASSERT_GE(m.steps.size(), 3u);
  EXPECT_EQ(m.steps[0].caption.rfind("octant 0: d = x - x_T = (0.5,0.215", 0), 0u)
      << m.steps[0].caption;
  EXPECT_EQ(m.steps[0].focus, cv::StepFocus::Octant);
  EXPECT_EQ(m.steps[1].caption, "ratio |dy|/|dx| = 0.43: k = floor(4*0.43) = 1 -> cell 1");
  EXPECT_EQ(m.steps[1].item, 1);
  EXPECT_EQ(m.steps[1].line, 1);
  EXPECT_TRUE(m.note.empty());
}

TEST(Steps, PaperModePolarTestsAnEdgeWhereTheRadiiWouldDecide) {
  const ConvexPolygon poly = octagon();
  const PolarLocator polar(poly, 4);
  const Vec2 c = *polar.centre();
  const Vec2 p{c.x + 0.1, c.y + 0.05};  // near the centre: the radii decide "inside"
  const Trace2D filtered = polar.trace(p);
  ASSERT_TRUE(filtered.byRadius);
  const cv::StepModel fast = cv::buildSteps(filtered, p, poly);
  EXPECT_EQ(countFocus(fast, cv::StepFocus::Edge), 0u);
  EXPECT_EQ(countFocus(fast, cv::StepFocus::Radii), 1u);

  const Locator2D loc(poly, Method2D::Polar, 4);
  const Trace2D paper = loc.trace(p, TraceOptions{.radii = false});
  const cv::StepModel m = cv::buildSteps(paper, p, poly);
  expectOneLineEach(m);
  EXPECT_EQ(countFocus(m, cv::StepFocus::Radii), 0u);
  ASSERT_EQ(countFocus(m, cv::StepFocus::Edge), 1u);
  const cv::Step& edge = m.steps[m.steps.size() - 2];
  EXPECT_EQ(edge.caption, "edge 0: orient2d = +1 (inner side)");
  EXPECT_EQ(edge.line, 3);
  EXPECT_EQ(m.steps.back().caption, "result: INSIDE");
  EXPECT_FALSE(m.note.empty());
  EXPECT_NE(m.code[2].find("off"), std::string::npos);
}

TEST(Steps, HalfplaneAndWedgeListEveryPredicate) {
  const ConvexPolygon poly = octagon();
  const Vec2 p{0.2, 0.1};
  const Trace2D h = HalfplaneLocator(poly).trace(p);
  const cv::StepModel hm = cv::buildSteps(h, p, poly);
  expectOneLineEach(hm);
  EXPECT_EQ(hm.steps.size(), h.edges.size() + 1);
  EXPECT_EQ(hm.steps[0].caption, "edge 0: orient2d = +1 (inner side)");
  const Trace2D w = WedgeLocator(poly).trace(p);
  const cv::StepModel wm = cv::buildSteps(w, p, poly);
  expectOneLineEach(wm);
  EXPECT_EQ(countFocus(wm, cv::StepFocus::Ray), w.rays.size());
  EXPECT_EQ(wm.steps[1].caption, "ray v0->v1: +1 (counter-clockwise)");
  EXPECT_EQ(wm.steps[1].line, 1);
}

TEST(Steps, CubemapShowsTheCubeFaceAndTheCell) {
  const ConvexPolyhedron cube(generatePolyhedron(PolyhedronKind::Cube, 12, 1));
  const CubemapLocator cm(cube, 4);
  const Vec3 c = *cm.centre();
  const Vec3 p{c.x + 0.5, c.y + 0.1, c.z - 0.2};
  const cv::StepModel m = cv::buildSteps3D(cm.trace(p), p, 2.0);
  expectOneLineEach(m);
  ASSERT_GE(m.steps.size(), 3u);
  EXPECT_EQ(m.steps[0].caption, "d = x - x_T = (0.5,0.1,-0.2): cube face +x");
  EXPECT_EQ(m.steps[0].item, 0);
  EXPECT_EQ(m.steps[1].caption, "(s,t) = (0.2,-0.4) -> cell (2,1) of 4x4");
  // paper-faithful: a face test decides instead of the radii
  const Trace3D paper = cm.trace(p, {.radii = false});
  const cv::StepModel pm = cv::buildSteps3D(paper, p, 2.0);
  EXPECT_EQ(countFocus(pm, cv::StepFocus::Radii), 0u);
  EXPECT_GE(countFocus(pm, cv::StepFocus::Face), 1u);
  EXPECT_EQ(pm.steps.back().caption, "result: INSIDE");
}

TEST(Steps, CubemapShowsAZeroUpToRoundingAsZero) {
  const ConvexPolyhedron cube(generatePolyhedron(PolyhedronKind::Cube, 12, 1));
  const CubemapLocator cm(cube, 4);
  const Vec3 c = *cm.centre();
  // d_y is one ulp of x_T's y (or a denormal): 0 as d shows it, so 0 in (s,t) too
  const Vec3 p{c.x + 0.5, std::nextafter(c.y, -1.0), c.z - 0.2};
  ASSERT_NE(p.y - c.y, 0.0);
  const cv::StepModel m = cv::buildSteps3D(cm.trace(p), p, 2.0);
  ASSERT_GE(m.steps.size(), 2u);
  EXPECT_EQ(m.steps[0].caption, "d = x - x_T = (0.5,0,-0.2): cube face +x");
  EXPECT_EQ(m.steps[1].caption.rfind("(s,t) = (0,-0.4) -> cell (", 0), 0u) << m.steps[1].caption;
}

// a point the cell's slab decides between its radii: the slab's step says so, and no face
// test is listed
TEST(Steps, CubemapNamesTheSlabThatDecides) {
  const ConvexPolyhedron cyl(generatePolyhedron(PolyhedronKind::Cylinder, 256, 1));
  const CubemapLocator cm(cyl);
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1.2, 1.2);
  std::size_t found = 0;
  for (int k = 0; k < 20000 && found < 20; ++k) {
    const Vec3 p{u(rng), u(rng), u(rng)};
    const Trace3D t = cm.trace(p);
    if (!t.bySlab) continue;
    ++found;
    const cv::StepModel m = cv::buildSteps3D(t, p, 2.0);
    const std::string word = t.result == Location::Inside ? "inside" : "outside";
    EXPECT_NE(t.result, Location::Boundary);
    EXPECT_EQ(countFocus(m, cv::StepFocus::Face), 0u);
    ASSERT_GE(m.steps.size(), 4u);
    const std::string& radii = m.steps[2].caption;
    EXPECT_EQ(radii.substr(radii.size() - 9), ": between") << radii;
    EXPECT_EQ(m.steps[3].caption,
              "the cell's slab: n . d beyond its bounds: " + word + " with no face test");
  }
  EXPECT_GT(found, 0u);
}

TEST(Steps, WalkListsEveryEdgeTestItCounts) {
  const ConvexPolyhedron poly(generatePolyhedron(PolyhedronKind::Geodesic, 320, 2));
  const WalkLocator walk(poly);
  const Vec3 p{0.3, -0.4, 0.5};
  const Trace3D t = walk.trace(p);
  ASSERT_FALSE(t.steps.empty());
  const cv::StepModel m = cv::buildSteps3D(t, p, 2.0);
  expectOneLineEach(m);
  EXPECT_EQ(countFocus(m, cv::StepFocus::Walk), t.steps.size());
  EXPECT_EQ(countFocus(m, cv::StepFocus::Face), t.faces.size());
  // the inspector lists as many predicates as it counts
  const std::vector<cv::TraceLine> lines = cv::describeTrace3D(t, p, 2.0);
  std::size_t listed = 0;
  for (const cv::TraceLine& l : lines)
    listed += l.kind == cv::TraceLine::Positive || l.kind == cv::TraceLine::Negative ||
              l.kind == cv::TraceLine::Zero;
  const std::size_t counted = t.faces.size() + t.steps.size();
  EXPECT_EQ(listed, counted);
  std::string count = std::to_string(counted);
  count += " predicates)";
  EXPECT_NE(lines.back().text.find(count), std::string::npos) << lines.back().text;
}

TEST(Steps, NumbersNeverBreakAndTinyCentresReadZero) {
  const double values[] = {0.0,         -0.0,      -0.2791048542272344,
                           1e300,       -1e-300,   8.28e-21,
                           123456789.0, 1.0 / 3.0, std::numeric_limits<double>::infinity()};
  for (double v : values) {
    const std::string s = cv::compact(v);
    EXPECT_EQ(s.find(' '), std::string::npos) << s;
    EXPECT_EQ(s.find('\n'), std::string::npos) << s;
    EXPECT_LE(s.size(), 13u) << s;
  }
  EXPECT_EQ(cv::compact(-0.0), "0");
  EXPECT_EQ(cv::compact(-0.2791048542272344), "-0.279105");
  EXPECT_EQ(cv::compact(8.28e-21, 2.0), "0");
  EXPECT_EQ(cv::compact(8.28e-21), "8.28e-21");  // no scale: nothing snaps
  EXPECT_EQ(cv::compact(Vec3{8.28e-21, 0.0, 0.0}, 2.0), "(0,0,0)");
  // the 3D inspector's centre line
  Trace3D t;
  t.method = Method3D::Walk;
  t.centre = Vec3{8.28e-21, 0.0, 0.0};
  bool found = false;
  for (const cv::TraceLine& l : cv::describeTrace3D(t, {1, 0, 0}, 2.0))
    if (l.text.rfind("centre x_T", 0) == 0) {
      EXPECT_EQ(l.text, "centre x_T = (0,0,0)");
      found = true;
    }
  EXPECT_TRUE(found);
}

TEST(Steps, CursorClampsStepsAndPlays) {
  EXPECT_EQ(cv::clampStep(-1, 5), -1);
  EXPECT_EQ(cv::clampStep(2, 5), 2);
  EXPECT_EQ(cv::clampStep(99, 5), 4);
  EXPECT_EQ(cv::clampStep(3, 0), -1);
  EXPECT_EQ(cv::nextStep(-1, 5, true), 0);
  EXPECT_EQ(cv::nextStep(-1, 5, false), 4);
  EXPECT_EQ(cv::nextStep(4, 5, true), 4);
  EXPECT_EQ(cv::nextStep(0, 5, false), 0);
  cv::StepPlayer player;
  player.speed = 2.0f;
  int k = -1;
  player.start(k, 5, 10.0);
  EXPECT_EQ(k, 0);
  EXPECT_TRUE(player.playing);
  EXPECT_EQ(player.tick(k, 5, 10.4), 0);
  k = player.tick(k, 5, 10.6);
  EXPECT_EQ(k, 1);
  k = player.tick(k, 5, 20.0);
  EXPECT_EQ(k, 4);
  EXPECT_FALSE(player.playing);
}

TEST(Steps, StepAndPaperOptions) {
  auto parse = [](std::vector<std::string_view> a) { return cv::parseOptions(a); };
  EXPECT_EQ(parse({}).options.step, -1);
  EXPECT_FALSE(parse({}).options.paper);
  EXPECT_EQ(parse({"--step", "2"}).options.step, 2);
  EXPECT_EQ(parse({"--step", "-1"}).options.step, -1);
  EXPECT_TRUE(parse({"--paper"}).options.paper);
  EXPECT_FALSE(parse({"--step"}).error.empty());
  EXPECT_FALSE(parse({"--step", "two"}).error.empty());
  EXPECT_FALSE(parse({"--step", "-2"}).error.empty());
  EXPECT_NE(cv::usageText().find("--step K"), std::string::npos);
  EXPECT_NE(cv::usageText().find("--paper"), std::string::npos);
}

TEST(Steps, ModelAppliesStepAndPaperMode) {
  auto applied = [](std::vector<std::string_view> a, cv::Model& m) {
    const cv::ParsedOptions p = cv::parseOptions(a);
    ASSERT_TRUE(p.error.empty()) << p.error;
    EXPECT_EQ(m.apply(p.options), "");
  };
  cv::Model m;
  applied({"--generate", "regular", "--n", "8", "--method", "slab", "--probe", "0.3,0.55", "--step",
           "2"},
          m);
  ASSERT_TRUE(m.steps().has_value());
  EXPECT_EQ(m.step(), 1);  // --step counts from 1
  m.stepBy(true);
  EXPECT_EQ(m.step(), 2);
  cv::Model far;
  applied({"--generate", "regular", "--n", "8", "--method", "slab", "--probe", "0.3,0.55", "--step",
           "999"},
          far);
  EXPECT_EQ(far.step(), static_cast<int>(far.steps()->steps.size()) - 1);
  cv::Model all;
  applied({"--generate", "regular", "--n", "8", "--probe", "0.01,0.01", "--paper"}, all);
  EXPECT_EQ(all.step(), -1);
  EXPECT_TRUE(all.settings.paperMode);
  ASSERT_TRUE(all.scene2d.probe().has_value());
  EXPECT_FALSE(all.scene2d.probe()->trace.radiusFilter);
  EXPECT_FALSE(all.scene2d.probe()->trace.edges.empty());
  all.setPaperMode(false);
  EXPECT_TRUE(all.scene2d.probe()->trace.radiusFilter);
  EXPECT_TRUE(all.scene2d.probe()->trace.byRadius);
}

// the horizontal segments of a draw list at height y
static std::size_t linesAtY(const cv::DrawList& d, double y) {
  std::size_t n = 0;
  for (const cv::Segment& s : d.segments) n += s.a.y == y && s.b.y == y && s.a.x != s.b.x;
  return n;
}

TEST(Steps, OverlayDrawsTheCurrentProbeLine) {
  cv::Scene2D s;
  const ConvexPolygon poly = octagon();
  ASSERT_TRUE(s.setShape(poly.vertices(), "octagon"));
  s.setMethod(Method2D::Slab);
  s.place({0.1, 0.0});
  const cv::Palette& pal = cv::paletteFor(cv::Theme::Dark);
  cv::DrawList all, first, second;
  cv::buildOverlay2D(s, pal, {}, all);
  EXPECT_EQ(linesAtY(all, 1.0), 0u);  // the whole trace shows no probe lines
  const std::uint64_t before = s.versions().overlay;
  s.setStep(1);  // probe 2: y4 = 1
  EXPECT_GT(s.versions().overlay, before);
  cv::buildOverlay2D(s, pal, {}, second);
  EXPECT_GE(linesAtY(second, 1.0), 1u);
  s.setStep(0);  // probe 1: y2 = 0, not yet y4
  cv::buildOverlay2D(s, pal, {}, first);
  EXPECT_EQ(linesAtY(first, 1.0), 0u);
  EXPECT_GE(linesAtY(first, 0.0), 1u);
}

TEST(Steps, OverlayFillsTheFaceTestedAtThatStep) {
  cv::Scene3D s;
  ASSERT_TRUE(s.generate(PolyhedronKind::Cube, 12, 1));
  s.setMethod(Method3D::Halfspace);
  s.place({0.2, 0.1, -0.3});
  const cv::Palette& pal = cv::paletteFor(cv::Theme::Dark);
  cv::DrawList none, one;
  s.setStep(0);
  cv::buildOverlay3D(s, pal, {}, one);
  s.setStep(-1);
  cv::buildOverlay3D(s, pal, {}, none);
  ASSERT_TRUE(s.probe().has_value());
  ASSERT_FALSE(s.probe()->trace.faces.empty());
  // step 0 fills the first face tested (a square: two triangles), the full trace every face
  // tested
  EXPECT_EQ(one.fills.size(), 6u);
  EXPECT_EQ(none.fills.size(), 6 * s.probe()->trace.faces.size());
}

// the wedge's rays are labelled with the numbers the Steps window gives their tests (step 1
// is the fan, so the first ray is step 2, not ray 1)
TEST(Steps, WedgeRayLabelsCarryTheirStepNumbers) {
  cv::Scene2D s;
  const ConvexPolygon poly = octagon();
  ASSERT_TRUE(s.setShape(poly.vertices(), "octagon"));
  s.setMethod(Method2D::Wedge);
  s.place({0.1, 0.05});
  const cv::StepModel m = cv::buildSteps(s.probe()->trace, {0.1, 0.05}, poly);
  std::vector<std::string> expected;
  for (std::size_t i = 0; i < m.steps.size(); ++i)
    if (m.steps[i].focus == cv::StepFocus::Ray)
      expected.push_back(std::to_string(i + 1) + cv::signText(m.steps[i].sign));
  ASSERT_GE(expected.size(), 2u);
  EXPECT_NE(expected.front().rfind("1", 0), 0u);
  cv::DrawList all;
  cv::buildOverlay2D(s, cv::paletteFor(cv::Theme::Light), {}, all);
  for (const std::string& text : expected)
    EXPECT_TRUE(std::any_of(all.labels.begin(), all.labels.end(), [&](const cv::Label& l) {
      return l.text == text;
    })) << text;
}

// the polar query's first step highlights its octant without a second "octant K" label
TEST(Steps, PolarOctantStepNamesItsOctantOnce) {
  cv::Scene2D s;
  ASSERT_TRUE(s.setShape(octagon().vertices(), "octagon"));
  s.setMethod(Method2D::Polar);
  s.setTraceOptions({.radii = false});
  s.place({0.1, -0.6});
  s.setStep(0);
  const cv::Palette& pal = cv::paletteFor(cv::Theme::Light);
  cv::DrawList base, overlay;
  cv::buildStructure2D(s, pal, {}, base);
  cv::buildOverlay2D(s, pal, {}, overlay);
  const std::string name = "octant " + std::to_string(s.probe()->trace.octant);
  std::size_t seen = 0;
  for (const cv::DrawList* d : {&base, &overlay})
    seen += static_cast<std::size_t>(std::count_if(
        d->labels.begin(), d->labels.end(), [&](const cv::Label& l) { return l.text == name; }));
  EXPECT_EQ(seen, 1u);
}
