// The 3D Planes mode: the plane's state follows core's PlaneIntersector (both methods), the
// dual cube map's cells come from core, the sliders derive the three points, the command
// line's --plane turns the mode on and refuses collinear points.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

#include "convexloc/crossing.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/intersect3d.hpp"
#include "logic/app/model.hpp"
#include "logic/app/options.hpp"
#include "logic/dual/planes3d.hpp"

namespace cv = convexloc::viewer;
using convexloc::Crossing;
using convexloc::PlaneIntersector;
using convexloc::PlaneMethod;
using convexloc::Vec3;

namespace {

// a scene holding the cube [-1, 1]^3, and the Planes mode on over it
struct CubePlanes {
  cv::Scene3D scene;
  cv::Planes3D planes;
  CubePlanes() {
    EXPECT_TRUE(scene.generate(convexloc::PolyhedronKind::Cube, 6, 1));
    planes.setEnabled(true);
    planes.sync(scene);
  }
  // the plane through q1, q2, q3: the mode's answer, checked against core's own
  Crossing ask(Vec3 q1, Vec3 q2, Vec3 q3) {
    EXPECT_TRUE(planes.setPlane(q1, q2, q3));
    const auto& p = planes.plane();
    EXPECT_TRUE(p.has_value());
    if (!p) return Crossing::Misses;
    const PlaneIntersector dual(scene.polyhedron(), PlaneMethod::Dual);
    const PlaneIntersector baseline(scene.polyhedron(), PlaneMethod::Vertices);
    EXPECT_EQ(p->dual.crossing, dual.classify(q1, q2, q3));
    EXPECT_EQ(p->vertices.crossing, baseline.classify(q1, q2, q3));
    EXPECT_TRUE(p->agree());
    return p->dual.crossing;
  }
};

// how many of the section's samples core found inside
std::size_t insideSamples(const cv::Section& s) {
  return static_cast<std::size_t>(
      std::count(s.classes.begin(), s.classes.end(), convexloc::Location::Inside));
}

}  // namespace

