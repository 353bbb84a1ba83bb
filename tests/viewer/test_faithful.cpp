// The drawing faithful to the shape and to the text: the font holds every glyph the
// captions use, radii stay in their cells, labels sit beside their own vertex, a polyhedron
// reports its plane faces.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

#include "logic/app/legend.hpp"
#include "logic/app/model.hpp"
#include "logic/base/glyphs.hpp"
#include "logic/draw/radii_arc.hpp"
#include "logic/draw/section_polygon.hpp"
#include "logic/draw/structure2d.hpp"
#include "logic/draw/zoom_inset.hpp"
#include "logic/scene/scene2d.hpp"
#include "logic/scene/scene3d.hpp"
#include "logic/teach/build_anim.hpp"
#include "logic/view/camera2d.hpp"
#include "logic/view/camera3d.hpp"
#include "logic/view/scene_labels.hpp"

namespace cv = convexloc::viewer;
using convexloc::Vec2;

namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

TEST(Glyphs, TheFontHoldsTheCaptionsMathematics) {
  EXPECT_EQ(cv::firstMissingGlyph("⌊ ⌋ ∈ ≤ ≥ × → ≈ ∞ ∑ √ · – — ° ² ½ x_T"), std::nullopt);
  EXPECT_EQ(cv::firstMissingGlyph("i = ⌊q·tan φ⌋, θ ∈ [0, π)"), std::nullopt);
  EXPECT_EQ(cv::firstMissingGlyph("slab 日"), U'日');
  EXPECT_EQ(cv::firstMissingGlyph(std::string("bad \xC3")), U'\uFFFD');
}

TEST(Glyphs, EveryCharacterOfTheShippedLectureIsInTheFont) {
  const std::string text = readFile(CONVEXLOC_SOURCE_DIR "/assets/lectures/paper.lecture");
  ASSERT_FALSE(text.empty());
  const auto missing = cv::firstMissingGlyph(text);
  EXPECT_EQ(missing, std::nullopt) << "U+" << std::hex << static_cast<std::uint32_t>(*missing);
}

TEST(FaceCount, AGeneratedPolyhedronIsNamedByItsPlaneFaces) {
  cv::Scene3D s;
  ASSERT_TRUE(s.generate(convexloc::PolyhedronKind::Dodecahedron, 320, 1));
  EXPECT_EQ(s.polyhedron().planeCount(), 12u);
  EXPECT_EQ(s.label(), "dodecahedron, 12 faces (36 triangles)");
  EXPECT_EQ(s.stats().faces, 12u);
  ASSERT_TRUE(s.generate(convexloc::PolyhedronKind::Cube, 320, 1));
  EXPECT_EQ(s.label(), "cube, 6 faces (12 triangles)");
  ASSERT_TRUE(s.generate(convexloc::PolyhedronKind::SphereHull, 100, 4));
  EXPECT_NE(s.label().find(", seed 4"), std::string::npos) << s.label();
  EXPECT_EQ(s.label().find("about"), std::string::npos) << s.label();
}

// === Radii: arcs inside their cell's wedge

namespace {

// p - c lies in the closed wedge from direction lo counter-clockwise to hi (up to rounding
// relative to |p - c|)
bool inWedge(glm::dvec2 c, glm::dvec2 lo, glm::dvec2 hi, glm::dvec2 p) {
  const glm::dvec2 d = p - c;
  const auto cross = [](glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; };
  const double slack = 1e-9 * glm::length(d) * glm::length(lo) + 1e-300;
  const double slackHi = 1e-9 * glm::length(d) * glm::length(hi) + 1e-300;
  return cross(lo, d) >= -slack && cross(d, hi) >= -slackHi;
}

}  // namespace

TEST(Radii, AnArcRunsFromOneRayToTheOtherAtItsRadius) {
  const glm::dvec2 c{2.0, -1.0}, lo{1.0, 0.2}, hi{0.6, 1.0};
  const auto arc = cv::wedgeArc(c, 3.0, lo, hi);
  ASSERT_GE(arc.size(), 3u);
  for (const glm::dvec2& p : arc) {
    EXPECT_NEAR(glm::length(p - c), 3.0, 1e-12);
    EXPECT_TRUE(inWedge(c, lo, hi, p)) << p.x << ", " << p.y;
  }
  EXPECT_NEAR(glm::length(glm::normalize(arc.front() - c) - glm::normalize(lo)), 0.0, 1e-15);
  EXPECT_NEAR(glm::length(glm::normalize(arc.back() - c) - glm::normalize(hi)), 0.0, 1e-15);
  // a wedge across the negative x axis (the angle wraps)
  for (const glm::dvec2& p : cv::wedgeArc(c, 1.0, {-1.0, 0.3}, {-1.0, -0.3}))
    EXPECT_TRUE(inWedge(c, {-1.0, 0.3}, {-1.0, -0.3}, p));
  // no wedge: the whole circle, closed
  const auto whole = cv::wedgeArc(c, 1.0, {0.0, 0.0}, {0.0, 0.0});
  EXPECT_NEAR(glm::length(whole.front() - whole.back()), 0.0, 1e-12);
}

