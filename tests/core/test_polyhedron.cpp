// ConvexPolyhedron: what it accepts and normalises, and every rejection with its message;
// hulls; the generators' shapes.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "convexloc/error.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/locate3d.hpp"
#include "convexloc/polyhedron.hpp"
#include "convexloc/predicates.hpp"
#include "reference3d.hpp"
#include "shapes3d.hpp"

using namespace convexloc;
using shapes3d::failureOf;
using testing::HasSubstr;

namespace {

// every face has the polyhedron's centre strictly on its inner side
bool facesPointOut(const ConvexPolyhedron& p) {
  const Vec3 c = *p.centre();
  for (std::size_t t = 0; t < p.faceCount(); ++t)
    if (p.side(t, c) <= 0) return false;
  return true;
}

// the cube with its top face replaced by `top` (indices into the cube's vertices, extended)
MeshData cubeWithTop(std::vector<Vec3> extra, std::vector<std::uint32_t> top) {
  MeshData m = shapes3d::cube();
  MeshData out;
  out.vertices = m.vertices;
  for (Vec3 v : extra) out.addVertex(v);
  for (std::size_t f = 0; f + 1 < m.faceCount(); ++f) out.addFace(m.face(f));
  out.addFace(top);
  return out;
}

}  // namespace

// === Accepted shapes

TEST(Polyhedron3D, CubeIsTriangulatedAndOutward) {
  ConvexPolyhedron p(shapes3d::cube());
  EXPECT_EQ(p.faceCount(), 12u);
  EXPECT_EQ(p.vertexCount(), 8u);
  EXPECT_EQ(p.inputFaces(), 6u);
  EXPECT_FALSE(p.wasInverted());
  ASSERT_TRUE(p.centre().has_value());
  EXPECT_TRUE(facesPointOut(p));
  EXPECT_DOUBLE_EQ(p.volume(), 8.0);
  EXPECT_DOUBLE_EQ(p.area(), 24.0);
  // each triangle comes from its square, fan from the square's first vertex
  EXPECT_EQ(p.sourceFace()[0], 0u);
  EXPECT_EQ(p.sourceFace()[1], 0u);
  EXPECT_EQ(p.triangles()[0][0], p.triangles()[1][0]);
  // neighbours are mutual and share the edge
  for (std::size_t t = 0; t < p.faceCount(); ++t)
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t u = p.neighbours()[t][k];
      const std::uint32_t a = p.triangles()[t][k], b = p.triangles()[t][(k + 1) % 3];
      bool back = false;
      for (int j = 0; j < 3; ++j)
        back |= p.triangles()[u][j] == b && p.triangles()[u][(j + 1) % 3] == a &&
                p.neighbours()[u][j] == t;
      EXPECT_TRUE(back) << t << ' ' << k;
    }
}

TEST(Polyhedron3D, InvertedMeshIsReversedSilently) {
  ConvexPolyhedron p(shapes3d::reversed(shapes3d::cube()));
  EXPECT_TRUE(p.wasInverted());
  EXPECT_TRUE(facesPointOut(p));
  EXPECT_DOUBLE_EQ(p.volume(), 8.0);
}

TEST(Polyhedron3D, EqualVerticesMergeAndUnusedOnesGo) {
  MeshData m = shapes3d::cube();
  m.addVertex({5, 5, 5});                             // unused
  const std::uint32_t copy = m.addVertex({1, 1, 1});  // equal to vertex 7
  m.indices[m.faceStart[5] + 2] = copy;               // the top face uses the copy
  ConvexPolyhedron p(m);
  EXPECT_EQ(p.vertexCount(), 8u);
  EXPECT_EQ(p.mergedVertices(), 1u);
  EXPECT_EQ(p.unusedVertices(), 1u);
  EXPECT_TRUE(facesPointOut(p));
}

TEST(Polyhedron3D, ConsecutiveRepeatsInAFaceAreDropped) {
  MeshData m = shapes3d::cube();
  MeshData out;
  out.vertices = m.vertices;
  for (std::size_t f = 0; f + 1 < m.faceCount(); ++f) out.addFace(m.face(f));
  out.addFace({1, 5, 5, 7, 3, 1});
  ConvexPolyhedron p(out);
  EXPECT_EQ(p.faceCount(), 12u);
}

