// Faces as planes and the cube map's zones: coplanar triangles merged exactly (a fan cap is
// one face, a quad's two triangles one face), and the thin faces of a cylinder's or a
// prism's side searched by bisection, exact against the independent reference on points
// chosen where the bisection decides: on the zone's edges, one ulp off them, on the caps'
// slivers and the rims.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <ostream>
#include <set>
#include <string>
#include <vector>

#include "adversarial3d.hpp"
#include "convexloc/error.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/locate3d.hpp"
#include "reference3d.hpp"
#include "scale.hpp"

using namespace convexloc;

namespace {

// points on every k-th edge of the mesh (middle and a third along), its ends, and their ulp
// neighbours; edges chosen across all triangles so zone edges and fan diagonals come in
std::vector<Vec3> edgePoints(const ConvexPolyhedron& p, std::size_t budget) {
  std::vector<Vec3> out;
  const auto v = p.vertices();
  const auto tri = p.triangles();
  const std::size_t step = std::max<std::size_t>(1, tri.size() / budget);
  for (std::size_t t = 0; t < tri.size(); t += step)
    for (int k = 0; k < 3; ++k) {
      const Vec3 a = v[tri[t][k]], b = v[tri[t][(k + 1) % 3]];
      for (double s : {0.5, 1.0 / 3, 0.9})
        adversarial3d::withNeighbours(
            out, {a.x + s * (b.x - a.x), a.y + s * (b.y - a.y), a.z + s * (b.z - a.z)});
      adversarial3d::withNeighbours(out, a);
    }
  return out;
}

// every point's class from each 3D method, one by one and in a batch, equals the reference's
void expectExact(const ConvexPolyhedron& p, const std::vector<Vec3>& points, const char* what) {
  const reftest::Reference ref(p);
  ASSERT_TRUE(ref.sound());
  const CubemapLocator cm(p);
  const WalkLocator walk(p);
  std::vector<Location> batch(points.size());
  cm.locate(points, batch);
  std::size_t wrong = 0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Location want = ref.locate(points[i]);
    const Location got[] = {cm.locate(points[i]), batch[i], walk.locate(points[i]),
                            i % 31 == 0 ? cm.trace(points[i]).result : want};
    for (Location g : got)
      if (g != want && ++wrong <= 5)
        ADD_FAILURE() << what << " point " << i << " (" << points[i].x << ", " << points[i].y
                      << ", " << points[i].z << "): got " << toString(g) << ", reference "
                      << toString(want);
  }
  EXPECT_EQ(wrong, 0u) << what;
}

}  // namespace

TEST(Planes, FanCapsAndQuadsMergeIntoOneFaceEach) {
  for (std::size_t sides : {3u, 64u, 1000u}) {
    const ConvexPolyhedron p(generatePolyhedron(PolyhedronKind::Cylinder, 4 * sides - 4, 1));
    EXPECT_EQ(p.faceCount(), 4 * sides - 4);
    ASSERT_EQ(p.planeCount(), sides + 2) << sides;
    std::size_t caps = 0;
    for (std::size_t f = 0; f < p.planeCount(); ++f) {
      const auto loop = p.planeLoop(f);
      caps += loop.size() == sides;
      if (loop.size() != sides) {
        EXPECT_EQ(loop.size(), 4u);
      }
      // the fat triangle lies in the face: every corner of the loop is on its plane
      const auto& t = p.planes()[f];
      const auto v = p.vertices();
      for (std::uint32_t w : loop) EXPECT_EQ(reftest::orient(v[t[0]], v[t[1]], v[t[2]], v[w]), 0);
      // and its inner side holds the centre
      EXPECT_GT(p.side(p.planeTriangles(f)[0], *p.centre()), 0);
      EXPECT_GT(reftest::orient(v[t[0]], v[t[1]], v[t[2]], *p.centre()), 0);
      for (std::uint32_t tri : p.planeTriangles(f)) EXPECT_EQ(p.planeOf()[tri], f);
    }
    EXPECT_EQ(caps, 2u) << sides;
  }
}

TEST(Planes, WithoutCoplanarNeighboursFaceTIsTriangleT) {
  const ConvexPolyhedron p(generatePolyhedron(PolyhedronKind::Geodesic, 1280, 1));
  ASSERT_EQ(p.planeCount(), p.faceCount());
  for (std::size_t t = 0; t < p.faceCount(); ++t) {
    EXPECT_EQ(p.planes()[t], p.triangles()[t]);
    EXPECT_EQ(p.planeOf()[t], t);
  }
  const ConvexPolyhedron cube(generatePolyhedron(PolyhedronKind::Coplanar, 300, 1));
  EXPECT_EQ(cube.planeCount(), 6u);  // each face's k x k grid of squares is one face
  EXPECT_EQ(CubemapLocator(cube).stats().faces, 6u);
  EXPECT_EQ(HalfspaceLocator(cube).stats().triangles, cube.faceCount());
}

