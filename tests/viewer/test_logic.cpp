// Colours, options, draw lists, words and mouse gestures.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <string>
#include <string_view>
#include <vector>

#include "logic/app/interaction.hpp"
#include "logic/app/model.hpp"
#include "logic/app/options.hpp"
#include "logic/base/colour.hpp"
#include "logic/base/format.hpp"
#include "logic/draw/structure2d.hpp"

namespace cv = convexloc::viewer;
using convexloc::Location;
using convexloc::Method2D;
using convexloc::Vec2;

namespace {

// relative luminance, for telling colours apart without hue
double luminance(cv::Rgba c) {
  return 0.2126 * c.r + 0.7152 * c.g + 0.0722 * c.b;
}

cv::ParsedOptions parse(std::vector<std::string_view> args) {
  return cv::parseOptions(args);
}

}  // namespace

// === Colours

TEST(Colour, ClassesHaveDistinctColoursInBothThemes) {
  for (cv::Theme t : {cv::Theme::Dark, cv::Theme::Light}) {
    const cv::Palette& p = cv::paletteFor(t);
    const cv::Rgba in = cv::colourOf(p, Location::Inside), on = cv::colourOf(p, Location::Boundary),
                   out = cv::colourOf(p, Location::Outside);
    EXPECT_NE(in, on);
    EXPECT_NE(in, out);
    EXPECT_NE(on, out);
    // told apart by lightness too, not only by hue (colour-blind viewers)
    EXPECT_GT(std::abs(luminance(in) - luminance(out)), 0.05);
    EXPECT_GT(luminance(on), luminance(in));
    // inside and outside stand out from the background; boundary points carry a dark rim
    for (cv::Rgba c : {in, out}) EXPECT_GT(std::abs(luminance(c) - luminance(p.background)), 0.25);
    EXPECT_GT(luminance(on) - luminance(p.rim), 0.5);
  }
}

TEST(Colour, CellTintGrowsWithExtraEdges) {
  const cv::Palette& p = cv::paletteFor(cv::Theme::Dark);
  EXPECT_EQ(cv::cellTint(p, 1, 1, false).a, 0.0f);
  EXPECT_EQ(cv::cellTint(p, 2, 2, false).a, 0.0f);
  const float a2 = cv::cellTint(p, 2, 1, false).a, a3 = cv::cellTint(p, 3, 1, false).a;
  EXPECT_GT(a2, 0.0f);
  EXPECT_GT(a3, a2);
  EXPECT_EQ(cv::cellTint(p, 50, 1, false).a, cv::cellTint(p, 60, 1, false).a);  // capped
  EXPECT_EQ(cv::withAlpha(cv::cellTint(p, 9, 1, true), 1.0f), cv::withAlpha(p.crowded, 1.0f));
}

TEST(Colour, PackAndHex) {
  EXPECT_EQ(cv::packAbgr(cv::hex(0x112233, 1.0f)), 0xFF332211u);
  EXPECT_EQ(cv::packAbgr({2.0f, -1.0f, 0.5f, 0.0f}), 0x008000FFu);
  const cv::Rgba m = cv::mix(cv::hex(0x000000), cv::hex(0xffffff), 0.5f);
  EXPECT_FLOAT_EQ(m.g, 0.5f);
}

// === Options

TEST(Options, ParsesTheSceneFlags) {
  const auto r =
      parse({"shape.txt", "--method",        "wedge",        "--spray",   "1e6",      "--seed",
             "7",         "--near-boundary", "--screenshot", "out.png",   "--frames", "5",
             "--size",    "1024x768",        "--theme",      "light",     "--probe",  "0.5,-1e-3",
             "--show",    "inside",          "--hide-ui",    "--samples", "0"});
  ASSERT_EQ(r.error, "");
  const cv::Options& o = r.options;
  EXPECT_EQ(o.shape, "shape.txt");
  EXPECT_EQ(o.method, "wedge");
  EXPECT_EQ(o.spray, 1000000u);
  EXPECT_EQ(o.seed, 7u);
  EXPECT_TRUE(o.nearBoundary);
  EXPECT_EQ(o.screenshot, "out.png");
  EXPECT_EQ(o.frames, 5);
  EXPECT_EQ(o.width, 1024);
  EXPECT_EQ(o.height, 768);
  EXPECT_EQ(o.theme, cv::Theme::Light);
  ASSERT_TRUE(o.probe);
  EXPECT_EQ(o.probe->y, -1e-3);
  EXPECT_TRUE(o.hideUi);
  EXPECT_EQ(o.samples, 0);
}