TEST(Polyhedron3D, CoplanarNeighboursAreValid) {
  ConvexPolyhedron p(generatePolyhedron(PolyhedronKind::Coplanar, 300, 1));
  EXPECT_GT(p.faceCount(), 200u);
  EXPECT_NEAR(p.volume(), 8.0, 1e-12);
}

TEST(Polyhedron3D, ZeroAreaFanTrianglesAreFlippedAway) {
  // a vertex in the middle of the top-front edge, used by the top and the front faces: the
  // top's fan from (-1, -1, 1) starts with a zero-area triangle
  MeshData m = shapes3d::cube();
  MeshData out;
  out.vertices = m.vertices;
  const std::uint32_t mid = out.addVertex({0, -1, 1});
  out.addFace(m.face(0));
  out.addFace(m.face(1));
  out.addFace({0, 4, 5, mid, 1});  // y = -1, through the middle vertex
  out.addFace(m.face(3));
  out.addFace(m.face(4));
  out.addFace({1, mid, 5, 7, 3});  // z = +1
  ConvexPolyhedron p(out);
  EXPECT_GE(p.flippedSlivers(), 1u);
  EXPECT_DOUBLE_EQ(p.volume(), 8.0);
  for (std::size_t t = 0; t < p.faceCount(); ++t) {
    const auto& f = p.triangles()[t];
    const Vec3 a = p.vertices()[f[0]], b = p.vertices()[f[1]], c = p.vertices()[f[2]];
    const double nx = (b.y - a.y) * (c.z - a.z) - (b.z - a.z) * (c.y - a.y);
    const double ny = (b.z - a.z) * (c.x - a.x) - (b.x - a.x) * (c.z - a.z);
    const double nz = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    EXPECT_GT(nx * nx + ny * ny + nz * nz, 0.0) << "triangle " << t << " has zero area";
  }
  reftest::Reference ref(p);
  CubemapLocator cm(p);
  for (Vec3 q : std::vector<Vec3>{
           {0, -1, 1}, {0.5, -1, 1}, {0, 0, 1}, {0, -1, 0.5}, {0, -0.5, 0.5}, {0, -1, 1.5}})
    EXPECT_EQ(cm.locate(q), ref.locate(q));
}

TEST(Polyhedron3D, ThinnerThanTheDoubleGridHasNoCentreButValidates) {
  // a tetrahedron one ulp tall at z = 2^30: no double lies strictly inside
  const double z = 0x1p30, up = std::nextafter(z, 2 * z);
  ConvexPolyhedron p(shapes3d::tetrahedron({0, 0, z}, {1, 0, z}, {0, 1, z}, {0, 0, up}));
  EXPECT_FALSE(p.centre().has_value());
  reftest::Reference ref(p);
  for (const Method3D m : kAllMethods3D) {
    Locator3D loc(p, m);
    for (Vec3 q : std::vector<Vec3>{{0, 0, z},
                                    {0.25, 0.25, z},
                                    {0.25, 0.25, up},
                                    {0.1, 0.1, std::nextafter(up, 2 * z)},
                                    {-0.1, 0.1, z},
                                    {0.6, 0.6, z},
                                    {0, 0, up}})
      EXPECT_EQ(loc.locate(q), ref.locate(q)) << toString(m);
    EXPECT_TRUE(loc.trace({0.25, 0.25, z}).fallback || m == Method3D::Halfspace);
  }
}

