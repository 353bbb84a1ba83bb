// The drawing faithful to the shape and to the text: the font holds every glyph the
// captions use, radii stay in their cells, labels sit beside their own vertex, a polyhedron
// reports its plane faces.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "logic/base/glyphs.hpp"
#include "logic/scene/scene3d.hpp"

namespace cv = convexloc::viewer;

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
