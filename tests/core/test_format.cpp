// The texts every front end shares: FILE:LINE: problem, exact decimals, binary sizes, the
// cube map's face names.
#include <gtest/gtest.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <string>

#include "convexloc/error.hpp"
#include "convexloc/format.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/locate3d.hpp"

namespace {

using convexloc::Vec3;

TEST(Format, ProblemsNameTheirFileAndLine) {
  EXPECT_EQ(convexloc::located("a.txt", 3, "not a number"), "a.txt:3: not a number");
  EXPECT_EQ(convexloc::located("a.txt", 0, "cannot be read"), "a.txt: cannot be read");
  EXPECT_EQ(convexloc::located("-", 7, "bad"), "<stdin>:7: bad");
  EXPECT_EQ(convexloc::located("", 7, "no file"), "no file");
}

TEST(Format, ExactDecimalsReadBackToTheSameDouble) {
  const double values[] = {0.1,
                           1.0 / 3.0,
                           -2.5e-300,
                           std::numeric_limits<double>::denorm_min(),
                           std::numeric_limits<double>::max(),
                           9007199254740993.0,
                           -0.0};
  for (const double v : values) {
    const std::string s = convexloc::exactText(v);
    double back = 1.0;
    const auto r = std::from_chars(s.data(), s.data() + s.size(), back);
    ASSERT_EQ(r.ptr, s.data() + s.size()) << s;
    EXPECT_EQ(back, v) << s;
    EXPECT_EQ(std::signbit(back), std::signbit(v)) << s;
  }
  EXPECT_EQ(convexloc::exactText(Vec3{1.0, -0.5, 0.1}), "(1, -0.5, 0.1)");
}

TEST(Format, SizesAreNamedInBinaryUnits) {
  EXPECT_EQ(convexloc::binarySize(0), "0 B");
  EXPECT_EQ(convexloc::binarySize(1023), "1023 B");
  EXPECT_EQ(convexloc::binarySize(1024), "1 KiB");
  EXPECT_EQ(convexloc::binarySize(1536), "1.5 KiB");
  EXPECT_EQ(convexloc::binarySize(10.0 * 1024 * 1024), "10 MiB");
  EXPECT_EQ(convexloc::binarySize(3.0 * 1024 * 1024 * 1024), "3 GiB");
  // a count only a double holds stays in the largest unit
  const std::string huge = convexloc::binarySize(1e300);
  EXPECT_EQ(huge.substr(huge.size() - 4), " EiB") << huge;
}

// the trace's cube face is named by the table: the face the direction's largest coordinate
// points to
TEST(Format, CubeFaceNamesFollowTheTraceNumbering) {
  const convexloc::ConvexPolyhedron p(
      convexloc::generatePolyhedron(convexloc::PolyhedronKind::Icosahedron, 20, 1));
  const convexloc::CubemapLocator cube(p);
  ASSERT_TRUE(cube.centre());
  const Vec3 c = *cube.centre();
  const Vec3 toward[6] = {{1, 0.1, 0.2},  {-1, 0.2, 0.1}, {0.1, 1, 0.2},
                          {0.2, -1, 0.1}, {0.1, 0.2, 1},  {0.2, 0.1, -1}};
  const char* names[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
  for (int k = 0; k < 6; ++k) {
    const Vec3 d = toward[k];
    const convexloc::Trace3D t = cube.trace({c.x + 0.3 * d.x, c.y + 0.3 * d.y, c.z + 0.3 * d.z});
    ASSERT_GE(t.cubeFace, 0);
    EXPECT_EQ(convexloc::kCubeFaceNames[static_cast<std::size_t>(t.cubeFace)], names[k]);
  }
}

}  // namespace
