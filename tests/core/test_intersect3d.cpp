// Plane against polyhedron: both methods against an exact rational reference (every
// vertex's orient3d in GMP rationals) on every generator kind, scaled to huge and tiny
// coordinates, with random planes and planes through vertices, edges and faces, one ulp off
// them, and nearly parallel to faces.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <span>
#include <string>
#include <vector>

#include "convexloc/generate3d.hpp"
#include "convexloc/intersect3d.hpp"
#include "convexloc/locate3d.hpp"
#include "convexloc/polyhedron.hpp"
#include "reference3d.hpp"
#include "scale.hpp"

namespace {

using convexloc::ConvexPolyhedron;
using convexloc::Crossing;
using convexloc::MeshData;
using convexloc::PlaneIntersector;
using convexloc::PlaneMethod;
using convexloc::PolyhedronKind;
using convexloc::Vec3;

// the crossing from every vertex's exact side
Crossing referenceCrossing(std::span<const Vec3> vertices, Vec3 a, Vec3 b, Vec3 c) {
  bool above = false, below = false, on = false;
  for (const Vec3 v : vertices) {
    const int s = reftest::orient(a, b, c, v);
    above |= s > 0;
    below |= s < 0;
    on |= s == 0;
  }
  if (above && below) return Crossing::Crosses;
  return on ? Crossing::Touches : Crossing::Misses;
}

// the mesh scaled by 2^e
MeshData scaled(MeshData m, int e) {
  for (Vec3& v : m.vertices) v = {std::ldexp(v.x, e), std::ldexp(v.y, e), std::ldexp(v.z, e)};
  return m;
}

struct Plane {
  Vec3 a, b, c;
};

std::string show(Vec3 p) {
  char buf[160];
  std::snprintf(buf, sizeof buf, "(%a, %a, %a)", p.x, p.y, p.z);
  return buf;
}

// random planes through the enlarged box, and planes through vertices, edges and faces, one
// ulp off them, through the middle, and nearly parallel to faces
std::vector<Plane> planesFor(const ConvexPolyhedron& p, std::size_t randomCount,
                             std::uint64_t seed) {
  convexloc::Rng rng(seed);
  const convexloc::Box3 box = p.bounds();
  const Vec3 size{box.hi.x - box.lo.x, box.hi.y - box.lo.y, box.hi.z - box.lo.z};
  auto randomPoint = [&] {
    return Vec3{rng.uniform(box.lo.x - 0.2 * size.x, box.hi.x + 0.2 * size.x),
                rng.uniform(box.lo.y - 0.2 * size.y, box.hi.y + 0.2 * size.y),
                rng.uniform(box.lo.z - 0.2 * size.z, box.hi.z + 0.2 * size.z)};
  };
  auto ulp = [](Vec3 v, int k) {
    const double inf = std::numeric_limits<double>::infinity();
    return Vec3{std::nextafter(v.x, (k & 1) ? inf : -inf), v.y,
                std::nextafter(v.z, (k & 2) ? inf : -inf)};
  };
  const Vec3 middle{box.lo.x * 0.5 + box.hi.x * 0.5, box.lo.y * 0.5 + box.hi.y * 0.5,
                    box.lo.z * 0.5 + box.hi.z * 0.5};
  std::vector<Plane> out;
  auto add = [&](Vec3 a, Vec3 b, Vec3 c) {
    for (Vec3 v : {a, b, c})
      if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z)) return;
    if (convexloc::collinear(a, b, c)) return;
    out.push_back({a, b, c});
    out.push_back({a, c, b});
  };
  for (std::size_t k = 0; k < randomCount; ++k) add(randomPoint(), randomPoint(), randomPoint());
  const auto v = p.vertices();
  const auto tri = p.triangles();
  const std::size_t step = std::max<std::size_t>(1, tri.size() / 48);
  for (std::size_t f = 0; f < tri.size(); f += step) {
    const Vec3 a = v[tri[f][0]], b = v[tri[f][1]], c = v[tri[f][2]];
    add(a, b, c);                          // through a face
    add(a, b, randomPoint());              // through an edge
    add(a, randomPoint(), randomPoint());  // through a vertex
    add(a, b, middle);                     // through an edge and the middle
    add(a, v[(tri[f][0] + v.size() / 2) % v.size()], v[(tri[f][1] + v.size() / 3) % v.size()]);
    for (int k = 0; k < 4; ++k) {
      add(ulp(a, k), b, c);  // one ulp off a face
      add(ulp(a, k), ulp(b, k), ulp(c, k));
    }
    const double shift = (rng.uniform() - 0.5) * (std::fabs(a.x - b.x) + std::fabs(a.y - b.y));
    add({a.x, a.y, a.z + shift}, {b.x, b.y, b.z + shift}, {c.x, c.y, c.z + shift});
  }
  return out;
}