TEST(Polyhedron3D, BoxesFromTheSmallestSubnormalStepToTheLargestDoubleValidate) {
  constexpr double kMax = std::numeric_limits<double>::max();
  constexpr double kStep = std::numeric_limits<double>::denorm_min();
  struct Case {
    Vec3 lo, hi;
  };
  // one subnormal step thick: no double strictly inside, the exact way decides (the fuzzer's
  // tests/data/fuzz/differential/box-one-subnormal-step-thick); three steps thick and as wide
  // as the doubles: a double centre, differences that overflow (halving them lost the thin
  // axis: both were said to wind twice)
  for (const Case& c : {Case{{8.5829409986692742e-310, -3.8944703855129008e-270, -0.0},
                             {kMax, -1e-300, kStep}},
                        Case{{-kMax, -1, 0}, {kMax, 1, 3 * kStep}},
                        Case{{-kMax, -kMax, -kMax}, {kMax, kStep, kMax}},
                        Case{{0, 0, 0}, {kStep, kStep, kStep}}}) {
    const MeshData m = shapes3d::box(c.lo, c.hi);
    ConvexPolyhedron p(m);
    EXPECT_EQ(p.faceCount(), 12u);
    reftest::Reference ref(p);
    std::vector<Vec3> queries(m.vertices.begin(), m.vertices.end());
    const Vec3 mid{c.lo.x / 2 + c.hi.x / 2, c.lo.y / 2 + c.hi.y / 2, c.lo.z / 2 + c.hi.z / 2};
    queries.push_back(mid);
    queries.push_back({mid.x, mid.y, std::nextafter(c.hi.z, kMax)});
    queries.push_back({mid.x, mid.y, c.lo.z});
    queries.push_back({std::nextafter(c.lo.x, -kMax), mid.y, mid.z});
    for (const Method3D method : kAllMethods3D) {
      Locator3D loc(p, method);
      for (const Vec3& q : queries) EXPECT_EQ(loc.locate(q), ref.locate(q)) << toString(method);
    }
  }
}

TEST(Polyhedron3D, LargeOffsetKeepsExactness) {
  ConvexPolyhedron p(generatePolyhedron(PolyhedronKind::Offset, 500, 1));
  ASSERT_TRUE(p.centre().has_value());
  EXPECT_GT(p.bounds().lo.x, 1e9 - 10);
}

// === Rejections, each naming its witness

TEST(Polyhedron3DReject, IndexOutOfRange) {
  MeshData m = shapes3d::cube();
  m.indices[5] = 9;
  m.faceLines = {11, 12, 13, 14, 15, 16};
  auto f = failureOf(m);
  EXPECT_TRUE(f.geometry);
  EXPECT_THAT(f.message, HasSubstr("face 1 refers to vertex 9, but there are only 8 vertices"));
  EXPECT_EQ(f.line, 12u);
}

TEST(Polyhedron3DReject, NonFiniteCoordinate) {
  MeshData m = shapes3d::cube();
  m.vertices[3].y = std::numeric_limits<double>::quiet_NaN();
  m.vertexLines = {2, 3, 4, 5, 6, 7, 8, 9};
  auto f = failureOf(m);
  EXPECT_THAT(f.message, HasSubstr("vertex 3"));
  EXPECT_THAT(f.message, HasSubstr("not a finite number"));
  EXPECT_EQ(f.line, 5u);
  m.vertices[3].y = std::numeric_limits<double>::infinity();
  EXPECT_THAT(failureOf(m).message, HasSubstr("not a finite number"));
}

TEST(Polyhedron3DReject, FaceWithTooFewVertices) {
  MeshData m = shapes3d::cube();
  m.addFace(std::vector<std::uint32_t>{0, 1});
  EXPECT_THAT(failureOf(m).message, HasSubstr("face 6 has 2 vertices; a face needs at least 3"));
  MeshData none;
  none.vertices = m.vertices;
  EXPECT_THAT(failureOf(none).message, HasSubstr("no faces"));
}

TEST(Polyhedron3DReject, DegenerateFaces) {
  MeshData m = shapes3d::cube();
  m.addFace({0, 0, 1});
  EXPECT_THAT(failureOf(m).message,
              HasSubstr("face 6 is degenerate: it has fewer than 3 distinct vertices"));
  MeshData twice = shapes3d::cube();
  twice.addFace({0, 1, 0, 2});
  EXPECT_THAT(failureOf(twice).message, HasSubstr("face 6 visits vertex 0"));
}

TEST(Polyhedron3DReject, OpenSurfaceNamesTheEdge) {
  MeshData m = shapes3d::cube();
  MeshData open;
  open.vertices = m.vertices;
  for (std::size_t f = 0; f + 1 < m.faceCount(); ++f) open.addFace(m.face(f));
  auto f = failureOf(open);
  EXPECT_THAT(f.message, HasSubstr("the surface is open: edge "));
  EXPECT_THAT(f.message, HasSubstr("belongs to face"));
}

