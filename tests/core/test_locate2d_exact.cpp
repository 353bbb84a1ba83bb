// Every 2D locator against the independent rational reference, over the shape matrix, with
// random queries and the adversarial points: through Locator2D (one point and batch) and
// through each concrete class's batch.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "adversarial2d.hpp"
#include "convexloc/generate2d.hpp"
#include "convexloc/locate2d.hpp"
#include "convexloc/polygon.hpp"
#include "reference2d.hpp"
#include "scale.hpp"
#include "shapes2d.hpp"

using namespace convexloc;

namespace {

// a method with a resolution (0 = the default chosen from the polygon)
struct Config {
  Method2D method;
  std::uint32_t resolution;
};

// defaults, plus resolutions that force crowded cells (one cell) or many thin cells
constexpr Config kConfigs[] = {
    {Method2D::Halfplane, 0}, {Method2D::Wedge, 0},   {Method2D::Slab, 0},
    {Method2D::Uniform, 0},   {Method2D::Uniform, 1}, {Method2D::Uniform, 1000},
    {Method2D::Polar, 0},     {Method2D::Polar, 1},   {Method2D::Polar, 37},
};

// the concrete class of `config`, its batch locate over `points`
std::vector<Location> concreteBatch(const ConvexPolygon& polygon, Config config,
                                    const std::vector<Vec2>& points) {
  std::vector<Location> out(points.size(), Location::Boundary);
  switch (config.method) {
    case Method2D::Halfplane: HalfplaneLocator(polygon).locate(points, out); break;
    case Method2D::Wedge: WedgeLocator(polygon).locate(points, out); break;
    case Method2D::Slab: SlabLocator(polygon).locate(points, out); break;
    case Method2D::Uniform: UniformLocator(polygon, config.resolution).locate(points, out); break;
    case Method2D::Polar: PolarLocator(polygon, config.resolution).locate(points, out); break;
  }
  return out;
}

// every query point for a shape: random, the generator's near-boundary set, adversarial
std::vector<Vec2> queryPoints(const shapes::ShapeCase& shape, const ConvexPolygon& polygon) {
  Rng rng(0x5eed0000u + shape.input.size());
  const PolarLocator polar(polygon);
  // without a centre, the fan's apex (vertex 0) stands in for it, as the query uses it
  const Vec2 centre = polar.centre().value_or(polygon.vertex(0));
  // (under the sanitizers a tenth of the random points, uniform and near the boundary: the
  // adversarial ones all stay)
  std::vector<Vec2> points = adversarial::randomPoints(
      polygon.bounds(), centre, testscale::scaled(shape.randomPoints, 1000), rng);
  std::vector<Vec2> near = generatePoints(polygon, testscale::scaled(2000, 200), 77, true);
  points.insert(points.end(), near.begin(), near.end());
  auto append = [&](const std::vector<Vec2>& more) {
    points.insert(points.end(), more.begin(), more.end());
  };
  append(adversarial::boundaryPoints(polygon, shape.input, rng));
  append(adversarial::polarPoints(polar, polygon));
  append(adversarial::polarPoints(PolarLocator(polygon, 37), polygon));
  append(adversarial::uniformPoints(UniformLocator(polygon), polygon, rng));
  append(adversarial::uniformPoints(UniformLocator(polygon, 1000), polygon, rng));
  return points;
}

// one line describing a wrong answer
std::string mismatch(const std::string& shape, Config config, const char* path, Vec2 p,
                     Location got, Location want) {
  std::ostringstream s;
  s << shape << " " << toString(config.method) << "(" << config.resolution << ") " << path << " at "
    << adversarial::show(p) << ": got " << toString(got) << ", reference says " << toString(want);
  return s.str();
}

class LocateExact : public testing::TestWithParam<std::size_t> {};

TEST_P(LocateExact, EveryMethodMatchesTheReference) {
  const shapes::ShapeCase& shape = shapes::cases()[GetParam()];
  const ConvexPolygon polygon(shape.input);
  // the reference classifies against the normalised ring; it must be the input's hull
  ASSERT_TRUE(ref::sameCycle(polygon.vertices(), ref::hull(shape.input))) << shape.name;

  const std::vector<Vec2> points = queryPoints(shape, polygon);
  std::vector<Location> want(points.size());
  std::size_t counts[3] = {0, 0, 0};
  for (std::size_t i = 0; i < points.size(); ++i) {
    want[i] = ref::locate(polygon.vertices(), points[i]);
    ++counts[static_cast<int>(want[i])];
  }
  // the matrix is only a proof if every class occurs (no double lies inside the ulp sliver)
  if (shape.name != "ulp_sliver") {
    EXPECT_GT(counts[static_cast<int>(Location::Inside)], 0u) << shape.name;
  } else {
    EXPECT_EQ(counts[static_cast<int>(Location::Inside)], 0u) << shape.name;
  }
  EXPECT_GT(counts[static_cast<int>(Location::Boundary)], 0u) << shape.name;
  EXPECT_GT(counts[static_cast<int>(Location::Outside)], 0u) << shape.name;

  for (Config config : kConfigs) {
    const Locator2D locator(polygon, config.method, config.resolution);
    ASSERT_EQ(locator.method(), config.method);
    // halfplane is O(N) per point (the reference has checked the same predicates on every
    // point): on large polygons it runs over every 4th point
    const std::size_t stride = config.method == Method2D::Halfplane && polygon.size() > 256 ? 4 : 1;
    std::vector<Vec2> sample;
    std::vector<Location> sampleWant;
    for (std::size_t i = 0; i < points.size(); i += stride) {
      sample.push_back(points[i]);
      sampleWant.push_back(want[i]);
    }
    std::vector<Location> batch(sample.size(), Location::Boundary);
    locator.locate(sample, batch);
    const std::vector<Location> concrete = concreteBatch(polygon, config, sample);
    std::size_t wrong = 0;
    auto check = [&](const char* path, Vec2 p, Location got, Location expected) {
      if (got == expected) return;
      if (++wrong <= 10) ADD_FAILURE() << mismatch(shape.name, config, path, p, got, expected);
    };
    for (std::size_t i = 0; i < sample.size(); ++i) {
      check("locate", sample[i], locator.locate(sample[i]), sampleWant[i]);
      check("Locator2D batch", sample[i], batch[i], sampleWant[i]);
      check("concrete batch", sample[i], concrete[i], sampleWant[i]);
    }
    EXPECT_EQ(wrong, 0u) << shape.name << " " << toString(config.method) << "(" << config.resolution
                         << "): " << wrong << " wrong answers over " << points.size() << " points";
  }
}

INSTANTIATE_TEST_SUITE_P(Shapes, LocateExact, testing::ValuesIn(shapes::caseIndices()),
                         shapes::CaseName());

// the batch leaves entries past the shorter of its two spans alone
TEST(LocateBatch, WritesOnlyTheCommonLength) {
  const ConvexPolygon square(std::vector<Vec2>{{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  const std::vector<Vec2> points = {{0.5, 0.5}, {2, 2}, {1, 1}};
  for (Method2D m : kAllMethods2D) {
    const Locator2D locator(square, m);
    std::vector<Location> out(5, Location::Boundary);
    locator.locate(points, std::span<Location>(out).first(2));
    EXPECT_EQ(out[0], Location::Inside) << toString(m);
    EXPECT_EQ(out[1], Location::Outside) << toString(m);
    EXPECT_EQ(out[2], Location::Boundary) << toString(m);
    std::vector<Location> longer(5, Location::Boundary);
    locator.locate(points, longer);
    EXPECT_EQ(longer[2], Location::Boundary) << toString(m);
    EXPECT_EQ(longer[3], Location::Boundary) << toString(m);
  }
}

// the locators keep their own copy: the polygon may go away after the build
TEST(LocateBatch, OutlivesThePolygon) {
  std::vector<Locator2D> locators;
  {
    const ConvexPolygon triangle(std::vector<Vec2>{{0, 0}, {4, 0}, {0, 4}});
    for (Method2D m : kAllMethods2D) locators.emplace_back(triangle, m);
  }
  for (const Locator2D& l : locators) {
    EXPECT_EQ(l.locate({1, 1}), Location::Inside) << toString(l.method());
    EXPECT_EQ(l.locate({2, 2}), Location::Boundary) << toString(l.method());
    EXPECT_EQ(l.locate({2.5, 2}), Location::Outside) << toString(l.method());
  }
}

// infinite and NaN coordinates are outside for every method, and never reach a predicate
TEST(LocateNonFinite, IsOutsideForEveryMethod) {
  const double inf = std::numeric_limits<double>::infinity();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const std::vector<Vec2> points = {{inf, 0.5}, {-inf, 0.5}, {0.5, inf}, {0.5, -inf}, {inf, inf},
                                    {nan, 0.5}, {0.5, nan},  {nan, nan}, {nan, inf},  {-inf, nan}};
  const std::vector<std::vector<Vec2>> polygons = {
      {{0, 0}, {1, 0}, {1, 1}, {0, 1}},
      {{0, 0}, {1, 1}, {1, 1 - 0x1p-53}},  // no centre: polar answers with the fan
      generatePolygon(PolygonKind::Regular, 64, 1)};
  for (const std::vector<Vec2>& input : polygons) {
    const ConvexPolygon polygon(input);
    for (Method2D m : kAllMethods2D)
      for (std::uint32_t resolution : {0u, 1u}) {
        const Locator2D locator(polygon, m, resolution);
        std::vector<Location> out(points.size(), Location::Inside);
        locator.locate(points, out);
        for (std::size_t i = 0; i < points.size(); ++i) {
          const std::string at = std::string(toString(m)) + " at " + adversarial::show(points[i]);
          EXPECT_EQ(locator.locate(points[i]), Location::Outside) << at;
          EXPECT_EQ(out[i], Location::Outside) << at;
          EXPECT_EQ(locator.trace(points[i]).result, Location::Outside) << at;
        }
      }
  }
}

// A polygon wider than the double range: directions from any centre overflow, so polar has
// no table and bisects the fan (the differential fuzz target found its build converting a
// NaN angle to a cell index); every method stays exact.
TEST(LocateExtreme, PolygonWiderThanTheDoubleRange) {
  const double M = std::numeric_limits<double>::max();
  const ConvexPolygon polygon(std::vector<Vec2>{{-M, -M}, {M, -M}, {M, M}, {-M, M}});
  const std::vector<std::pair<Vec2, Location>> cases = {
      {{0, 0}, Location::Inside},
      {{M, 0}, Location::Boundary},
      {{M, M}, Location::Boundary},
      {{-M, 1}, Location::Boundary},
      {{1e308, -1e308}, Location::Inside},
      {{-1e308, 1.5e308}, Location::Inside},
      {{0, -M}, Location::Boundary},
      {{1, std::numeric_limits<double>::infinity()}, Location::Outside}};
  for (Method2D m : kAllMethods2D) {
    const Locator2D locator(polygon, m);
    for (const auto& [p, want] : cases) {
      EXPECT_EQ(locator.locate(p), want) << toString(m) << " at " << adversarial::show(p);
      EXPECT_EQ(locator.trace(p).result, want) << toString(m) << " at " << adversarial::show(p);
    }
  }
}

// method names round-trip
TEST(Method2DNames, RoundTrip) {
  for (Method2D m : kAllMethods2D) EXPECT_EQ(parseMethod2D(toString(m)), m);
  EXPECT_FALSE(parseMethod2D("Polar").has_value());
  EXPECT_FALSE(parseMethod2D("").has_value());
  EXPECT_EQ(toString(Method2D::Polar), "polar");
}

}  // namespace
