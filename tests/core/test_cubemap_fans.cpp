// The cube map's fans (core/src/cubemap/sectors.cpp) on cylinders as CAD programs export
// them: turned by odd angles, moved to 10^6, rounded to float32 and read as their hulls, so
// that no two side edges are exactly parallel and no zone forms. Every answer is checked
// against the independent exact reference, for random points and hard ones: vertices, points
// on edges and faces, their ulp neighbours, cell borders, the centre, points along the rays
// through the fans' keys; the single-point query, the batch and the trace agree.
#include <gtest/gtest.h>

#include <cstdlib>
#include <string>
#include <vector>

#include "../bench/cad_family.hpp"
#include "adversarial3d.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/locate3d.hpp"
#include "reference3d.hpp"

using namespace convexloc;

namespace {

// `full` scaled by CONVEXLOC_HOSTILE_SCALE (the sanitized run shrinks it), at least `floor`
std::size_t scaled(std::size_t full, std::size_t floor) {
  const char* env = std::getenv("CONVEXLOC_HOSTILE_SCALE");
  double scale = env ? std::strtod(env, nullptr) : 1.0;
  if (!(scale > 0)) scale = 1.0;
  const auto n = static_cast<std::size_t>(static_cast<double>(full) * scale);
  return n < floor ? floor : n;
}

// the hard points: the surface's, the cube map's, and the rays through every vertex (the keys
// of the fans are vertices: on these rays p lies on or next to a key's plane through the axis)
std::vector<Vec3> hardPoints(const ConvexPolyhedron& p, const CubemapLocator& cm, Rng& rng) {
  std::vector<Vec3> out = adversarial3d::surfacePoints(p, scaled(800, 100), rng);
  const auto more = adversarial3d::cubemapPoints(p, cm, rng);
  out.insert(out.end(), more.begin(), more.end());
  const Vec3 c = *cm.centre();
  const auto v = p.vertices();
  const std::size_t step = std::max<std::size_t>(1, v.size() / scaled(200, 20));
  for (std::size_t i = 0; i < v.size(); i += step)
    adversarial3d::alongRay(out, p, c, {v[i].x - c.x, v[i].y - c.y, v[i].z - c.z});
  return out;
}

// every point's answer from locate, the batch and trace, against the reference
void expectExact(const ConvexPolyhedron& p, const CubemapLocator& cm,
                 const std::vector<Vec3>& pts) {
  const reftest::Reference ref(p);
  std::vector<Location> batch(pts.size());
  cm.locate(pts, batch);
  std::size_t wrong = 0, sectorTraces = 0;
  for (std::size_t i = 0; i < pts.size(); ++i) {
    const Location want = ref.locate(pts[i]);
    wrong += cm.locate(pts[i]) != want || batch[i] != want;
    if (i % 7 == 0) {
      const Trace3D t = cm.trace(pts[i], TraceOptions{.radii = false});
      wrong += t.result != want;
      sectorTraces += !t.sectorSteps.empty();
    }
    if (wrong) {
      ADD_FAILURE() << "wrong at " << pts[i].x << ' ' << pts[i].y << ' ' << pts[i].z;
      return;
    }
  }
  EXPECT_GT(sectorTraces, 0u) << "no traced point went through a fan's bisection";
}

struct Case {
  std::size_t sides;
  double height;
  bool moved;
};

class CadFans : public ::testing::TestWithParam<Case> {};

TEST_P(CadFans, LocatesExactlyThroughTheFans) {
  const Case k = GetParam();
  bool hull = false;
  const ConvexPolyhedron p = cadfamily::polyhedron({k.sides, k.height, k.moved}, &hull);
  EXPECT_TRUE(hull);  // float32 rounding folds every one of these
  const CubemapLocator cm(p);
  const Stats3D s = cm.stats();
  EXPECT_GT(s.sectorCells, 0u);
  EXPECT_LE(s.bytes, 128 * s.triangles + 65536);
  Rng rng(k.sides + static_cast<std::uint64_t>(k.height * 10));
  std::vector<Vec3> pts = generatePoints3D(p, scaled(4000, 400), 11, false);
  const auto near = generatePoints3D(p, scaled(2000, 200), 12, true);
  pts.insert(pts.end(), near.begin(), near.end());
  const auto hard = hardPoints(p, cm, rng);
  pts.insert(pts.end(), hard.begin(), hard.end());
  expectExact(p, cm, pts);
}

INSTANTIATE_TEST_SUITE_P(Cylinders, CadFans,
                         ::testing::Values(Case{512, 4, false}, Case{512, 10, true},
                                           Case{1024, 4, true}, Case{512, 10, false}),
                         [](const ::testing::TestParamInfo<Case>& param) {
                           return std::to_string(param.param.sides) + "sides_h" +
                                  std::to_string(static_cast<int>(param.param.height * 10)) +
                                  (param.param.moved ? "_moved" : "");
                         });

// the fans' tables and the cells of the larger parts within the cube map's memory bound
TEST(CadFans, LargerPartsStayWithin128BytesPerTriangle) {
  for (const Case k : {Case{scaled(4096, 1024), 1, false}, Case{scaled(4096, 1024), 10, true}}) {
    const ConvexPolyhedron p = cadfamily::polyhedron({k.sides, k.height, k.moved});
    const Stats3D s = CubemapLocator(p).stats();
    EXPECT_GT(s.sectorCells, 0u) << k.sides << " sides, height " << k.height;
    EXPECT_LE(s.bytes, 128 * s.triangles + 65536) << k.sides << " sides, height " << k.height;
  }
}

}  // namespace