TEST(Radii, APlacedPointsRadiiAreDrawnInsideItsCellOnly) {
  // the default scene's polar query at (0.3, 0.2) is decided by the radii
  cv::Scene2D s;
  s.place({0.3, 0.2});
  ASSERT_TRUE(s.probe());
  const convexloc::Trace2D& t = s.probe()->trace;
  ASSERT_TRUE(t.byRadius);
  const std::ptrdiff_t pos = cv::cellPosition(s, t.cell);
  ASSERT_GE(pos, 0);
  const convexloc::Cell2D& cell = s.cells()[static_cast<std::size_t>(pos)];
  const cv::Palette& pal = cv::paletteFor(cv::Theme::Dark);
  cv::DrawList out;
  cv::buildOverlay2D(s, pal, cv::View2DOptions{}, out);
  const glm::dvec2 c{t.apex.x, t.apex.y};
  int radii = 0;
  for (const cv::Segment& seg : out.segments) {
    const bool radius =
        seg.dash > 0.0f && (seg.colour == pal.positive || seg.colour == pal.negative);
    if (!radius) continue;
    ++radii;
    for (const glm::dvec3& p : {seg.a, seg.b}) {
      EXPECT_TRUE(
          inWedge(c, {cell.dirLo.x, cell.dirLo.y}, {cell.dirHi.x, cell.dirHi.y}, {p.x, p.y}));
      const double r = glm::length(glm::dvec2(p.x, p.y) - c);
      EXPECT_TRUE(std::abs(r - t.innerRadius) < 1e-9 || std::abs(r - t.outerRadius) < 1e-9) << r;
    }
  }
  EXPECT_GE(radii, 4);
}

TEST(Labels, TheStepsOctantIsNamedOnce) {
  cv::Scene2D s;
  s.place({0.3, 0.2});
  s.setStep(0);  // the octant
  const cv::Palette& pal = cv::paletteFor(cv::Theme::Light);
  for (const bool structure : {true, false}) {
    cv::View2DOptions opt;
    opt.showStructure = structure;
    cv::DrawList base, overlay;
    cv::buildStructure2D(s, pal, opt, base);
    cv::buildOverlay2D(s, pal, opt, overlay);
    const std::string name = "octant " + std::to_string(s.probe()->trace.octant);
    int named = 0;
    for (const cv::DrawList* list : {&base, &overlay})
      for (const cv::Label& l : list->labels) named += l.text == name;
    EXPECT_EQ(named, 1) << (structure ? "with" : "without") << " the structure";
  }
}

// === Labels beside their vertices (the build slide: "11" sat beside vertex 12, "2", "6",
// "8" away from theirs, and "e8 added" was crowded out)

namespace {

// the gap in pixels between an anchor and a placed label's box
double gapTo(const cv::LabelPlacement& p, glm::dvec2 anchor) {
  const glm::dvec2 lo = p.centre - 0.5 * p.size, hi = p.centre + 0.5 * p.size;
  const glm::dvec2 nearest = glm::clamp(anchor, lo, hi);
  return glm::length(nearest - anchor);
}

}  // namespace

