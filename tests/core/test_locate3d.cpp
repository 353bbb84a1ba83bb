// Every 3D locator against the independent rational reference, over the shape matrix (every
// generator kind, every degenerate preset), with random points, the generator's
// near-boundary points and the adversarial set: through Locator3D (one point, batch, trace)
// and through each concrete class's batch.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "adversarial3d.hpp"
#include "convexloc/error.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/locate3d.hpp"
#include "reference3d.hpp"
#include "scale.hpp"
#include "shapes3d.hpp"

using namespace convexloc;

namespace {

// a method with a resolution (0 = the default chosen from the face count)
struct Config {
  Method3D method;
  std::uint32_t resolution;
};

// defaults, plus a one-cell-per-face grid (crowded cells, deep quadtrees) and a fine one
constexpr Config kConfigs[] = {{Method3D::Halfspace, 0},
                               {Method3D::Walk, 0},
                               {Method3D::Cubemap, 0},
                               {Method3D::Cubemap, 1},
                               {Method3D::Cubemap, 48}};

// the concrete class of `config`, its batch locate over `points`
std::vector<Location> concreteBatch(const ConvexPolyhedron& p, Config config,
                                    const std::vector<Vec3>& points) {
  std::vector<Location> out(points.size(), Location::Boundary);
  switch (config.method) {
    case Method3D::Halfspace: HalfspaceLocator(p).locate(points, out); break;
    case Method3D::Walk: WalkLocator(p).locate(points, out); break;
    case Method3D::Cubemap: CubemapLocator(p, config.resolution).locate(points, out); break;
  }
  return out;
}

std::string show(Vec3 p) {
  std::ostringstream s;
  s.precision(17);
  s << '(' << p.x << ", " << p.y << ", " << p.z << ')';
  return s.str();
}

// one line describing a wrong answer
std::string mismatch(const std::string& shape, Config config, const char* path, Vec3 p,
                     Location got, Location want) {
  std::ostringstream s;
  s << shape << ' ' << toString(config.method) << '(' << config.resolution << ") " << path << " at "
    << show(p) << ": got " << toString(got) << ", reference says " << toString(want);
  return s.str();
}

// n scaled by CONVEXLOC_HOSTILE_SCALE where it is over `floor`, never below it
std::size_t sized(std::size_t n, std::size_t floor) {
  return n <= floor ? n : testscale::scaled(n, floor);
}

class LocateExact3D : public testing::TestWithParam<std::size_t> {};

}  // namespace

