// The cube map's zoom inset: shown for the tiny-faces corner (its patch holds the refined
// leaves, the magnification as written), placed off the cube and the legend, and absent
// where no cell is refined far below a base cell.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "logic/app/model.hpp"
#include "logic/app/options.hpp"
#include "logic/draw/cube_inset.hpp"
#include "writers/svg_writer.hpp"

namespace cv = convexloc::viewer;
using convexloc::Cell3D;

namespace {

double sideOf(const Cell3D& c) {
  return c.s1 - c.s0;
}

bool meets(const cv::CubeInset& in, const Cell3D& c) {
  return c.cubeFace == in.cubeFace && c.s0 < in.lo.x + in.side && c.s1 > in.lo.x &&
         c.t0 < in.lo.y + in.side && c.t1 > in.lo.y;
}

bool overlap(const cv::PixelBox& a, const cv::PixelBox& b) {
  return a.lo.x < b.hi.x && b.lo.x < a.hi.x && a.lo.y < b.hi.y && b.lo.y < a.hi.y;
}

}  // namespace

TEST(CubeInset, TinyFacesShowsItsRefinedLeavesMagnified) {
  cv::Model m;
  ASSERT_TRUE(m.applyPreset("tiny-faces")) << m.error();
  const cv::Scene3D& scene = m.scene3d();
  const std::vector<Cell3D>& cells = scene.cells();
  const auto inset = cv::cubeMapInset(cells);
  ASSERT_TRUE(inset);
  // a base cell is a cube face's side (2) over the grid size
  const double base = 2.0 / scene.effectiveResolution();
  EXPECT_DOUBLE_EQ(inset->baseSide, base);
  double smallest = INFINITY;
  for (const Cell3D& c : cells) smallest = std::min(smallest, sideOf(c));
  EXPECT_EQ(inset->smallestSide, smallest);
  EXPECT_LT(smallest, base / 64.0);
  // the patch: a square of the face, holding every smallest leaf of its face
  EXPECT_GE(inset->lo.x, -1.0);
  EXPECT_GE(inset->lo.y, -1.0);
  EXPECT_LE(inset->lo.x + inset->side, 1.0);
  EXPECT_LE(inset->lo.y + inset->side, 1.0);
  std::size_t meeting = 0, deep = 0;
  for (std::size_t k = 0; k < cells.size(); ++k) {
    const Cell3D& c = cells[k];
    const bool listed =
        std::find(inset->cells.begin(), inset->cells.end(), k) != inset->cells.end();
    EXPECT_EQ(listed, meets(*inset, c)) << "cell " << k;
    meeting += meets(*inset, c);
    deep += listed && sideOf(c) < base / 64.0;
    if (c.cubeFace == inset->cubeFace && sideOf(c) == smallest) {
      EXPECT_TRUE(listed) << "cell " << k;
      EXPECT_GE(c.s0, inset->lo.x);
      EXPECT_LE(c.t1, inset->lo.y + inset->side);
    }
  }
  EXPECT_EQ(inset->cells.size(), meeting);
  EXPECT_GT(deep, 0u);
  // the patch is a cube face over mantissa * 10^exponent, at least 16 smallest leaves wide;
  // the next step up (x2 or x2.5) would be narrower than that
  ASSERT_TRUE(inset->mantissa == 1 || inset->mantissa == 2 || inset->mantissa == 5);
  const double zoom = inset->mantissa * std::pow(10.0, inset->exponent);
  EXPECT_DOUBLE_EQ(inset->magnification(), zoom);
  EXPECT_DOUBLE_EQ(inset->side, 2.0 / zoom);
  EXPECT_GE(inset->side, 16.0 * smallest);
  EXPECT_LT(2.0 / (zoom * (inset->mantissa == 2 ? 2.5 : 2.0)), 16.0 * smallest);
  std::string text = "zoom \u00D7";
  if (inset->mantissa != 1) text += std::to_string(inset->mantissa) + "\u00B7";
  EXPECT_EQ(cv::cubeInsetZoomText(*inset), text + "10^" + std::to_string(inset->exponent));
  // the cap rounds the box's (1,1,1) corner: the patch is in a corner of its cube face, and
  // lies on the drawing cube where the centre's diagonal to that corner meets it
  const std::string face(convexloc::kCubeFaceNames[static_cast<std::size_t>(inset->cubeFace)]);
  EXPECT_EQ(cv::cubeInsetTitle(*inset), "cube face " + face + " near (s,t) = (1, 1)");
  const glm::dvec3 anchor = cv::cubeInsetAnchor(*inset, cells);
  const glm::dvec3 centre = cv::toGlm(*scene.centre());
  const double h = scene.cubeHalfSize();
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(anchor[a], centre[a] + h, 1e-3 * h) << a;
}