TEST(Polyhedron3DReject, NonManifoldEdge) {
  // two tetrahedra sharing only the edge (0, 0, 0) - (1, 0, 0)
  MeshData m = shapes3d::tetrahedron({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  MeshData other = shapes3d::tetrahedron({0, 0, 0}, {1, 0, 0}, {0, -1, 0}, {0, 0, -1});
  for (std::size_t f = 0; f < other.faceCount(); ++f) {
    std::vector<std::uint32_t> face;
    for (std::uint32_t i : other.face(f)) face.push_back(i < 2 ? i : i + 2);
    m.addFace(face);
  }
  m.vertices.push_back({0, -1, 0});
  m.vertices.push_back({0, 0, -1});
  auto f = failureOf(m);
  EXPECT_THAT(f.message, testing::ContainsRegex("not a manifold: edge (0-1|1-0) from"));
  EXPECT_THAT(f.message, HasSubstr("shared by 4 triangles"));
}

TEST(Polyhedron3DReject, MixedOrientation) {
  MeshData m = shapes3d::cube();
  std::reverse(m.indices.begin() + m.faceStart[2], m.indices.begin() + m.faceStart[3]);
  m.faceLines = {3, 4, 5, 6, 7, 8};
  auto f = failureOf(m);
  EXPECT_THAT(f.message, HasSubstr("inconsistent orientation"));
  EXPECT_THAT(f.message, HasSubstr("in the same direction"));
  EXPECT_THAT(f.message, HasSubstr("face 2"));
}

TEST(Polyhedron3DReject, SeveralPieces) {
  MeshData m = shapes3d::tetrahedron({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1});
  MeshData other = shapes3d::tetrahedron({5, 0, 0}, {6, 0, 0}, {5, 1, 0}, {5, 0, 1});
  for (Vec3 v : other.vertices) m.addVertex(v);
  for (std::size_t f = 0; f < other.faceCount(); ++f) {
    std::vector<std::uint32_t> face;
    for (std::uint32_t i : other.face(f)) face.push_back(i + 4);
    m.addFace(face);
  }
  EXPECT_THAT(failureOf(m).message, HasSubstr("the surface has 2 separate pieces"));
}

TEST(Polyhedron3DReject, TorusIsNotASphere) {
  EXPECT_THAT(failureOf(shapes3d::torus()).message, HasSubstr("not a sphere: V - E + F = 0"));
}

TEST(Polyhedron3DReject, ZeroVolume) {
  MeshData flat = shapes3d::tetrahedron({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0});
  EXPECT_THAT(failureOf(flat).message, HasSubstr("zero volume: all 4 vertices are coplanar"));
  MeshData line;
  line.vertices = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
  line.addFace({0, 1, 2});
  line.addFace({0, 2, 1});
  EXPECT_THAT(failureOf(line).message, HasSubstr("zero volume: all 3 vertices are collinear"));
}

TEST(Polyhedron3DReject, ReflexEdge) {
  // the cube's top pushed in at its centre
  MeshData m = cubeWithTop({{0, 0, 0.5}}, {1, 5, 7, 3});
  MeshData dented;
  dented.vertices = m.vertices;
  for (std::size_t f = 0; f + 1 < m.faceCount(); ++f) dented.addFace(m.face(f));
  dented.addFace({1, 5, 8});
  dented.addFace({5, 7, 8});
  dented.addFace({7, 3, 8});
  dented.addFace({3, 1, 8});
  dented.faceLines = {1, 2, 3, 4, 5, 6, 7, 8, 9};
  auto f = failureOf(dented);
  EXPECT_THAT(f.message, HasSubstr("not convex: reflex edge"));
  EXPECT_THAT(f.message, HasSubstr("between face"));
  EXPECT_GT(f.line, 0u);
}

TEST(Polyhedron3DReject, CoplanarFold) {
  // the top face as a dart (whose fan overlaps itself) and the convex quad beside it
  MeshData m = shapes3d::cube();
  MeshData out;
  out.vertices = m.vertices;
  const std::uint32_t q = out.addVertex({0.5, -0.2, 1});
  for (std::size_t f = 0; f + 1 < m.faceCount(); ++f) out.addFace(m.face(f));
  out.addFace({1, 5, 7, q});  // (-1,-1), (1,-1), (1,1), Q: reflex at Q, fanned from (-1,-1)
  out.addFace({q, 7, 3, 1});
  EXPECT_THAT(failureOf(out).message, HasSubstr("lie in one plane and fold onto each other"));
}

TEST(Polyhedron3DReject, SurfaceWrappingTwice) {
  auto f = failureOf(shapes3d::starBipyramid());
  EXPECT_THAT(f.message, HasSubstr("not convex: the surface winds 2 times around its inside"));
}

TEST(Polyhedron3DReject, InconsistentMeshDataIsAUsageError) {
  MeshData m = shapes3d::cube();
  m.faceLines = {1, 2};
  EXPECT_THROW(ConvexPolyhedron{m}, UsageError);
  MeshData broken = shapes3d::cube();
  broken.faceStart.back() += 1;
  EXPECT_THROW(ConvexPolyhedron{broken}, UsageError);
}

// === Hulls

TEST(Hull3D, RandomPointsGiveTheirHull) {
  Rng rng(3);
  std::vector<Vec3> pts(2000);
  for (Vec3& p : pts) p = {rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
  ConvexPolyhedron h = ConvexPolyhedron::hullOf(pts);
  reftest::Reference ref(h);
  ASSERT_TRUE(ref.sound());
  std::size_t outside = 0;
  for (Vec3 p : pts) outside += ref.locate(p) == Location::Outside;
  EXPECT_EQ(outside, 0u);
}

TEST(Hull3D, NearlyCoplanarPointsAreRepairedToAnExactHull) {
  // the cube's corners and points on its faces, each pushed an ulp or two either way
  Rng rng(9);
  std::vector<Vec3> pts;
  for (double x : {-1.0, 1.0})
    for (double y : {-1.0, 1.0})
      for (double z : {-1.0, 1.0}) pts.push_back({x, y, z});
  for (int i = 0; i < 3000; ++i) {
    Vec3 p{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
    double* c = i % 3 == 0 ? &p.x : i % 3 == 1 ? &p.y : &p.z;
    *c = (i % 2 ? 1.0 : -1.0);
    for (std::uint64_t k = rng.below(3); k > 0; --k)
      *c = std::nextafter(*c, rng.below(2) ? 2.0 : -2.0);
    pts.push_back(p);
  }
  ConvexPolyhedron h = ConvexPolyhedron::hullOf(pts);  // validated exactly, or it throws
  EXPECT_NEAR(h.volume(), 8.0, 1e-9);
}

TEST(Hull3D, HugeAndTinyCoordinatesGiveTheirHull) {
  // Qhull squares coordinates: near 2^628 it overflowed and crashed (found by the
  // differential fuzz target); the hull must come out exact at any scale
  for (int e : {628, 1000, -1000, -1060}) {
    SCOPED_TRACE(e);
    // an octahedron and a point inside it
    std::vector<Vec3> pts = {{4, 0, 0}, {-4, 0, 0}, {0, 4, 0}, {0, -4, 0}, {0, 0, 4}, {0, 0, -4},
                             {1, 1, 1}};
    for (Vec3& p : pts) p = {std::ldexp(p.x, e - 2), std::ldexp(p.y, e - 2), std::ldexp(p.z, e - 2)};
    ConvexPolyhedron h = ConvexPolyhedron::hullOf(pts);
    EXPECT_EQ(h.vertexCount(), 6u);
    EXPECT_EQ(h.faceCount(), 8u);
    reftest::Reference ref(h);
    ASSERT_TRUE(ref.sound());
    EXPECT_EQ(ref.locate(pts[6]), Location::Inside);
    for (std::size_t i = 0; i < 6; ++i) EXPECT_EQ(ref.locate(pts[i]), Location::Boundary);
  }
}

TEST(Hull3D, Rejections) {
  std::vector<Vec3> flat = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 3, 0}};
  try {
    ConvexPolyhedron::hullOf(flat);
    FAIL();
  } catch (const GeometryError& e) {
    EXPECT_THAT(e.what(), HasSubstr("zero volume"));
    EXPECT_THAT(e.what(), HasSubstr("coplanar"));
  }
  std::vector<Vec3> three = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  EXPECT_THROW(ConvexPolyhedron::hullOf(three), GeometryError);
  std::vector<Vec3> nan = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, std::nan("")}};
  EXPECT_THROW(ConvexPolyhedron::hullOf(nan), GeometryError);
}