TEST(Options, RejectsWhatItCannotUse) {
  EXPECT_NE(parse({"--size", "1024"}).error, "");
  EXPECT_NE(parse({"--size", "10x10"}).error, "");
  EXPECT_NE(parse({"--spray", "-3"}).error, "");
  EXPECT_NE(parse({"--spray", "1e9"}).error, "");
  EXPECT_NE(parse({"--frames"}).error, "");
  EXPECT_NE(parse({"--probe", "1;2"}).error, "");
  EXPECT_NE(parse({"--theme", "purple"}).error, "");
  EXPECT_NE(parse({"--bogus"}).error, "");
  EXPECT_NE(parse({"a.txt", "b.txt"}).error, "");
  EXPECT_NE(parse({"a.txt", "--preset", "sliver"}).error, "");
  EXPECT_EQ(parse({}).error, "");
  EXPECT_TRUE(parse({"--help"}).options.help);
  EXPECT_NE(cv::usageText().find("--screenshot"), std::string::npos);
}

// one declaration: every option --help lists is one the parser knows (a missing value says
// what it needs, never "unknown option"), and the lecture keys the run refuses are its own
TEST(Options, HelpParserAndLectureKeysShareOneDeclaration) {
  const std::string help = cv::usageText();
  for (const char* name : {"--method", "--resolution", "--probe", "--line", "--plane", "--slice",
                           "--cell", "--step", "--figure", "--lecture", "--theme", "--caption",
                           "--size", "--why-max", "--split", "--build-step", "--screenshot"}) {
    EXPECT_NE(help.find(name), std::string::npos) << name;
    const std::string error = parse({name}).error;
    EXPECT_EQ(error.rfind(std::string(name) + " needs ", 0), 0u) << error;
  }
  // an option's values go in where it stands: the later one wins
  EXPECT_EQ(parse({"--method", "slab", "--method", "polar"}).options.method, "polar");
  EXPECT_EQ(parse({"--line", "-3", "1", "3", "2"}).options.line->first.x, -3.0);
  EXPECT_TRUE(cv::setsTheRun("size"));
  EXPECT_TRUE(cv::setsTheRun("export"));
  EXPECT_FALSE(cv::setsTheRun("method"));
  EXPECT_FALSE(cv::setsTheRun("why-svg"));
  EXPECT_FALSE(cv::setsTheRun("wobble"));
}

// === Draw lists

TEST(Structure2D, PolarDrawsItsRaysOctantsAndCentre) {
  cv::Scene2D s;
  ASSERT_TRUE(s.setShape(std::vector<Vec2>{{0, 0}, {4, 0}, {4, 3}, {0, 3}}, "box"));
  s.setMethod(Method2D::Polar);
  ASSERT_TRUE(s.setResolution(5));
  cv::DrawList d;
  cv::View2DOptions opt;
  const cv::Palette& pal = cv::paletteFor(cv::Theme::Dark);
  cv::buildStructure2D(s, pal, opt, d);
  std::size_t octant = 0, rays = 0, edges = 0;
  for (const cv::Segment& seg : d.segments) {
    if (seg.colour == pal.octant) ++octant;
    if (seg.colour == pal.structure) ++rays;
    if (seg.colour == pal.polygonEdge) ++edges;
  }
  EXPECT_EQ(octant, 8u);
  EXPECT_EQ(rays, 40u - 8u);
  EXPECT_EQ(edges, 4u);
  ASSERT_FALSE(d.markers.empty());
  EXPECT_EQ(d.markers.front().shape, cv::MarkerShape::Cross);
  // the structure's switches take things away
  opt.showStructure = false;
  opt.showBox = false;
  cv::buildStructure2D(s, pal, opt, d);
  EXPECT_EQ(d.segments.size(), 4u);
}