TEST(Planes3D, BuildsOnlyWhenOnAndFollowsTheShapeKeepingThePlane) {
  cv::Scene3D scene;
  cv::Planes3D planes;
  planes.sync(scene);
  EXPECT_EQ(planes.dualIntersector(), nullptr);  // off: nothing built
  planes.setEnabled(true);
  planes.sync(scene);
  ASSERT_NE(planes.dualIntersector(), nullptr);
  EXPECT_FALSE(planes.dualCells().empty());
  ASSERT_TRUE(planes.setPlane({0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  ASSERT_TRUE(scene.generate(convexloc::PolyhedronKind::Cube, 6, 1));
  planes.sync(scene);
  EXPECT_EQ(planes.dualIntersector()->stats().faces, scene.polyhedron().faceCount());
  ASSERT_TRUE(planes.plane());
  EXPECT_EQ(planes.plane()->q[1], (Vec3{1, 0, 0}));
}

TEST(Planes3D, ThroughTheCentreCrossesFarAwayMissesThroughAVertexOrFaceTouches) {
  CubePlanes c;
  EXPECT_EQ(c.ask({0, 0, 0}, {1, 0.5, 0}, {0, 1, 0.25}), Crossing::Crosses);
  EXPECT_EQ(c.ask({0, 0, 5}, {1, 0, 5}, {0, 1, 5.5}), Crossing::Misses);
  // x + y + z = 3 meets the cube at the vertex (1, 1, 1) only
  EXPECT_EQ(c.ask({3, 0, 0}, {0, 3, 0}, {0, 0, 3}), Crossing::Touches);
  // z = 1 holds a face
  EXPECT_EQ(c.ask({0, 0, 1}, {1, 0, 1}, {0, 1, 1}), Crossing::Touches);
  // one ulp beyond the vertex: misses
  const double past = std::nextafter(3.0, 4.0);
  EXPECT_EQ(c.ask({past, 0, 0}, {0, past, 0}, {0, 0, past}), Crossing::Misses);
}

TEST(Planes3D, TheSectionShowsWhereTheLocatorFindsThePlaneInside) {
  CubePlanes c;
  c.ask({0, 0, 0.5}, {1, 0, 0.5}, {0, 1, 0.5});
  EXPECT_GT(insideSamples(c.planes.plane()->section), 100u);
  EXPECT_GE(c.planes.plane()->patch.size(), 3u);
  c.ask({0, 0, 5}, {1, 0, 5}, {0, 1, 5});
  EXPECT_EQ(insideSamples(c.planes.plane()->section), 0u);
}

TEST(Planes3D, TheDualCellOfYListsCoresFacesAndTheProposalsClimbToTheExtremes) {
  CubePlanes c;
  c.ask({0.1, 0.2, 0.3}, {1, 0.5, 0}, {0, 1, 0.25});
  const cv::PlaneProbe3D& p = *c.planes.plane();
  ASSERT_TRUE(p.dual.proposed);
  ASSERT_GE(p.cellUp, 0);
  ASSERT_GE(p.cellDown, 0);
  ASSERT_FALSE(p.listedUp.empty());
  EXPECT_EQ(c.planes.dualCells()[static_cast<std::size_t>(p.cellUp)].faces, p.listedUp);
  EXPECT_EQ(p.listedUp.size(), p.dual.listedMax);
  EXPECT_EQ(p.listedDown.size(), p.dual.listedMin);
  // every listed dual face stands for a vertex of the cube
  const auto labels = c.planes.dualIntersector()->dualLabels();
  for (const auto* listed : {&p.listedUp, &p.listedDown})
    for (const std::uint32_t f : *listed) EXPECT_LT(labels[f], 8u);
  // the proposals are vertices, and the climb from them ends at the exact extremes
  EXPECT_LT(p.dual.startMax, 8u);
  EXPECT_LT(p.dual.startMin, 8u);
  const PlaneIntersector every(c.scene.polyhedron(), PlaneMethod::Vertices);
  const convexloc::PlaneTrace e = every.trace(p.q[0], p.q[1], p.q[2]);
  EXPECT_EQ(p.dual.extremes.largestSign, e.extremes.largestSign);
  EXPECT_EQ(p.dual.extremes.smallestSign, e.extremes.smallestSign);
}

TEST(Planes3D, CollinearPointsAreRefusedAndTheLastPlaneStays) {
  CubePlanes c;
  c.ask({0, 0, 0}, {1, 0, 0}, {0, 1, 0});
  EXPECT_FALSE(c.planes.setPlane({0, 0, 0}, {1, 1, 1}, {2, 2, 2}));
  EXPECT_FALSE(c.planes.setPlane({1, 2, 3}, {1, 2, 3}, {0, 0, 0}));
  EXPECT_EQ(c.planes.plane()->q[1], (Vec3{1, 0, 0}));
}

TEST(Planes3D, SlidersDeriveThePlaneAndThroughTheCentreCrosses) {
  CubePlanes c;
  cv::PlaneSliders s{0.0, 0.4, 0.3};
  c.planes.setSliders(s);
  EXPECT_EQ(c.planes.plane()->dual.crossing, Crossing::Crosses);
  // the offset's reach lies beyond every vertex: the plane misses
  s.offset = c.planes.offsetReach();
  c.planes.setSliders(s);
  EXPECT_EQ(c.planes.plane()->dual.crossing, Crossing::Misses);
  EXPECT_EQ(c.planes.plane()->vertices.crossing, Crossing::Misses);
  // three points asked give back their sliders: the plane z = 0.5
  ASSERT_TRUE(c.planes.setPlane({0, 0, 0.5}, {1, 0, 0.5}, {0, 1, 0.5}));
  EXPECT_NEAR(c.planes.sliders().offset, 0.5, 1e-12);
  EXPECT_NEAR(c.planes.sliders().elevation, 1.5707963267948966, 1e-12);
}

TEST(Planes3D, TheDualViewSitsBesideAndTheFitHoldsBoth) {
  CubePlanes c;
  c.planes.placeDual({1, 0, 0});
  const cv::Bounds3 both = c.planes.both();
  EXPECT_GT(c.planes.place().middle.x, 1.0);  // right of the cube
  EXPECT_LE(both.lo.x, -1.0);
  EXPECT_GE(both.hi.x, c.planes.place().middle.x);
  c.planes.placeDual({0, -1, 0});
  EXPECT_LT(c.planes.place().middle.y, -1.0);
}

TEST(Planes3D, InspectorTellsTheCellsTheExtremesAndBothAnswers) {
  CubePlanes c;
  c.ask({0, 0, 0}, {1, 0.5, 0}, {0, 1, 0.25});
  std::string all;
  for (const cv::TraceLine& l : cv::describePlane(*c.planes.plane(), PlaneMethod::Dual, {}))
    all += l.text + "\n";
  EXPECT_NE(all.find("cell "), std::string::npos) << all;
  EXPECT_NE(all.find("largest G at vertex"), std::string::npos) << all;
  EXPECT_NE(all.find("the methods agree"), std::string::npos) << all;
  EXPECT_NE(all.find("the plane crosses"), std::string::npos) << all;
  c.planes.setMethod(PlaneMethod::Vertices);
  all.clear();
  for (const cv::TraceLine& l : cv::describePlane(*c.planes.plane(), PlaneMethod::Vertices, {}))
    all += l.text + "\n";
  EXPECT_NE(all.find("every vertex's sign"), std::string::npos) << all;
  EXPECT_EQ(all.find("cell "), std::string::npos) << all;
}

TEST(Planes3D, CommandLineTurnsTheModeOnAndRefusesCollinearPoints) {
  const std::vector<std::string_view> args{"--plane", "0",    "0", "0.25", "1",
                                           "0",       "0.25", "0", "1",    "0.25"};
  const cv::ParsedOptions parsed = cv::parseOptions(args);
  ASSERT_TRUE(parsed.error.empty()) << parsed.error;
  ASSERT_TRUE(parsed.options.plane);
  EXPECT_EQ((*parsed.options.plane)[2], (Vec3{0, 1, 0.25}));
  cv::Model model;
  EXPECT_EQ(model.apply(parsed.options), "");
  EXPECT_EQ(model.dim, cv::Dim::Three);
  EXPECT_TRUE(model.planes3d.enabled());
  ASSERT_TRUE(model.planes3d.plane());
  EXPECT_EQ(model.planes3d.plane()->q[0], (Vec3{0, 0, 0.25}));
  EXPECT_EQ(model.planes3d.plane()->dual.crossing, Crossing::Crosses);

  const cv::ParsedOptions collinear = cv::parseOptions(
      std::vector<std::string_view>{"--plane", "0", "0", "0", "1", "1", "1", "2", "2", "2"});
  EXPECT_NE(collinear.error.find("not on one line"), std::string::npos) << collinear.error;
  for (const std::vector<std::string_view>& bad :
       {std::vector<std::string_view>{"--plane", "1", "2", "3"},
        std::vector<std::string_view>{"--plane", "0", "0", "0", "1", "0", "0", "0", "x", "0"}})
    EXPECT_FALSE(cv::parseOptions(bad).error.empty());
}