TEST(CubeInset, DrawnInItsFrameWithTitleZoomAndLeader) {
  cv::Model m;
  ASSERT_TRUE(m.applyPreset("tiny-faces")) << m.error();
  const auto& cells = m.scene3d().cells();
  const auto inset = cv::cubeMapInset(cells);
  ASSERT_TRUE(inset);
  const cv::PixelBox frame{{600.0, 100.0}, {900.0, 400.0}};
  cv::DrawList out;
  cv::drawCubeInset(*inset, cells, cv::paletteFor(cv::Theme::Light), frame, 30.0,
                    glm::dvec2(100.0, 500.0), out);
  ASSERT_EQ(out.labels.size(), 3u);
  EXPECT_EQ(out.labels[0].text, cv::cubeInsetTitle(*inset));
  EXPECT_LT(out.labels[0].p.y, frame.lo.y);
  EXPECT_EQ(out.labels[1].text, cv::cubeInsetZoomText(*inset));
  EXPECT_GT(out.labels[1].p.y, frame.hi.y);
  // the leader's end names the face the title names, beyond the ring from the frame
  const std::string face(convexloc::kCubeFaceNames[static_cast<std::size_t>(inset->cubeFace)]);
  EXPECT_EQ(out.labels[2].text, face);
  EXPECT_NE(out.labels[0].text.find("cube face " + face + " "), std::string::npos);
  const glm::dvec2 middle = 0.5 * (frame.lo + frame.hi);
  EXPECT_GT(glm::length(glm::dvec2(out.labels[2].p) - middle),
            glm::length(glm::dvec2(100.0, 500.0) - middle));
  // every line but the leader and its ring inside the frame; the leader from the frame's
  // edge to the anchor
  std::size_t outside = 0;
  const auto in = [&](glm::dvec3 p) {
    return p.x >= frame.lo.x - 1e-9 && p.x <= frame.hi.x + 1e-9 && p.y >= frame.lo.y - 1e-9 &&
           p.y <= frame.hi.y + 1e-9;
  };
  for (const cv::Segment& g : out.segments) outside += !(in(g.a) && in(g.b));
  EXPECT_EQ(outside, 1u + 8u);
  EXPECT_GE(out.segments.size(), 4u * inset->cells.size() + 4u + 9u);
  for (const cv::FillVertex& v : out.fills) EXPECT_TRUE(in(v.p));
}