// a shape of the matrix: its name, and how to make it (gtest names every case in every
// process it starts, so naming builds nothing)
struct Case3D {
  std::string name;
  std::function<MeshData()> mesh;
};

const std::vector<Case3D>& cases() {
  static const std::vector<Case3D> all = [] {
    std::vector<Case3D> out;
    for (PolyhedronKind k : convexloc::kAllPolyhedronKinds) {
      std::string name(convexloc::toString(k));
      for (char& ch : name)
        if (ch == '-') ch = '_';
      out.push_back({name, [k] { return convexloc::generatePolyhedron(k, 300, 1); }});
    }
    out.push_back({"geodesic_5120", [] {
                     return convexloc::generatePolyhedron(PolyhedronKind::Geodesic, 5120, 1);
                   }});
    auto ico = [] { return convexloc::generatePolyhedron(PolyhedronKind::Geodesic, 80, 1); };
    out.push_back({"huge_2e997", [ico] { return scaled(ico(), 997); }});
    out.push_back({"tiny_2e_1000", [ico] { return scaled(ico(), -1000); }});
    out.push_back({"subnormal_cube", [] {
                     const PolyhedronKind cube = PolyhedronKind::Cube;
                     return scaled(convexloc::generatePolyhedron(cube, 12, 1), -1070);
                   }});
    return out;
  }();
  return all;
}

class Intersect3DExact : public testing::TestWithParam<std::size_t> {};

TEST_P(Intersect3DExact, BothMethodsMatchTheReference) {
  const ConvexPolyhedron p(cases()[GetParam()].mesh());
  const PlaneIntersector vertices(p, PlaneMethod::Vertices), dual(p, PlaneMethod::Dual);
  std::size_t crosses = 0, touches = 0;
  // random planes scaled under the sanitizers (scale.hpp); the adversarial ones all kept
  const auto planes = planesFor(p, testscale::scaled(300, 30), GetParam() + 7);
  // the batch of both methods, in one call (blocks, prefetching, a partial last block)
  std::vector<Vec3> flat;
  for (const Plane& pl : planes) flat.insert(flat.end(), {pl.a, pl.b, pl.c});
  std::vector<Crossing> viaVertices(planes.size()), viaDual(planes.size());
  vertices.classify(std::span(flat), std::span(viaVertices));
  dual.classify(std::span(flat), std::span(viaDual));
  for (std::size_t k = 0; k < planes.size(); ++k) {
    const Plane& pl = planes[k];
    const Crossing want = referenceCrossing(p.vertices(), pl.a, pl.b, pl.c);
    ASSERT_EQ(viaVertices[k], want) << "batch plane " << k;
    ASSERT_EQ(viaDual[k], want) << "batch plane " << k;
    crosses += want == Crossing::Crosses;
    touches += want == Crossing::Touches;
    for (const PlaneIntersector* pi : {&vertices, &dual}) {
      const std::string where = std::string(convexloc::toString(pi->method())) + " plane " +
                                show(pl.a) + show(pl.b) + show(pl.c);
      ASSERT_EQ(pi->classify(pl.a, pl.b, pl.c), want) << where;
      const convexloc::PlaneTrace t = pi->trace(pl.a, pl.b, pl.c);
      ASSERT_EQ(t.crossing, want) << where;
    }
  }
  EXPECT_GT(crosses, 0u);
  EXPECT_GT(touches, 0u);
}