TEST(Structure2D, OverlayShowsTheTraceAndTheHoveredCell) {
  cv::Scene2D s;
  ASSERT_TRUE(s.setShape(std::vector<Vec2>{{0, 0}, {4, 0}, {4, 3}, {0, 3}}, "box"));
  s.setMethod(Method2D::Halfplane);
  s.place({5.0, 1.0});
  cv::DrawList d;
  const cv::Palette& pal = cv::paletteFor(cv::Theme::Light);
  cv::buildOverlay2D(s, pal, {}, d);
  // the edges tested, coloured by sign: edge 0 inner (+), edge 1 outer (-), then it stops
  std::size_t plus = 0, minus = 0;
  for (const cv::Segment& seg : d.segments) {
    plus += seg.colour == pal.positive;
    minus += seg.colour == pal.negative;
  }
  EXPECT_EQ(plus, 1u);
  EXPECT_EQ(minus, 1u);
  ASSERT_FALSE(d.markers.empty());
  EXPECT_EQ(d.markers.back().colour, pal.outside);
  s.setMethod(Method2D::Uniform);
  s.clearProbe();
  s.hover(Vec2{2.0, 1.0});
  cv::buildOverlay2D(s, pal, {}, d);
  EXPECT_FALSE(d.fills.empty());
  bool bold = false;
  for (const cv::Segment& seg : d.segments) bold |= seg.colour == pal.hoverEdge && seg.width > 4.0f;
  EXPECT_TRUE(bold);
}

TEST(Structure2D, ClipLineToBox) {
  glm::dvec2 p, q;
  const convexloc::Box2 box{{0, 0}, {10, 10}};
  ASSERT_TRUE(cv::clipLineToBox({1, 1}, {2, 2}, box, p, q));
  EXPECT_NEAR(p.x, 0.0, 1e-12);
  EXPECT_NEAR(q.y, 10.0, 1e-12);
  ASSERT_TRUE(cv::clipLineToBox({3, 5}, {4, 5}, box, p, q));  // horizontal
  EXPECT_NEAR(p.x, 0.0, 1e-12);
  EXPECT_NEAR(q.x, 10.0, 1e-12);
  EXPECT_FALSE(cv::clipLineToBox({0, 20}, {1, 20}, box, p, q));
}

// === Words

TEST(Text, ExactNumbersReadBack) {
  for (double v : {0.1, 1e9 + 0.5, -2.5e-300, 1.0 / 3.0}) {
    const std::string s = convexloc::exactText(v);
    double back = 0.0;
    std::from_chars(s.data(), s.data() + s.size(), back);
    EXPECT_EQ(back, v) << s;
  }
  EXPECT_EQ(convexloc::exactText(Vec2{1.0, -0.5}), "(1, -0.5)");
  EXPECT_EQ(cv::grouped(1234567), "1 234 567");
  EXPECT_EQ(cv::grouped(12), "12");
  EXPECT_EQ(convexloc::binarySize(512), "512 B");
}