TEST(Labels, TheBuildSlidesLabelsSitBesideTheirVertices) {
  cv::Scene2D s;
  ASSERT_TRUE(s.generate(convexloc::PolygonKind::Random, 16, 7));
  s.setMethod(convexloc::Method2D::Polar);
  ASSERT_TRUE(s.setResolution(3));
  // a 1920x1080 slide: the title card above, the caption below, the legend at the right
  cv::Camera2D cam;
  cam.setViewport({1920.0, 1080.0});
  cam.fit(s.polygon().bounds(), {{0.0, 95.0}, {1380.0, 915.0}});
  const cv::Palette& pal = cv::paletteFor(cv::Theme::Light);
  cv::View2DOptions opt;
  opt.showTints = false;
  cv::DrawList structure, step;
  cv::buildStructure2D(s, pal, opt, structure);
  cv::buildAnimation2D(s, 9, pal, step);
  cv::appendBuildStep(structure, step);
  const cv::DrawList* lists[] = {&structure};
  const cv::ScreenProjection project = [&](glm::dvec3 p) -> std::optional<glm::dvec3> {
    return glm::dvec3(cam.toScreen({p.x, p.y}), 0.0);
  };
  const double scale = 1.33;
  const cv::MeasureText measure = [&](std::string_view t) {
    return glm::dvec2(9.0 * scale * static_cast<double>(t.size()), 19.0 * scale);
  };
  const cv::PixelBox windows[] = {{{100.0, 925.0}, {1820.0, 1070.0}},
                                  {{1380.0, 490.0}, {1910.0, 910.0}}};
  const auto placed = cv::layoutSceneLabels(lists, 1, project, {{0.0, 0.0}, {1920.0, 1080.0}},
                                            measure, scale, 400, windows);
  bool added = false;
  std::size_t vertices = 0;
  for (const cv::PlacedSceneLabel& p : placed) {
    added |= p.label->text.starts_with("e8 added");
    for (std::size_t i = 0; i < s.polygon().size(); ++i) {
      if (p.label->text != std::to_string(i)) continue;
      ++vertices;
      const glm::dvec2 v = cam.toScreen({s.polygon().vertex(i).x, s.polygon().vertex(i).y});
      EXPECT_LT(gapTo(p.place, v), 16.0 * scale) << "vertex " << i;
      // and nearer to its own vertex than to any other
      for (std::size_t j = 0; j < s.polygon().size(); ++j) {
        const glm::dvec2 w = cam.toScreen({s.polygon().vertex(j).x, s.polygon().vertex(j).y});
        if (j != i) {
          EXPECT_LT(gapTo(p.place, v), gapTo(p.place, w)) << i << " nearer " << j;
        }
      }
    }
  }
  EXPECT_TRUE(added);
  EXPECT_EQ(vertices, s.polygon().size());
}

// === Live fit: a wide 3D scene (the Planes mode's polyhedron and dual) fills its area

namespace {

// the screen box of the eight corners of `box`
cv::ScreenRect cornersOnScreen(const cv::Camera3D& cam, const cv::Bounds3& box) {
  glm::dvec2 lo{1e9}, hi{-1e9};
  for (int k = 0; k < 8; ++k) {
    const glm::dvec3 c{(k & 1) ? box.hi.x : box.lo.x, (k & 2) ? box.hi.y : box.lo.y,
                       (k & 4) ? box.hi.z : box.lo.z};
    const cv::Projected p = cam.toScreen(c);
    EXPECT_TRUE(p.visible());
    lo = glm::min(lo, p.screen), hi = glm::max(hi, p.screen);
  }
  return {lo, hi};
}

}  // namespace

TEST(Fit, AWideBoxFittedByItsCornersFillsTheArea) {
  cv::Camera3D cam;
  cam.setViewport({1920.0, 1080.0});
  const cv::Bounds3 box{{-1.0, -1.0, -1.0}, {4.0, 1.0, 1.0}};  // 5 by 2 by 2
  const cv::ScreenRect area{{345.0, 0.0}, {1590.0, 1080.0}};
  for (const double yaw : {0.0, 0.4, -0.7}) {
    cam.set({1.5, 0.0, 0.0}, 10.0, yaw, 0.35);
    cam.fit(box, area);
    const cv::ScreenRect sphere = cornersOnScreen(cam, box);
    cam.fitCorners(std::span<const cv::Bounds3>(&box, 1), area);
    const cv::ScreenRect r = cornersOnScreen(cam, box);
    EXPECT_GE(r.lo.x, area.lo.x - 1.0) << yaw;
    EXPECT_GE(r.lo.y, area.lo.y - 1.0) << yaw;
    EXPECT_LE(r.hi.x, area.hi.x + 1.0) << yaw;
    EXPECT_LE(r.hi.y, area.hi.y + 1.0) << yaw;
    // some corner reaches within 5% of an edge of the area ...
    const double gap =
        std::min({r.lo.x - area.lo.x, r.lo.y - area.lo.y, area.hi.x - r.hi.x, area.hi.y - r.hi.y});
    EXPECT_LT(gap, 0.05 * area.size().y) << yaw;
    // ... and the box is drawn far larger than its bounding sphere's fit drew it
    EXPECT_GT(r.size().x, 1.15 * sphere.size().x) << yaw;
  }
}

// === Degenerate cases that show: the points normalisation dropped