TEST_P(LocateExact3D, EveryMethodMatchesTheReference) {
  const shapes3d::ShapeCase& shape = shapes3d::matrix()[GetParam()];
  const std::string name = std::string(toString(shape.kind)) + "-" + std::to_string(shape.n);
  // under the sanitizers (CONVEXLOC_HOSTILE_SCALE) the large shapes and the random point
  // sets are smaller; the test's name keeps the full size
  const ConvexPolyhedron p(generatePolyhedron(shape.kind, sized(shape.n, 1000), 11));
  const reftest::Reference ref(p);
  ASSERT_TRUE(ref.sound());

  Rng rng(0x3d00 + GetParam());
  std::vector<Vec3> points = generatePoints3D(p, sized(shape.randomPoints, 3000), 21, false);
  auto append = [&](const std::vector<Vec3>& more) {
    points.insert(points.end(), more.begin(), more.end());
  };
  append(generatePoints3D(p, sized(shape.nearPoints, 3000), 22, true));
  append(adversarial3d::surfacePoints(p, p.faceCount() > 1000 ? 500 : 1500, rng));
  append(adversarial3d::cubemapPoints(p, CubemapLocator(p), rng));
  append(adversarial3d::cubemapPoints(p, CubemapLocator(p, 48), rng));
  if (testscale::factor() == 1.0 && shape.randomPoints + shape.nearPoints >= 100000) {
    EXPECT_GE(points.size(), 100000u);
  }

  std::vector<Location> want(points.size());
  std::size_t counts[3] = {0, 0, 0};
  for (std::size_t i = 0; i < points.size(); ++i) {
    want[i] = ref.locate(points[i]);
    ++counts[static_cast<int>(want[i])];
  }
  // the set exercises all three answers
  EXPECT_GT(counts[static_cast<int>(Location::Inside)], 0u) << name;
  EXPECT_GT(counts[static_cast<int>(Location::Boundary)], 0u) << name;
  EXPECT_GT(counts[static_cast<int>(Location::Outside)], 0u) << name;

  for (const Config& config : kConfigs) {
    // halfspace costs O(F) per point: on the larger shapes it checks every stride-th point
    const std::size_t stride = config.method == Method3D::Halfspace
                                   ? std::clamp<std::size_t>(p.faceCount() / 100, 1, 16)
                                   : 1;
    std::vector<Vec3> tested;
    std::vector<Location> expected;
    for (std::size_t i = 0; i < points.size(); i += stride) {
      tested.push_back(points[i]);
      expected.push_back(want[i]);
    }
    const Locator3D loc(p, config.method, config.resolution);
    std::vector<Location> batch(tested.size(), Location::Boundary);
    loc.locate(tested, batch);
    const std::vector<Location> concrete = concreteBatch(p, config, tested);
    std::size_t wrong = 0;
    for (std::size_t i = 0; i < tested.size(); ++i) {
      const Location one = loc.locate(tested[i]);
      for (auto [got, path] : {std::pair{one, "locate"}, std::pair{batch[i], "batch"},
                               std::pair{concrete[i], "concrete"}})
        if (got != expected[i] && ++wrong <= 5)
          ADD_FAILURE() << mismatch(name, config, path, tested[i], got, expected[i]);
      if (i % 97 == 0) {
        const Trace3D t = loc.trace(tested[i]);
        if (t.result != expected[i] && ++wrong <= 5)
          ADD_FAILURE() << mismatch(name, config, "trace", tested[i], t.result, expected[i]);
      }
    }
    EXPECT_EQ(wrong, 0u) << name << ' ' << toString(config.method) << '(' << config.resolution
                         << ") on " << tested.size() << " points";
  }
}