// === Generators

TEST(Generate3D, EveryKindValidatesAndIsDeterministic) {
  for (PolyhedronKind k : kAllPolyhedronKinds) {
    SCOPED_TRACE(std::string(toString(k)));
    EXPECT_EQ(parsePolyhedronKind(toString(k)), k);
    MeshData a = generatePolyhedron(k, 400, 5), b = generatePolyhedron(k, 400, 5);
    EXPECT_EQ(a.vertices, b.vertices);
    EXPECT_EQ(a.indices, b.indices);
    ConvexPolyhedron p(a);
    EXPECT_FALSE(p.wasInverted());
    EXPECT_TRUE(p.centre().has_value());
  }
  EXPECT_FALSE(parsePolyhedronKind("sphere").has_value());
  EXPECT_THROW(generatePolyhedron(PolyhedronKind::Geodesic, 3, 1), UsageError);
}

TEST(Generate3D, PlatonicSolidsHaveTheirFaces) {
  auto faces = [](PolyhedronKind k) { return generatePolyhedron(k, 4, 1).faceCount(); };
  EXPECT_EQ(faces(PolyhedronKind::Tetrahedron), 4u);
  EXPECT_EQ(faces(PolyhedronKind::Cube), 6u);
  EXPECT_EQ(faces(PolyhedronKind::Octahedron), 8u);
  EXPECT_EQ(faces(PolyhedronKind::Dodecahedron), 12u);
  EXPECT_EQ(faces(PolyhedronKind::Icosahedron), 20u);
  MeshData d = generatePolyhedron(PolyhedronKind::Dodecahedron, 4, 1);
  for (std::size_t f = 0; f < d.faceCount(); ++f) EXPECT_EQ(d.face(f).size(), 5u);
}