TEST(Text, TraceIsToldStepByStep) {
  cv::Scene2D s;
  ASSERT_TRUE(s.setShape(std::vector<Vec2>{{0, 0}, {4, 0}, {4, 3}, {0, 3}}, "box"));
  s.setMethod(Method2D::Polar);
  s.place({1.0, 1.0});
  const auto lines = cv::describeTrace(s.probe()->trace, s.probe()->point, s.polygon());
  ASSERT_GE(lines.size(), 4u);
  EXPECT_EQ(lines.front().kind, cv::TraceLine::Heading);
  EXPECT_EQ(lines.back().kind, cv::TraceLine::Result);
  EXPECT_NE(lines.back().text.find("INSIDE"), std::string::npos);
  bool octant = false, radii = false;
  for (const auto& l : lines) {
    octant |= l.text.find("octant") != std::string::npos;
    // (1, 1) is nearer the centre (2, 1.5) than the box's sides: the radius decides
    radii |= l.text.find("cell radii") != std::string::npos &&
             l.text.find("inside with no test") != std::string::npos;
  }
  EXPECT_TRUE(octant);
  EXPECT_TRUE(radii);
}

// === Gestures

namespace {

cv::Model fittedModel() {
  cv::Model m;
  m.scene2d.setShape(std::vector<Vec2>{{0, 0}, {4, 0}, {4, 3}, {0, 3}}, "box");
  m.camera2d.setViewport({1000.0, 800.0});
  m.fit({{0.0, 0.0}, {1000.0, 800.0}});
  return m;
}

cv::PointerInput at(glm::dvec2 pos) {
  cv::PointerInput in;
  in.pos = pos;
  return in;
}

}  // namespace

TEST(Interaction, NothingMovesWhileImGuiWantsTheMouse) {
  cv::Model m = fittedModel();
  cv::Interaction ia;
  const double scale = m.camera2d.scale();
  const glm::dvec2 centre = m.camera2d.centre();
  cv::PointerInput in = at({500.0, 400.0});
  in.captured = true;
  in.wheel = 3.0;
  in.pressed[0] = in.down[0] = true;
  ia.update(in, m);
  in.pressed[0] = false;
  in.pos += glm::dvec2(50.0, 20.0);
  in.delta = {50.0, 20.0};
  ia.update(in, m);
  EXPECT_EQ(m.camera2d.scale(), scale);
  EXPECT_EQ(m.camera2d.centre(), centre);
  EXPECT_FALSE(m.scene2d.probe());
}

TEST(Interaction, WheelZoomsAtTheCursor) {
  cv::Model m = fittedModel();
  cv::Interaction ia;
  cv::PointerInput in = at({700.0, 250.0});
  const glm::dvec2 before = m.camera2d.toWorld(in.pos);
  in.wheel = 2.0;
  ia.update(in, m);
  const glm::dvec2 after = m.camera2d.toWorld(in.pos);
  EXPECT_NEAR(after.x, before.x, 1e-9);
  EXPECT_NEAR(after.y, before.y, 1e-9);
  EXPECT_GT(m.camera2d.scale(), 1.4);
}

// a pinch zooms about its centre and pans even where ImGui has the mouse (over a panel)
TEST(Interaction, PinchZoomsAboutItsCentreAndPansOverAPanel) {
  cv::Model m = fittedModel();
  cv::Interaction ia;
  cv::PointerInput in = at({300.0, 600.0});
  in.captured = true;
  const glm::dvec2 before = m.camera2d.toWorld(in.pos);
  const double scale = m.camera2d.scale();
  in.zoom = 1.5;
  ia.update(in, m);
  const glm::dvec2 after = m.camera2d.toWorld(in.pos);
  EXPECT_NEAR(after.x, before.x, 1e-9);
  EXPECT_NEAR(after.y, before.y, 1e-9);
  EXPECT_NEAR(m.camera2d.scale(), 1.5 * scale, 1e-9 * scale);
  in.zoom = 1.0;
  in.pan = {40.0, -10.0};
  ia.update(in, m);
  const glm::dvec2 moved = m.camera2d.toScreen(before);
  EXPECT_NEAR(moved.x, in.pos.x + 40.0, 1e-6);
  EXPECT_NEAR(moved.y, in.pos.y - 10.0, 1e-6);
  EXPECT_FALSE(m.scene2d.probe());
}

