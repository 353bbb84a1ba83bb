// The 3D scene: polyhedra, the cube map's cells, the slicing plane and its section, picking
// a cell by a ray, probes, and the 3D draw lists.
#include <gtest/gtest.h>

#include <fstream>
#include <string>

#include "logic/app/interaction.hpp"
#include "logic/app/model.hpp"
#include "logic/app/options.hpp"
#include "logic/draw/structure3d.hpp"
#include "logic/scene/scene3d.hpp"

namespace cv = convexloc::viewer;
using convexloc::Location;
using convexloc::Method3D;
using convexloc::Vec3;

namespace {

std::string writeTemp(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

// the unit cube as OFF
const char* kCubeOff =
    "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";

glm::dvec3 squareMiddle(const convexloc::Cell3D& c) {
  glm::dvec3 m{0.0};
  for (const Vec3& q : c.corners) m += cv::toGlm(q) / 4.0;
  return m;
}

}  // namespace

TEST(Scene3D, DefaultSceneIsTheCubeMapWithAClassifiedSpray) {
  const cv::Scene3D s;
  EXPECT_EQ(s.method(), Method3D::Cubemap);
  EXPECT_FALSE(s.cells().empty());
  ASSERT_TRUE(s.centre().has_value());
  EXPECT_GT(s.cubeHalfSize(), 0.0);
  ASSERT_FALSE(s.points().empty());
  EXPECT_EQ(s.counts()[0] + s.counts()[1] + s.counts()[2], s.points().size());
  for (std::size_t i = 0; i < s.points().size(); i += 53)
    EXPECT_EQ(s.classes()[i], s.locator().locate(s.points()[i]));
}

TEST(Scene3D, BadMeshesKeepTheLastValidOne) {
  cv::Scene3D s;
  const std::string good = writeTemp("viewer_cube.off", kCubeOff);
  ASSERT_TRUE(s.loadFile(good)) << s.error();
  EXPECT_EQ(s.polyhedron().faceCount(), 12u);
  EXPECT_EQ(s.label(), "viewer_cube.off");
  // a face pointing at a vertex that does not exist
  const std::string bad =
      writeTemp("viewer_bad.off",
                "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 9\n");
  EXPECT_FALSE(s.loadFile(bad));
  EXPECT_NE(s.error().find("viewer_bad.off:"), std::string::npos) << s.error();
  EXPECT_EQ(s.label(), "viewer_cube.off");
  EXPECT_FALSE(s.loadFile(::testing::TempDir() + "none.obj"));
  EXPECT_EQ(s.polyhedron().faceCount(), 12u);
}

TEST(Scene3D, StlAndPlyOpenAndAPointCloudShowsItsHull) {
  cv::Model m;
  const std::string stl = writeTemp(
      "viewer_tetra.STL",
      "solid t\nfacet normal 0 0 -1\nouter loop\nvertex 0 0 0\nvertex 0 1 0\nvertex 1 0 0\n"
      "endloop\nendfacet\nfacet normal 0 -1 0\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
      "vertex 0 0 1\nendloop\nendfacet\nfacet normal -1 0 0\nouter loop\nvertex 0 0 0\n"
      "vertex 0 0 1\nvertex 0 1 0\nendloop\nendfacet\nfacet normal 1 1 1\nouter loop\n"
      "vertex 1 0 0\nvertex 0 1 0\nvertex 0 0 1\nendloop\nendfacet\nendsolid t\n");
  ASSERT_TRUE(m.open(stl)) << m.error();
  EXPECT_EQ(m.dim, cv::Dim::Three);
  EXPECT_EQ(m.scene3d().polyhedron().vertexCount(), 4u);
  // the cube's corners and its centre, without faces
  std::string cloud =
      "ply\nformat ascii 1.0\nelement vertex 9\nproperty float x\nproperty float y\n"
      "property float z\nend_header\n0 0 0\n";
  for (int i = 0; i < 8; ++i)
    cloud += std::to_string(i & 1 ? 1 : -1) + " " + std::to_string(i & 2 ? 1 : -1) + " " +
             std::to_string(i & 4 ? 1 : -1) + "\n";
  ASSERT_TRUE(m.open(writeTemp("viewer_cloud.ply", cloud))) << m.error();
  EXPECT_EQ(m.scene3d().polyhedron().vertexCount(), 8u);
  EXPECT_EQ(m.scene3d().label(), "viewer_cloud.ply");
}

TEST(Scene3D, HullOpensAMeshWhoseFaceIsNotPlanar) {
  // a cube of quads with one corner pushed off its top face: refused as given, named; with
  // --hull the viewer opens the convex hull of its corners
  const std::string off =
      writeTemp("viewer_bent.off",
                "OFF\n8 6 0\n-1 -1 -1\n1 -1 -1\n-1 1 -1\n1 1 -1\n-1 -1 1\n1 -1 1\n-1 1 1\n"
                "1 1 0.999999\n4 7 6 4 5\n4 0 2 3 1\n4 0 1 5 4\n4 2 6 7 3\n4 0 4 6 2\n4 1 3 7 5\n");
  cv::Model m;
  EXPECT_FALSE(m.open(off));
  EXPECT_NE(m.error().find("is not planar"), std::string::npos) << m.error();
  cv::Options o;
  o.shape = off;
  o.hull = true;
  EXPECT_EQ(m.apply(o), "") << m.error();
  EXPECT_EQ(m.dim, cv::Dim::Three);
  EXPECT_EQ(m.scene3d().polyhedron().vertexCount(), 8u);
  EXPECT_EQ(m.scene3d().polyhedron().planeCount(), 7u);
  o.hull = false;
  o.shape.clear();
  m.apply(o);  // the choice lasts for one application of the options
}

TEST(Scene3D, MethodsAndGrid) {
  cv::Scene3D s;
  ASSERT_TRUE(s.setResolution(3));
  EXPECT_EQ(s.effectiveResolution(), 3u);
  EXPECT_GE(s.cells().size(), 6u * 9u);
  s.setMethod(Method3D::Walk);
  EXPECT_TRUE(s.cells().empty());
  EXPECT_TRUE(s.centre().has_value());
  s.setMethod(Method3D::Halfspace);
  EXPECT_EQ(s.cubeHalfSize(), 0.0);
  s.setMethod(Method3D::Cubemap);
  EXPECT_EQ(s.effectiveResolution(), 3u);
}

TEST(Scene3D, SectionIsWhatCoreClassifiesOnThePlane) {
  cv::Scene3D s;
  const cv::Bounds3 b = s.bounds();
  s.setSlice({2, b.middle().z});
  const cv::Section& sec = s.section();
  ASSERT_EQ(sec.classes.size(), static_cast<std::size_t>(sec.n) * sec.n);
  std::size_t inside = 0;
  for (Location l : sec.classes) inside += l == Location::Inside;
  EXPECT_GT(inside, sec.classes.size() / 10);
  EXPECT_LT(inside, sec.classes.size());
  // moving the plane beyond the shape leaves nothing inside
  s.setSlice({0, b.hi.x + 1.0});
  EXPECT_LE(s.slice().offset, b.hi.x + 0.15 * (b.hi.x - b.lo.x) + 1e-12);  // clamped
  inside = 0;
  for (Location l : s.section().classes) inside += l == Location::Inside;
  EXPECT_EQ(inside, 0u);
}

TEST(Scene3D, ARayMeetsThePlaneInsideItsRectangle) {
  cv::Scene3D s;
  s.setSlice({2, 0.25});
  cv::Ray3 down{{0.1, -0.2, 5.0}, {0.0, 0.0, -1.0}};
  const auto hit = s.hitSlice(down);
  ASSERT_TRUE(hit);
  EXPECT_EQ(hit->z, 0.25);
  EXPECT_DOUBLE_EQ(hit->x, 0.1);
  cv::Ray3 away{{0.1, -0.2, 5.0}, {0.0, 0.0, 1.0}};
  EXPECT_FALSE(s.hitSlice(away));
  cv::Ray3 wide{{50.0, 0.0, 5.0}, {0.0, 0.0, -1.0}};
  EXPECT_FALSE(s.hitSlice(wide));
}

TEST(Scene3D, PickingACellByARayFindsTheSquareItLeavesBy) {
  cv::Scene3D s;
  ASSERT_TRUE(s.setResolution(4));
  const glm::dvec3 c = cv::toGlm(*s.centre());
  for (std::size_t k = 0; k < s.cells().size(); k += 7) {
    const glm::dvec3 m = squareMiddle(s.cells()[k]);
    // from far behind the centre, through it, out through the square's middle
    cv::Ray3 r;
    r.origin = c - 4.0 * (m - c);
    r.direction = glm::normalize(m - c);
    EXPECT_EQ(s.pickCell(r), static_cast<std::ptrdiff_t>(k));
  }
  cv::Ray3 miss{c + glm::dvec3(100.0, 100.0, 0.0), {0.0, 0.0, 1.0}};
  EXPECT_EQ(s.pickCell(miss), -1);
}

TEST(Scene3D, ProbeCarriesCoresTraceAndItsCell) {
  cv::Scene3D s;
  s.place({0.2, 0.1, 0.05});
  ASSERT_TRUE(s.probe());
  EXPECT_EQ(s.probe()->trace.result, Location::Inside);
  const std::ptrdiff_t k = s.probeCell();
  ASSERT_GE(k, 0);
  EXPECT_EQ(s.cells()[static_cast<std::size_t>(k)].cubeFace, s.probe()->trace.cubeFace);
  s.place({9.0, 0.0, 0.0});
  EXPECT_EQ(s.probe()->trace.result, Location::Outside);
  s.setMethod(Method3D::Walk);
  EXPECT_EQ(s.probe()->trace.method, Method3D::Walk);
  EXPECT_EQ(s.probeCell(), -1);
  s.clearProbe();
  EXPECT_FALSE(s.probe());
}

TEST(Scene3D, CompareAgrees) {
  cv::Scene3D s;
  const auto rows = s.compare(0.02);
  ASSERT_EQ(rows.size(), 3u);
  for (const auto& r : rows) {
    EXPECT_GT(r.points, 0u);
    EXPECT_EQ(r.disagreements, 0u) << toString(r.method);
  }
}

TEST(Structure3D, FarFacesAreThoseSeenFromInside) {
  cv::Scene3D s;
  const glm::dvec3 c = cv::toGlm(*s.centre());
  // far along +x: the +x face is near (seen from outside), every other one from inside
  EXPECT_EQ(cv::farCubeFaces(s, c + glm::dvec3(100.0, 0.0, 0.0)), 0b111110u);
  EXPECT_EQ(cv::farCubeFaces(s, c + glm::dvec3(0.0, 0.0, -100.0)), 0b011111u);
  EXPECT_EQ(cv::farCubeFaces(s, c), 0b111111u);
}

TEST(Structure3D, GridOnFarFacesOnlyAndOverlayShowsThePinnedCell) {
  cv::Scene3D s;
  const cv::Palette& pal = cv::paletteFor(cv::Theme::Dark);
  cv::View3DOptions opt;
  opt.wireframe = false;
  opt.showSlice = false;
  cv::DrawList none, all;
  cv::buildStructure3D(s, pal, opt, 0u, none);
  cv::buildStructure3D(s, pal, opt, 0b111111u, all);
  std::size_t gridNone = 0, gridAll = 0;
  for (const auto& seg : none.segments) gridNone += seg.colour == pal.cube;
  for (const auto& seg : all.segments) gridAll += seg.colour == pal.cube;
  EXPECT_EQ(gridNone, 12u);  // the cube's outline; the near faces' grid is faint
  EXPECT_EQ(gridAll, 12u + 4u * s.cells().size());
  cv::DrawList mesh;
  cv::buildMesh3D(s, pal, opt, mesh);
  EXPECT_EQ(mesh.fills.size(), 3u * s.polyhedron().faceCount());
  s.pin(5);
  cv::DrawList overlay;
  cv::buildOverlay3D(s, pal, opt, overlay);
  EXPECT_FALSE(overlay.fills.empty());
  EXPECT_FALSE(overlay.segments.empty());
}

TEST(Model3D, FilesPresetsAndOptionsChooseTheScene) {
  cv::Model m;
  EXPECT_FALSE(m.hasScene3d());
  const std::string cube = writeTemp("viewer_model_cube.off", kCubeOff);
  ASSERT_TRUE(m.open(cube)) << m.error();
  EXPECT_EQ(m.dim, cv::Dim::Three);
  EXPECT_TRUE(m.hasScene3d());
  m.show(cv::Dim::Two);
  EXPECT_EQ(m.dim, cv::Dim::Two);
  ASSERT_TRUE(m.applyPreset("tiny-faces")) << m.error();
  EXPECT_EQ(m.dim, cv::Dim::Three);
  ASSERT_TRUE(m.applyPreset("coplanar-faces")) << m.error();
  EXPECT_GT(m.scene3d().polyhedron().faceCount(), 12u);

  cv::Model n;
  cv::Options o;
  o.method = "walk";
  o.slice = cv::SlicePlane{0, 0.1};
  o.probe3 = Vec3{0.0, 0.0, 0.0};
  EXPECT_EQ(n.apply(o), "");
  EXPECT_EQ(n.dim, cv::Dim::Three);
  EXPECT_EQ(n.scene3d().method(), Method3D::Walk);
  EXPECT_EQ(n.scene3d().slice().axis, 0);
  ASSERT_TRUE(n.scene3d().probe());
  cv::Options g;
  g.generate = "cube";
  EXPECT_EQ(n.apply(g), "");
  EXPECT_EQ(n.scene3d().polyhedron().faceCount(), 12u);
}

TEST(Interaction3D, ClickOnThePlanePlacesAPointDragOrbits) {
  cv::Model m;
  m.show(cv::Dim::Three);
  m.camera3d.setViewport({1000.0, 800.0});
  m.fit({{0.0, 0.0}, {1000.0, 800.0}});
  cv::Scene3D& s = m.scene3d();
  s.setSlice({2, 0.0});
  // the screen position of the plane's point (0.1, 0.1, 0)
  const cv::Projected p = m.camera3d.toScreen({0.1, 0.1, 0.0});
  ASSERT_TRUE(p.visible());
  cv::Interaction ia;
  cv::PointerInput in;
  in.pos = p.screen;
  in.pressed[0] = in.down[0] = true;
  ia.update(in, m);
  in = {};
  in.pos = p.screen;
  in.released[0] = true;
  ia.update(in, m);
  ASSERT_TRUE(s.probe());
  EXPECT_NEAR(s.probe()->point.x, 0.1, 1e-6);
  EXPECT_EQ(s.probe()->point.z, 0.0);
  // a drag turns the view
  const double yaw = m.camera3d.yaw();
  in = {};
  in.pos = {100.0, 100.0};
  in.pressed[0] = in.down[0] = true;
  ia.update(in, m);
  in = {};
  in.pos = {160.0, 100.0};
  in.delta = {60.0, 0.0};
  in.down[0] = true;
  ia.update(in, m);
  EXPECT_NE(m.camera3d.yaw(), yaw);
}

namespace {

// a click (press and release without moving) at `at`
void clickAt(cv::Interaction& ia, cv::Model& m, glm::dvec2 at) {
  cv::PointerInput in;
  in.pos = at;
  in.pressed[0] = in.down[0] = true;
  ia.update(in, m);
  in = {};
  in.pos = at;
  in.released[0] = true;
  ia.update(in, m);
}

}  // namespace

TEST(Interaction3D, AClickPlacesNoPointOnAHiddenPlane) {
  cv::Model m;
  m.show(cv::Dim::Three);
  m.camera3d.setViewport({1000.0, 800.0});
  m.fit({{0.0, 0.0}, {1000.0, 800.0}});
  cv::Scene3D& s = m.scene3d();
  s.setSlice({2, 0.0});
  const cv::Projected p = m.camera3d.toScreen({0.1, 0.1, 0.0});
  ASSERT_TRUE(p.visible());
  cv::Interaction ia;
  // the Planes mode hides the slicing plane: no point lands on it
  m.planes3d.setEnabled(true);
  clickAt(ia, m, p.screen);
  EXPECT_FALSE(s.probe());
  // the slicing plane hidden by the View panel (--slice none): no point either
  m.planes3d.setEnabled(false);
  m.settings.view3d.showSlice = false;
  clickAt(ia, m, p.screen);
  EXPECT_FALSE(s.probe());
  // shown again: the same click places it
  m.settings.view3d.showSlice = true;
  clickAt(ia, m, p.screen);
  EXPECT_TRUE(s.probe());
}

// a slide names only the cube faces it asks for (its query's), the live view all six
TEST(Structure3D, OnlyTheCubeFacesAskedForAreNamed) {
  cv::Scene3D s;
  const cv::Palette& pal = cv::paletteFor(cv::Theme::Dark);
  const auto faceNames = [&](unsigned mask) {
    cv::View3DOptions opt;
    opt.faceNames = mask;
    cv::DrawList out;
    cv::buildStructure3D(s, pal, opt, 0b111111u, out);
    std::vector<std::string> names;
    for (const cv::Label& l : out.labels)
      for (const std::string_view n : convexloc::kCubeFaceNames)
        if (l.text == n) names.push_back(l.text);
    return names;
  };
  EXPECT_EQ(faceNames(0x3fu).size(), 6u);
  EXPECT_TRUE(faceNames(0u).empty());
  EXPECT_EQ(faceNames(1u << 3),
            std::vector<std::string>{std::string(convexloc::kCubeFaceNames[3])});
}
