// A 3D query on a slide (logic/teach/query_view, Camera3D::lookAlong and fitPoints): the
// face its ray leaves by, a view across the ray that keeps x_T and x apart and shows that
// face's front, and a fit by the drawn points that fills the room.
// And layout.json (logic/teach/slide_record).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "convexloc/generate3d.hpp"
#include "logic/teach/query_view.hpp"
#include "logic/teach/slide_record.hpp"
#include "logic/view/camera3d.hpp"

namespace cv = convexloc::viewer;
using convexloc::ConvexPolyhedron;

namespace {

ConvexPolyhedron icosahedron() {
  return ConvexPolyhedron(
      convexloc::generatePolyhedron(convexloc::PolyhedronKind::Icosahedron, 12, 1));
}

glm::dvec3 at(convexloc::Vec3 v) {
  return {v.x, v.y, v.z};
}

// the polyhedron's vertices
std::vector<glm::dvec3> verticesOf(const ConvexPolyhedron& p) {
  std::vector<glm::dvec3> out;
  for (const convexloc::Vec3 v : p.vertices()) out.push_back(at(v));
  return out;
}

}  // namespace

// the exit face is the one whose plane the ray meets first: its middle lies on the ray's
// side of every other plane, and the ray meets its plane beyond the point inside
TEST(QueryView, TheRayLeavesByTheNearestPlane) {
  const ConvexPolyhedron p = icosahedron();
  const glm::dvec3 c = at(*p.centre());
  for (const glm::dvec3 x : {c + glm::dvec3(0.3, 0.1, 0.05), c + glm::dvec3(-0.1, 0.2, -0.4)}) {
    const auto exit = cv::rayExitFace(p, c, x);
    ASSERT_TRUE(exit);
    const glm::dvec3 d = x - c;
    const double along = glm::dot(exit->normal, d);
    ASSERT_GT(along, 0.0);
    const double t = glm::dot(exit->normal, exit->faceMiddle - c) / along;  // the hit
    EXPECT_GT(t, 1.0);  // x is inside: the ray leaves beyond it
    // every other plane the ray runs toward is met no nearer
    for (std::size_t f = 0; f < p.planeCount(); ++f) {
      const auto tri = p.planes()[f];
      const glm::dvec3 a = at(p.vertices()[tri[0]]);
      glm::dvec3 n = glm::cross(at(p.vertices()[tri[1]]) - a, at(p.vertices()[tri[2]]) - a);
      if (glm::dot(n, c - a) > 0.0) n = -n;
      if (glm::dot(n, d) <= 0.0) continue;
      EXPECT_GE(glm::dot(n, a - c) / glm::dot(n, d), t * (1.0 - 1e-12)) << f;
    }
  }
  EXPECT_FALSE(cv::rayExitFace(p, c, c));
}

// looking along viewAcrossRay: x_T and x are far apart on the screen (cos(lean) of the ray,
// not its end-on dot), and the exit face is seen from its front
TEST(QueryView, TheViewAcrossTheRaySeparatesXTAndXAndShowsTheFace) {
  const ConvexPolyhedron p = icosahedron();
  const glm::dvec3 c = at(*p.centre()), x = c + glm::dvec3(0.5, 0.2, 0.3);
  const auto exit = cv::rayExitFace(p, c, x);
  ASSERT_TRUE(exit);
  const glm::dvec3 f = cv::viewAcrossRay(c, x, exit->normal);
  EXPECT_NEAR(glm::length(f), 1.0, 1e-12);
  const glm::dvec3 d = glm::normalize(x - c);
  // the ray's length across the view: most of it
  EXPECT_GT(glm::length(d - glm::dot(d, f) * f), 0.8);
  // the face's front toward the eye (the eye looks against its outward normal)
  EXPECT_LT(glm::dot(f, exit->normal), -0.3);
  // the camera turned so: its forward is that direction
  cv::Camera3D cam;
  cam.lookAlong(f);
  EXPECT_NEAR(glm::dot(cam.forward(), f), 1.0, 1e-9);
}

// fitPoints: the drawn box of the points centred in the area and `fill` of its width or
// height, the rest inside it
TEST(QueryView, AFitByTheDrawnPointsFillsTheRoom) {
  const ConvexPolyhedron p = icosahedron();
  const std::vector<glm::dvec3> pts = verticesOf(p);
  cv::Camera3D cam;
  cam.setViewport({1280.0, 720.0});
  const cv::Bounds3 b{at(p.bounds().lo), at(p.bounds().hi)};
  const cv::ScreenRect room{{20.0, 80.0}, {900.0, 620.0}};
  cam.fit(b, room);
  cam.fitPoints(pts, room, 0.88);
  cv::ScreenRect box{glm::dvec2(1e300), glm::dvec2(-1e300)};
  for (const glm::dvec3& q : pts) {
    const cv::Projected s = cam.toScreen(q);
    ASSERT_TRUE(s.visible());
    box.lo = glm::min(box.lo, s.screen);
    box.hi = glm::max(box.hi, s.screen);
  }
  EXPECT_GE(box.lo.x, room.lo.x);
  EXPECT_LE(box.hi.x, room.hi.x);
  EXPECT_GE(box.lo.y, room.lo.y);
  EXPECT_LE(box.hi.y, room.hi.y);
  const glm::dvec2 fill = box.size() / room.size();
  EXPECT_GT(std::max(fill.x, fill.y), 0.85);
  EXPECT_NEAR(box.middle().x, room.middle().x, 0.03 * room.size().x);
  EXPECT_NEAR(box.middle().y, room.middle().y, 0.03 * room.size().y);
}

// layout.json: boxes in page pixels as [x, y, width, height], empty boxes left out, numbers
// to a hundredth, the 3D query where there is one
TEST(SlideRecord, LayoutJsonWritesThePagesBoxes) {
  cv::SlideRecord r;
  r.slide = 23;
  r.kind = cv::SlideKind::Figure3D;
  r.page = {1280.0, 720.0};
  const glm::dvec2 pageLo{0.0, 40.0};  // a 16:10 window's letterbox
  r.add("title", {{10.0, 50.0}, {310.5, 110.0}}, pageLo);
  r.add("steps", {{0.0, 0.0}, {0.0, 0.0}}, pageLo);  // none drawn
  r.add("figure", {{10.0, 120.0}, {900.0, 660.123}}, pageLo);
  r.minTextPx = 16.0;
  r.query3d = cv::Query3DOnPage{{100.0, 200.0}, {300.0, 250.5}, {350.0, 260.0}};
  const cv::SlideRecord two[] = {r, r};
  const std::string json = cv::layoutJson(two);
  EXPECT_NE(
      json.find("{\"slide\": 23, \"kind\": \"figure3d\", \"page\": [1280, 720], \"boxes\": "
                "{\"title\": [10, 10, 300.5, 60], \"figure\": [10, 80, 890, 540.12]}, "
                "\"min_text_px\": 16, \"query3d\": {\"x_T\": [100, 200], \"x\": [300, 250.5], "
                "\"hit_face\": [350, 260]}}"),
      std::string::npos)
      << json;
  EXPECT_EQ(json.find("steps"), std::string::npos);
  EXPECT_EQ(json.rfind("{\"slides\": [", 0), 0u);
  EXPECT_EQ(json.substr(json.size() - 3), "]}\n");
}