TEST(Interaction, ClickPlacesDragPans) {
  cv::Model m = fittedModel();
  cv::Interaction ia;
  // a click on empty space inside the polygon
  const glm::dvec2 p = m.camera2d.toScreen({1.0, 1.5});
  cv::PointerInput in = at(p);
  in.pressed[0] = in.down[0] = true;
  ia.update(in, m);
  in = at(p);
  in.released[0] = true;
  ia.update(in, m);
  ASSERT_TRUE(m.scene2d.probe());
  EXPECT_EQ(m.scene2d.probe()->trace.result, Location::Inside);
  // a drag pans and places nothing new
  m.scene2d.clearProbe();
  // (from the middle of the left edge, away from the vertex handles)
  const glm::dvec2 w = m.camera2d.toWorld({100.0, 400.0});
  in = at({100.0, 400.0});
  in.pressed[0] = in.down[0] = true;
  ia.update(in, m);
  for (int k = 1; k <= 10; ++k) {
    in = at({100.0 + 10.0 * k, 400.0});
    in.delta = {10.0, 0.0};
    in.down[0] = true;
    ia.update(in, m);
  }
  in = at({200.0, 400.0});
  in.released[0] = true;
  ia.update(in, m);
  EXPECT_FALSE(m.scene2d.probe());
  const glm::dvec2 s = m.camera2d.toScreen(w);
  EXPECT_NEAR(s.x, 200.0, 1e-9);
  EXPECT_NEAR(s.y, 400.0, 1e-9);
}

TEST(Interaction, DraggingAVertexHandleEditsThePolygon) {
  cv::Model m = fittedModel();
  cv::Interaction ia;
  const glm::dvec2 corner = m.camera2d.toScreen({4.0, 3.0});
  cv::PointerInput in = at(corner + glm::dvec2(2.0, 2.0));
  in.pressed[0] = in.down[0] = true;
  ia.update(in, m);
  EXPECT_EQ(ia.gesture(), cv::Interaction::Gesture::DragVertex);
  const glm::dvec2 to = m.camera2d.toScreen({5.0, 4.0});
  in = at(to);
  in.delta = to - corner;
  in.down[0] = true;
  ia.update(in, m);
  in = at(to);
  in.released[0] = true;
  ia.update(in, m);
  EXPECT_EQ(ia.gesture(), cv::Interaction::Gesture::None);
  const auto v = m.scene2d.polygon().vertices();
  bool moved = false;
  for (Vec2 q : v) moved |= std::abs(q.x - 5.0) < 1e-9 && std::abs(q.y - 4.0) < 1e-9;
  EXPECT_TRUE(moved);
}

TEST(Colour, LabelsOnTheLightThemeReadWhileMarkersKeepTheLegendsYellow) {
  const cv::Palette& light = cv::paletteFor(cv::Theme::Light);
  const cv::Palette& dark = cv::paletteFor(cv::Theme::Dark);
  // the bright yellow on the light background is unreadable as text ...
  EXPECT_LT(cv::contrastRatio(light.boundary, light.background), 2.0f);
  // ... and reads once made readable, still a yellow (red and green over blue)
  const cv::Rgba text = cv::readableOn(light.boundary, light.background, light.text);
  EXPECT_GE(cv::contrastRatio(text, light.background), 4.0f);
  EXPECT_GT(text.r, text.b + 0.15f);
  EXPECT_GT(text.g, text.b + 0.15f);
  EXPECT_EQ(cv::textColourOf(light, Location::Boundary),
            cv::readableOn(light.zero, light.background, light.text));
  EXPECT_GE(cv::contrastRatio(cv::textColourOf(light, Location::Boundary), light.background), 4.0f);
  // the marker colour itself is left as the legend shows it
  EXPECT_EQ(cv::colourOf(light, Location::Boundary), light.boundary);
  // a colour that already reads is left alone (the dark theme's yellow)
  EXPECT_EQ(cv::readableOn(dark.boundary, dark.background, dark.text), dark.boundary);
}