TEST(CubeInset, TheSvgWritesItInWindowPixelsOverTheScene) {
  cv::Model m;
  ASSERT_TRUE(m.applyPreset("tiny-faces")) << m.error();
  const auto& cells = m.scene3d().cells();
  const auto inset = cv::cubeMapInset(cells);
  ASSERT_TRUE(inset);
  cv::DrawList list;
  cv::drawCubeInset(*inset, cells, cv::paletteFor(cv::Theme::Light),
                    {{600.0, 100.0}, {900.0, 400.0}}, 30.0, std::nullopt, list);
  cv::SvgScene s;
  s.size = {1000.0, 600.0};
  // a projection far off the window: the inset must not go through it
  s.project = [](glm::dvec3 p) -> std::optional<glm::dvec3> { return p + glm::dvec3(5000.0); };
  s.measure = [](std::string_view t) { return glm::dvec2(7.0 * t.size(), 14.0); };
  s.screen = {&list};
  const std::string svg = cv::sceneSvg(s);
  const std::size_t group = svg.find("<g class=\"inset\"");
  ASSERT_NE(group, std::string::npos);
  EXPECT_NE(svg.find(">" + cv::cubeInsetTitle(*inset) + "</text>", group), std::string::npos);
  EXPECT_NE(svg.find("zoom \u00D7", group), std::string::npos);
  // the frame's top left corner, as given
  EXPECT_NE(svg.find("x1=\"600.00\" y1=\"100.00\"", group), std::string::npos);
  std::size_t polygons = 0;
  for (std::size_t at = svg.find("<polygon points", group); at != std::string::npos;
       at = svg.find("<polygon points", at + 1))
    ++polygons;
  EXPECT_EQ(polygons, list.fills.size() / 3);
}

TEST(CubeInset, PlacedOffTheCubeAndTheLegend) {
  const cv::PixelBox area{{0.0, 100.0}, {1600.0, 900.0}};
  const cv::PixelBox cube{{400.0, 150.0}, {1000.0, 850.0}};
  const glm::dvec2 corners[] = {cube.lo, {cube.hi.x, cube.lo.y}, cube.hi, {cube.lo.x, cube.hi.y}};
  const cv::PixelBox legend[] = {{{1300.0, 600.0}, {1590.0, 890.0}}};
  const auto frame = cv::placeCubeInset(area, corners, legend, {250.0, 30.0});
  ASSERT_TRUE(frame);
  EXPECT_NEAR(frame->hi.x - frame->lo.x, frame->hi.y - frame->lo.y, 1e-9);
  EXPECT_GE(frame->hi.x - frame->lo.x, 120.0);
  const cv::PixelBox outer{frame->lo - glm::dvec2(0.0, 30.0), frame->hi + glm::dvec2(0.0, 30.0)};
  EXPECT_FALSE(overlap(outer, cube));
  EXPECT_FALSE(overlap(outer, legend[0]));
  EXPECT_GT(frame->lo.x, cube.hi.x);  // the upper right corner had room
  // a diamond filling the area's box: the corners beside its sides are free
  const glm::dvec2 diamond[] = {{800.0, 100.0}, {1600.0, 500.0}, {800.0, 900.0}, {0.0, 500.0}};
  const auto beside = cv::placeCubeInset(area, diamond, {}, {150.0, 20.0});
  ASSERT_TRUE(beside);
  // upper right, clear of the side from (800, 100) to (1600, 500) by the margin
  EXPECT_GT(beside->lo.x, 800.0);
  const glm::dvec2 far{beside->lo.x, beside->hi.y + 20.0};  // the outer box's nearest corner
  const glm::dvec2 n = glm::normalize(glm::dvec2(-400.0, 800.0));
  EXPECT_LE(glm::dot(far - glm::dvec2(800.0, 100.0), n), -12.0 + 1e-9);
  // nowhere free: no inset
  const glm::dvec2 everything[] = {{0.0, 0.0}, {1600.0, 0.0}, {1600.0, 900.0}, {0.0, 900.0}};
  EXPECT_FALSE(cv::placeCubeInset(area, everything, {}, {250.0, 30.0}));
}

TEST(CubeInset, NoneWhereNoCellIsRefinedFar) {
  cv::Model m;
  cv::Options o;
  o.generate = "cube";
  ASSERT_EQ(m.apply(o), "");
  ASSERT_FALSE(m.scene3d().cells().empty());
  EXPECT_FALSE(cv::cubeMapInset(m.scene3d().cells()));
  cv::Model icosahedron;
  icosahedron.show(cv::Dim::Three);
  ASSERT_FALSE(icosahedron.scene3d().cells().empty());
  EXPECT_FALSE(cv::cubeMapInset(icosahedron.scene3d().cells()));
  EXPECT_FALSE(cv::cubeMapInset({}));
}