TEST(Generate3D, GeodesicSizes) {
  EXPECT_EQ(ConvexPolyhedron(generatePolyhedron(PolyhedronKind::Geodesic, 20, 1)).faceCount(), 20u);
  EXPECT_EQ(ConvexPolyhedron(generatePolyhedron(PolyhedronKind::Geodesic, 2000, 1)).faceCount(),
            2000u);
  EXPECT_EQ(ConvexPolyhedron(generatePolyhedron(PolyhedronKind::Geodesic, 1280, 1)).faceCount(),
            1280u);
}

TEST(Generate3D, DegeneratePresetsAreWhatTheySay) {
  ConvexPolyhedron slab(generatePolyhedron(PolyhedronKind::ThinSlab, 100, 1));
  EXPECT_EQ(slab.bounds().hi.z - slab.bounds().lo.z, 1e-9);
  ConvexPolyhedron tiny(generatePolyhedron(PolyhedronKind::TinyFaces, 2000, 1));
  double lo = 1e300, hi = 0;
  for (const auto& t : tiny.triangles()) {
    const Vec3 a = tiny.vertices()[t[0]], b = tiny.vertices()[t[1]], c = tiny.vertices()[t[2]];
    const double nx = (b.y - a.y) * (c.z - a.z) - (b.z - a.z) * (c.y - a.y);
    const double ny = (b.z - a.z) * (c.x - a.x) - (b.x - a.x) * (c.z - a.z);
    const double nz = (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
    const double area = std::sqrt(nx * nx + ny * ny + nz * nz) / 2;
    lo = std::min(lo, area);
    hi = std::max(hi, area);
  }
  EXPECT_GE(hi / lo, 1e10);
  ConvexPolyhedron offset(generatePolyhedron(PolyhedronKind::Offset, 300, 1));
  EXPECT_GE(offset.bounds().lo.x, 1e9 - 2);
  ConvexPolyhedron coplanar(generatePolyhedron(PolyhedronKind::Coplanar, 1200, 1));
  EXPECT_EQ(coplanar.faceCount(), 1200u);
}

TEST(Generate3D, NearBoundaryPointsHitTheSurfaceExactly) {
  ConvexPolyhedron p(generatePolyhedron(PolyhedronKind::Coplanar, 300, 1));
  reftest::Reference ref(p);
  auto pts = generatePoints3D(p, 3000, 4, true);
  std::size_t on = 0;
  for (Vec3 q : pts) on += ref.locate(q) == Location::Boundary;
  EXPECT_GT(on, 1000u);
  auto a = generatePoints3D(p, 100, 4, false), b = generatePoints3D(p, 100, 4, false);
  EXPECT_EQ(a, b);
}