TEST(Dropped, TheInputPointsNormalisationDroppedAreDrawnAndNamed) {
  cv::Model m;
  ASSERT_TRUE(m.applyPreset("collinear-duplicate"));
  const auto dropped = m.scene2d.droppedPoints();
  ASSERT_FALSE(dropped.empty());
  EXPECT_EQ(dropped.size(), m.scene2d.polygon().droppedCount());
  const cv::Palette& pal = cv::paletteFor(m.settings.theme);
  cv::DrawList out;
  cv::buildStructure2D(m.scene2d, pal, m.settings.view2d, out);
  for (const Vec2 p : dropped) {
    bool ringed = false;
    for (const cv::Marker& k : out.markers)
      ringed |= k.shape == cv::MarkerShape::Ring && k.colour == pal.textMuted &&
                k.p == glm::dvec3(p.x, p.y, 0.0);
    EXPECT_TRUE(ringed) << p.x << ", " << p.y;
  }
  bool named = false;
  for (const cv::LegendRow& r : cv::legendOf(m).rows)
    named |= r.text.find("dropped") != std::string::npos;
  EXPECT_TRUE(named);
  // a shape with nothing dropped draws and names none
  ASSERT_TRUE(m.scene2d.setShape(std::vector<Vec2>{{0, 0}, {1, 0}, {0, 1}}, "triangle"));
  EXPECT_TRUE(m.scene2d.droppedPoints().empty());
}

// === A zoom inset onto the tiny edges

TEST(ZoomInset, TheTinyEdgesAreDrawnMagnifiedBesideThePolygon) {
  const convexloc::ConvexPolygon poly(
      convexloc::generatePolygon(convexloc::PolygonKind::TinyEdges, 24, 1));
  const auto inset = cv::tinyEdgesInset(poly);
  ASSERT_TRUE(inset);
  EXPECT_GE(inset->exponent, 6);
  const convexloc::Box2 box = poly.bounds();
  // beside the polygon, not over it, at the box's corner next to the tiny edges (on their
  // side, level with their half), and about half its height
  const auto centre = [](const convexloc::Box2& b) {
    return Vec2{0.5 * (b.lo.x + b.hi.x), 0.5 * (b.lo.y + b.hi.y)};
  };
  const Vec2 source = centre(inset->source), middle = centre(box), frame = centre(inset->frame);
  EXPECT_TRUE(inset->frame.hi.x < box.lo.x || inset->frame.lo.x > box.hi.x);
  EXPECT_EQ(source.x > middle.x, frame.x > middle.x);
  EXPECT_EQ(source.y > middle.y, frame.y > middle.y);
  // the leader from the source to the frame's facing side runs off the box's sides (the
  // polygon's edges here), not along one
  const glm::dvec3 end = cv::zoomLeaderEnd(*inset);
  EXPECT_TRUE(end.x == inset->frame.lo.x || end.x == inset->frame.hi.x);
  EXPECT_GT(std::abs(end.y - source.y), 0.1 * (box.hi.y - box.lo.y));
  const double side = inset->frame.hi.x - inset->frame.lo.x, height = box.hi.y - box.lo.y;
  EXPECT_GT(side, 0.2 * height);
  EXPECT_LE(side, 0.5 * height * (1.0 + 1e-9));
  // every edge too short to see lies in the source, and so is drawn in the frame
  std::size_t tiny = 0;
  for (std::size_t e = 0; e < poly.size(); ++e) {
    const Vec2 a = poly.edgeStart(e), b = poly.edgeEnd(e);
    if (std::hypot(b.x - a.x, b.y - a.y) > 1e-6) continue;
    ++tiny;
    for (const Vec2 p : {a, b}) {
      const Vec2 q = cv::insetPoint(*inset, p);
      EXPECT_TRUE(q.x >= inset->frame.lo.x && q.x <= inset->frame.hi.x &&
                  q.y >= inset->frame.lo.y && q.y <= inset->frame.hi.y);
    }
  }
  EXPECT_GE(tiny, 10u);
  EXPECT_NE(cv::magnificationText(*inset).find("10^"), std::string::npos);
  // and drawn: the label names the magnification
  cv::DrawList out;
  cv::drawZoomInset(poly, *inset, cv::paletteFor(cv::Theme::Light), out);
  bool named = false;
  for (const cv::Label& l : out.labels) named |= l.text == "zoom " + cv::magnificationText(*inset);
  EXPECT_TRUE(named);
  // a polygon whose edges all show has none
  EXPECT_FALSE(cv::tinyEdgesInset(convexloc::ConvexPolygon(
      convexloc::generatePolygon(convexloc::PolygonKind::Regular, 64, 1))));
}