INSTANTIATE_TEST_SUITE_P(Shapes, LocateExact3D,
                         testing::Range<std::size_t>(0, shapes3d::matrix().size()),
                         [](const testing::TestParamInfo<std::size_t>& param) {
                           const auto& s = shapes3d::matrix()[param.param];
                           std::string n =
                               std::string(toString(s.kind)) + "_" + std::to_string(s.n);
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

TEST(Locate3D, ExtremeScalesAndPoints) {
  // the cube scaled to 1e300 and to subnormal size, and points far out, at the limits
  for (double scale : {1e300, 0x1p-1070, 1.0}) {
    MeshData m = shapes3d::cube();
    for (Vec3& v : m.vertices) v = {v.x * scale, v.y * scale, v.z * scale};
    const ConvexPolyhedron p(m);
    const reftest::Reference ref(p);
    const double big = std::numeric_limits<double>::max(),
                 tiny = std::numeric_limits<double>::denorm_min();
    std::vector<Vec3> pts = {{0, 0, 0},
                             {scale, scale, scale},
                             {scale, 0, 0},
                             {big, big, big},
                             {-big, 0, 0},
                             {tiny, tiny, tiny},
                             {scale, scale, adversarial3d::ulps(scale, 1)},
                             {0, -scale, 0.5 * scale}};
    for (const Config& config : kConfigs) {
      const Locator3D loc(p, config.method, config.resolution);
      for (Vec3 q : pts)
        EXPECT_EQ(loc.locate(q), ref.locate(q))
            << scale << ' ' << toString(config.method) << show(q);
    }
  }
  // a box near the top of the double range: directions from its centre overflow
  MeshData m = shapes3d::cube();
  for (Vec3& v : m.vertices)
    v = {1.25e308 + v.x * 2e307, 1.25e308 + v.y * 2e307, 1.25e308 + v.z * 2e307};
  const ConvexPolyhedron p(m);
  const reftest::Reference ref(p);
  for (const Config& config : kConfigs) {
    const Locator3D loc(p, config.method, config.resolution);
    for (Vec3 q : std::vector<Vec3>{{-1.7e308, 1.25e308, 1.25e308},
                                    {1.25e308, 1.25e308, 1.25e308},
                                    {1.05e308, 1.05e308, 1.05e308}})
      EXPECT_EQ(loc.locate(q), ref.locate(q)) << toString(config.method) << show(q);
  }
}

// Needles 10^150 and 10^154 long, 10^12 and 10^138 wide: a face's distance from the centre
// fits in a double while its cross products squared do not (the 2D radii overflowed there).
TEST(Locate3D, NeedlesAcrossTheDoubleRange) {
  const std::vector<std::array<Vec3, 4>> needles = {
      {{{4e-150, 1e-150, 0}, {115e10, 1e150, 3e11}, {75, 2e150, -1e12}, {-2e12, 1.5e150, 1e11}}},
      {{{0, 0, 0},
        {3e154, 1e154 + 1e138, 2e138},
        {1.5e154, 5e153, -3e138},
        {2e154, 7e153, 5e138}}}};
  for (const auto& n : needles) {
    MeshData m = shapes3d::tetrahedron(n[0], n[1], n[2], n[3]);
    if (!shapes3d::failureOf(m).message.empty()) m = shapes3d::reversed(m);
    const ConvexPolyhedron p(m);
    const reftest::Reference ref(p);
    Rng rng(0x7e3d);
    std::vector<Vec3> points = generatePoints3D(p, 3000, 5, false);
    for (const auto& more :
         {generatePoints3D(p, 3000, 6, true), adversarial3d::surfacePoints(p, 1500, rng),
          adversarial3d::cubemapPoints(p, CubemapLocator(p), rng),
          adversarial3d::cubemapPoints(p, CubemapLocator(p, 48), rng)})
      points.insert(points.end(), more.begin(), more.end());
    points.insert(points.end(), n.begin(), n.end());
    std::size_t wrong = 0, inside = 0;
    for (const Config& config : kConfigs) {
      const Locator3D loc(p, config.method, config.resolution);
      std::vector<Location> batch(points.size(), Location::Boundary);
      loc.locate(points, batch);
      for (std::size_t i = 0; i < points.size(); ++i) {
        const Location want = ref.locate(points[i]);
        inside += want == Location::Inside;
        for (Location got : {loc.locate(points[i]), batch[i]})
          if (got != want && ++wrong <= 5)
            ADD_FAILURE() << mismatch("needle", config, "locate/batch", points[i], got, want);
      }
    }
    EXPECT_EQ(wrong, 0u);
    EXPECT_GT(inside, 0u);
  }
}

TEST(Locate3D, NonFinitePointsAreOutside) {
  const ConvexPolyhedron p(shapes3d::cube());
  const double inf = std::numeric_limits<double>::infinity(),
               nan = std::numeric_limits<double>::quiet_NaN();
  for (Method3D m : kAllMethods3D) {
    const Locator3D loc(p, m);
    for (Vec3 q : std::vector<Vec3>{{inf, 0, 0}, {0, -inf, 0}, {0, 0, nan}}) {
      EXPECT_EQ(loc.locate(q), Location::Outside);
      EXPECT_TRUE(loc.trace(q).nonFinite);
    }
  }
}

TEST(Locate3D, MethodNames) {
  for (Method3D m : kAllMethods3D) EXPECT_EQ(parseMethod3D(toString(m)), m);
  EXPECT_EQ(toString(Method3D::Cubemap), "cubemap");
  EXPECT_FALSE(parseMethod3D("polar").has_value());
  const ConvexPolyhedron p(shapes3d::cube());
  EXPECT_THROW(CubemapLocator(p, 8193), UsageError);
  EXPECT_EQ(Locator3D(p, Method3D::Walk).method(), Method3D::Walk);
  EXPECT_NE(Locator3D(p, Method3D::Cubemap, 3).get<CubemapLocator>(), nullptr);
}

TEST(Locate3D, BatchStopsAtTheShorterSpan) {
  const ConvexPolyhedron p(shapes3d::cube());
  const Locator3D loc(p, Method3D::Cubemap);
  std::vector<Vec3> pts = {{0, 0, 0}, {2, 0, 0}, {1, 0, 0}};
  std::vector<Location> out(2, Location::Boundary);
  loc.locate(pts, out);
  EXPECT_EQ(out[0], Location::Inside);
  EXPECT_EQ(out[1], Location::Outside);
}