std::vector<std::size_t> indices() {
  std::vector<std::size_t> out(cases().size());
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = i;
  return out;
}

INSTANTIATE_TEST_SUITE_P(Shapes, Intersect3DExact, testing::ValuesIn(indices()),
                         [](const testing::TestParamInfo<std::size_t>& param) {
                           return cases()[param.param].name;
                         });

// a fine geodesic sphere: the cube map's proposals are the extremes or within a few moves
TEST(Intersect3DDual, GeodesicClimbsLittle) {
  const ConvexPolyhedron p(convexloc::generatePolyhedron(PolyhedronKind::Geodesic, 20000, 1));
  const PlaneIntersector dual(p, PlaneMethod::Dual);
  ASSERT_NE(dual.dualLocator(), nullptr);
  convexloc::Rng rng(3);
  std::uint32_t worst = 0;
  for (int k = 0; k < 5000; ++k) {
    const Vec3 a{rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2)};
    const Vec3 b{rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2)};
    const Vec3 c{rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2)};
    const convexloc::PlaneTrace t = dual.trace(a, b, c);
    ASSERT_TRUE(t.proposed);
    worst = std::max(worst, t.climbSteps);
  }
  EXPECT_LE(worst, 8u);  // both climbs together
  const convexloc::PlaneStats s = dual.stats();
  EXPECT_EQ(s.faces, p.faceCount());
  EXPECT_GT(s.dualFaces, 0u);
  EXPECT_GT(s.cells, 0u);
}

// the trace's direction is the unit -N, and every face of the dual the cube map locates in
// is labelled with the vertex farthest along its middle direction
TEST(Intersect3DDual, TraceReportsTheDirectionAndItsCell) {
  const ConvexPolyhedron p(convexloc::generatePolyhedron(PolyhedronKind::Geodesic, 500, 1));
  const PlaneIntersector dual(p, PlaneMethod::Dual);
  const convexloc::CubemapLocator* cube = dual.dualLocator();
  ASSERT_NE(cube, nullptr);
  ASSERT_EQ(dual.dualLabels().size(), cube->faces().size());
  EXPECT_EQ(cube->vertices().size(), dual.stats().dualVertices);
  // N = (q2 - q1) x (q3 - q1) = (0, 0, 1): G grows along -z
  const convexloc::PlaneTrace t = dual.trace({0, 0, 0.25}, {1, 0, 0.25}, {0, 1, 0.25});
  EXPECT_EQ(t.direction.x, 0.0);
  EXPECT_EQ(t.direction.y, 0.0);
  EXPECT_EQ(t.direction.z, -1.0);
  const auto listed = cube->cellFaces(t.direction);
  ASSERT_FALSE(listed.empty());
  const auto q = cube->vertices();
  const auto v = p.vertices();
  for (std::size_t f = 0; f < cube->faces().size(); ++f) {
    const auto& tri = cube->faces()[f];
    const Vec3 mid{q[tri[0]].x + q[tri[1]].x + q[tri[2]].x, q[tri[0]].y + q[tri[1]].y + q[tri[2]].y,
                   q[tri[0]].z + q[tri[1]].z + q[tri[2]].z};
    auto along = [&](std::uint32_t k) { return mid.x * v[k].x + mid.y * v[k].y + mid.z * v[k].z; };
    double best = along(0);
    for (std::uint32_t k = 1; k < v.size(); ++k) best = std::max(best, along(k));
    ASSERT_LT(dual.dualLabels()[f], v.size());
    EXPECT_NEAR(along(dual.dualLabels()[f]), best, 1e-12) << f;
  }
  const PlaneIntersector baseline(p, PlaneMethod::Vertices);
  EXPECT_TRUE(baseline.dualLabels().empty());
  const convexloc::PlaneTrace b = baseline.trace({0, 0, 0.25}, {1, 0, 0.25}, {0, 1, 0.25});
  EXPECT_EQ(b.direction.z, 0.0);
}