namespace {

// a shape of the exactness test, its size asked of the generator (CONVEXLOC_HOSTILE_SCALE
// scales the large ones, as under the sanitizers)
struct ThinFacedShape {
  const char* name;  // with the full size, the same in every run
  PolyhedronKind kind;
  std::size_t n;
};

// the name in gtest's listing of the parameter
void PrintTo(const ThinFacedShape& shape, std::ostream* out) {
  *out << shape.name;
}

class PlanesExact : public testing::TestWithParam<ThinFacedShape> {};

}  // namespace

TEST_P(PlanesExact, CylindersAndPrismsAreExact) {
  const auto [name, kind, n] = GetParam();
  SCOPED_TRACE(std::string(name) + " at size " + std::to_string(n));
  const ConvexPolyhedron p(generatePolyhedron(kind, n, 1));
  Rng rng(17);
  // the reference tests every face: the 16380-triangle cylinder gets a quarter of the
  // random points (its zones and cells get every adversarial point all the same)
  const std::size_t share = n > 10000 ? 4 : 1;
  std::vector<Vec3> points = generatePoints3D(p, 6000 / share, 3, false);
  auto append = [&](const std::vector<Vec3>& more) {
    points.insert(points.end(), more.begin(), more.end());
  };
  append(generatePoints3D(p, 6000 / share, 4, true));
  append(edgePoints(p, 600));
  append(adversarial3d::surfacePoints(p, 800, rng));
  append(adversarial3d::cubemapPoints(p, CubemapLocator(p), rng));
  expectExact(p, points, toString(kind).data());
}

// each shape its own test, so that they run side by side
INSTANTIATE_TEST_SUITE_P(
    Planes, PlanesExact,
    testing::Values(
        ThinFacedShape{"cylinder_252", PolyhedronKind::Cylinder, 252},
        ThinFacedShape{"cylinder_16380", PolyhedronKind::Cylinder, testscale::scaled(16380, 1020)},
        ThinFacedShape{"prism_4000", PolyhedronKind::Prism, testscale::scaled(4000, 400)}),
    [](const testing::TestParamInfo<ThinFacedShape>& param) { return param.param.name; });

TEST(Planes, ThinSideFacesAreSearchedByBisection) {
  const ConvexPolyhedron p(generatePolyhedron(PolyhedronKind::Cylinder, 16380, 1));
  const CubemapLocator cm(p);
  const Stats3D s = cm.stats();
  EXPECT_GT(s.zoneCells, 0u);
  EXPECT_LE(s.bytesPerFace, 128.0);
  // a point on a side face, halfway up: its cell lies over the zone of 4096 faces, and the
  // bisection takes about lg of the cell's share of them, then one or two plane tests
  std::size_t traced = 0;
  for (std::size_t f = 0; f < p.planeCount(); f += 37) {
    if (p.planeLoop(f).size() != 4) continue;
    const auto v = p.vertices();
    const auto loop = p.planeLoop(f);
    Vec3 m{0, 0, 0};
    for (std::uint32_t w : loop) m = {m.x + v[w].x / 4, m.y + v[w].y / 4, m.z + v[w].z / 4};
    const Trace3D t = cm.trace(m, TraceOptions{.radii = false});
    if (t.zoneSteps.empty()) continue;
    ++traced;
    EXPECT_LE(t.zoneSteps.size(), 12u);
    EXPECT_LE(t.faces.size(), 3u);
    EXPECT_TRUE(std::any_of(t.faces.begin(), t.faces.end(),
                            [&](const FaceTest& ft) { return ft.face == f || ft.sign <= 0; }));
  }
  EXPECT_GT(traced, 50u);
}

TEST(Planes, AFaceNotExactlyPlanarIsNamedWithItsDistanceAndTheWayOut) {
  // a cube given as 6 quads, one corner pushed 1e-9 into the cube: the top quad folds inwards
  MeshData m;
  for (double z : {-1.0, 1.0})
    for (double y : {-1.0, 1.0})
      for (double x : {-1.0, 1.0}) m.addVertex({x, y, z});
  m.vertices[7].z = 1 - 1e-9;
  m.addFace({7, 6, 4, 5});  // top, from the pushed corner
  m.addFace({0, 2, 3, 1});  // bottom
  m.addFace({0, 1, 5, 4});
  m.addFace({2, 6, 7, 3});
  m.addFace({0, 4, 6, 2});
  m.addFace({1, 3, 7, 5});
  try {
    const ConvexPolyhedron p(m);
    FAIL() << "accepted a face that folds inwards";
  } catch (const GeometryError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("face 0 is not planar"), std::string::npos) << what;
    // the fan from corner 7 folds along 7-4: corner 5 lies off the plane of 7, 6 and 4
    EXPECT_NE(what.find("vertex 5"), std::string::npos) << what;
    EXPECT_NE(what.find("vertices 7, 6 and 4"), std::string::npos) << what;
    EXPECT_NE(what.find("1e-09 off the plane"), std::string::npos) << what;
    EXPECT_NE(what.find("--hull"), std::string::npos) << what;
  }
  // the hull of the same corners is valid: the top folds outwards in two plane faces (the
  // sides x = 1 and y = 1 stay planar)
  const ConvexPolyhedron hull = ConvexPolyhedron::hullOf(m.vertices);
  EXPECT_EQ(hull.vertexCount(), 8u);
  EXPECT_EQ(hull.planeCount(), 7u);
}