// === The plane's section as one straight-sided polygon

TEST(Section, TheSectionIsOnePolygonOnTheSurface) {
  cv::Scene3D s;
  ASSERT_TRUE(s.generate(convexloc::PolyhedronKind::Cube, 6, 1));
  // z = 0.3 through the cube [-1, 1]^3: the square |x|, |y| <= 1
  const auto square =
      cv::sectionPolygon(s.polyhedron(), {-2.0, -2.0, 0.3}, {0.1, 0.0, 0.0}, {0.0, 0.1, 0.0});
  ASSERT_EQ(square.size(), 4u);
  for (const glm::dvec3& p : square) {
    EXPECT_DOUBLE_EQ(p.z, 0.3);
    EXPECT_DOUBLE_EQ(std::abs(p.x), 1.0);
    EXPECT_DOUBLE_EQ(std::abs(p.y), 1.0);
  }
  // an oblique plane through the dodecahedron: every corner on the surface (on some face's
  // plane, inside all), the polygon convex and counter-clockwise about the normal
  ASSERT_TRUE(s.generate(convexloc::PolyhedronKind::Dodecahedron, 12, 1));
  const glm::dvec3 du{0.3, 0.1, -0.2}, dv{-0.1, 0.25, 0.15};
  const auto poly = cv::sectionPolygon(s.polyhedron(), {0.1, -0.05, 0.2}, du, dv);
  ASSERT_GE(poly.size(), 5u);
  const auto v = s.polyhedron().vertices();
  const auto at = [&](std::uint32_t i) { return glm::dvec3(v[i].x, v[i].y, v[i].z); };
  for (const glm::dvec3& p : poly) {
    double most = -1e300;
    for (const auto& t : s.polyhedron().triangles()) {
      const glm::dvec3 n = glm::normalize(glm::cross(at(t[1]) - at(t[0]), at(t[2]) - at(t[0])));
      most = std::max(most, glm::dot(p - at(t[0]), n));
    }
    EXPECT_NEAR(most, 0.0, 1e-12);
  }
  const glm::dvec3 n = glm::cross(du, dv);
  for (std::size_t i = 0; i < poly.size(); ++i) {
    const glm::dvec3 a = poly[i], b = poly[(i + 1) % poly.size()], c = poly[(i + 2) % poly.size()];
    EXPECT_GT(glm::dot(glm::cross(b - a, c - b), n), 0.0);
  }
  // a plane beside the polyhedron cuts nothing
  EXPECT_TRUE(cv::sectionPolygon(s.polyhedron(), {0.0, 0.0, 5.0}, {1.0, 0.0, 0.0}, {0.0, 1.0, 0.0})
                  .empty());
}

TEST(ZoomInset, AFarOffsetShowsItsDigits) {
  cv::Model m;
  ASSERT_TRUE(m.applyPreset("large-offset"));
  const auto note = cv::offsetNote(m.scene2d.polygon());
  ASSERT_TRUE(note);
  EXPECT_NE(note->find("10^9"), std::string::npos) << *note;
  EXPECT_NE(note->find(convexloc::exactText(m.scene2d.polygon().vertex(0))), std::string::npos);
  cv::DrawList out;
  cv::buildStructure2D(m.scene2d, cv::paletteFor(m.settings.theme), m.settings.view2d, out);
  bool drawn = false;
  for (const cv::Label& l : out.labels) drawn |= l.text == *note && l.essential;
  EXPECT_TRUE(drawn);  // and never left out for want of room
  // an essential label in a list of others wins the one spot there is
  cv::DrawList crowded;
  crowded.label({15.0, 8.0, 0.0}, "aaaa", {});
  crowded.label({15.0, 8.0, 0.0}, "note", {});
  crowded.labels.back().essential = true;
  const cv::DrawList* lists[] = {&crowded};
  const auto placed = cv::layoutSceneLabels(
      lists, 1, [](glm::dvec3 p) -> std::optional<glm::dvec3> { return p; },
      {{0.0, 0.0}, {30.0, 16.0}},
      [](std::string_view t) { return glm::dvec2(7.0 * t.size(), 14.0); }, 1.0, 400, {});
  ASSERT_FALSE(placed.empty());
  EXPECT_EQ(placed.front().label->text, "note");
  // near the origin: none
  EXPECT_FALSE(cv::offsetNote(convexloc::ConvexPolygon(
      convexloc::generatePolygon(convexloc::PolygonKind::Regular, 12, 1))));
}