// the batch over every length around its blocks (three in flight), against one plane at a
// time, on a coarse polyhedron (long climbs) and a fine one
TEST(Intersect3DDual, BatchLengthsAgreeWithSingle) {
  for (std::size_t faces : {12, 5120}) {
    const ConvexPolyhedron p(convexloc::generatePolyhedron(PolyhedronKind::Geodesic, faces, 1));
    const PlaneIntersector dual(p, PlaneMethod::Dual);
    convexloc::Rng rng(9);
    std::vector<Vec3> flat;
    for (int k = 0; k < 3 * 70; ++k)
      flat.push_back({rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2)});
    for (std::size_t count : {0, 1, 15, 16, 17, 32, 33, 48, 49, 70}) {
      std::vector<Crossing> out(count, Crossing::Touches);
      dual.classify(std::span(flat).first(3 * count), std::span(out));
      for (std::size_t k = 0; k < count; ++k) {
        const Vec3* q = flat.data() + 3 * k;
        ASSERT_EQ(out[k], dual.classify(q[0], q[1], q[2])) << faces << " " << count << " " << k;
        ASSERT_EQ(out[k], referenceCrossing(p.vertices(), q[0], q[1], q[2]));
      }
    }
  }
}

// A cone over a 48-gon, huge and tiny: its apex and the vertex its base's triangles fan from
// have degrees far above what a grid cell copies, so cells proposing them reach their
// records by index. Every plane, one at a time, in a batch and traced, matches the reference,
// and such a vertex is proposed.
// random planes per magnitude in the high-degree test (a tenth under the sanitizers)
constexpr std::size_t kHighDegreePlanes = 300;

TEST(Intersect3DDual, HighDegreeVerticesMatchTheReference) {
  for (int e : {0, 600, -600}) {
    std::vector<Vec3> points{{0, 0, std::ldexp(1.0, e)}};
    for (int k = 0; k < 48; ++k) {
      const double a = 2 * 3.141592653589793 * k / 48;
      points.push_back(
          {std::ldexp(std::cos(a), e), std::ldexp(std::sin(a), e), -std::ldexp(0.5, e)});
    }
    const ConvexPolyhedron p = ConvexPolyhedron::hullOf(points);
    std::vector<std::size_t> degree(p.vertexCount(), 0);
    for (const auto& t : p.triangles())
      for (const std::uint32_t v : t) ++degree[v];
    const PlaneIntersector dual(p, PlaneMethod::Dual);
    const auto planes = planesFor(p, testscale::scaled(kHighDegreePlanes, 30), 17);
    std::vector<Vec3> flat;
    for (const Plane& pl : planes) flat.insert(flat.end(), {pl.a, pl.b, pl.c});
    std::vector<Crossing> batch(planes.size());
    dual.classify(std::span(flat), std::span(batch));
    std::size_t highProposed = 0;
    for (std::size_t k = 0; k < planes.size(); ++k) {
      const Plane& pl = planes[k];
      const Crossing want = referenceCrossing(p.vertices(), pl.a, pl.b, pl.c);
      const std::string where = "plane " + show(pl.a) + show(pl.b) + show(pl.c);
      ASSERT_EQ(dual.classify(pl.a, pl.b, pl.c), want) << where;
      ASSERT_EQ(batch[k], want) << where;
      const convexloc::PlaneTrace t = dual.trace(pl.a, pl.b, pl.c);
      ASSERT_EQ(t.crossing, want) << where;
      highProposed += degree[t.startMax] > 8 || degree[t.startMin] > 8;
    }
    EXPECT_GT(highProposed, 0u) << e;
  }
}

TEST(Intersect3DNames, RoundTripAndCollinear) {
  for (PlaneMethod m : convexloc::kAllPlaneMethods)
    EXPECT_EQ(convexloc::parsePlaneMethod(convexloc::toString(m)), m);
  EXPECT_FALSE(convexloc::parsePlaneMethod("cubemap"));
  EXPECT_TRUE(convexloc::collinear({0, 0, 0}, {1, 1, 1}, {2, 2, 2}));
  EXPECT_TRUE(convexloc::collinear({1, 2, 3}, {1, 2, 3}, {4, 5, 6}));
  EXPECT_FALSE(convexloc::collinear({0, 0, 0}, {1, 1, 1}, {2, 2, 2.0000000000000004}));
}

}  // namespace
