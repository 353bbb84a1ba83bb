// convexloc-viewer — the 3D scene's Planes mode (the dual problem in 3D): a plane placed by
// three points (or by an offset and two angles), what core's PlaneIntersector reports about
// it by both methods, the cube-map cell of the dual polyhedron its direction falls in, and
// where the dual view sits beside the polyhedron. GL-free; everything shown is core's
// answer, nothing here decides a classification.
#pragma once

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "convexloc/intersect3d.hpp"
#include "logic/base/format.hpp"
#include "logic/narration/steps.hpp"
#include "logic/scene/scene3d.hpp"

namespace convexloc::viewer {

// A plane given as the panel's sliders give it: the unit normal
// (cos e cos a, cos e sin a, sin e) for azimuth a and elevation e (radians), through the
// point `offset` world units along it from the polyhedron's centre.
struct PlaneSliders {
  double offset = 0.0;
  double azimuth = -1.15;  // a plane tilted to the default camera: seen aslant, not face-on
  double elevation = 1.2;
};

// a plane and what core reports about it
struct PlaneProbe3D {
  std::array<Vec3, 3> q{};       // the three points defining it
  PlaneTrace dual, vertices;     // both methods' steps (the dual's also aims the cell)
  std::ptrdiff_t cellUp = -1;    // position in dualCells() of the cell of the direction y
  std::ptrdiff_t cellDown = -1;  // ... and of -y
  std::vector<std::uint32_t> listedUp, listedDown;  // the dual faces those cells list
  std::vector<glm::dvec3> patch;                    // the plane within the grown box
  Section section;  // samples on the plane, classified by the scene's locator
  // the chosen method's trace
  const PlaneTrace& chosen(PlaneMethod m) const { return m == PlaneMethod::Dual ? dual : vertices; }
  // both methods gave the same answer
  bool agree() const { return dual.crossing == vertices.crossing; }
};

// Where the dual view sits: dual point d is drawn at world point
// middle + scale * d (the dual polyhedron lies on the unit sphere around the origin).
struct DualPlace3D {
  glm::dvec3 middle{0.0};
  double scale = 1.0;
  // where dual point d is drawn
  glm::dvec3 toWorld(Vec3 d) const { return middle + scale * glm::dvec3(d.x, d.y, d.z); }
};

// The Planes mode: off by default; when on, it follows the scene's shape with a
// PlaneIntersector of each method and answers the plane placed.
class Planes3D {
 public:
  // whether the mode is on; turning it on builds the intersectors at the next sync
  bool enabled() const { return enabled_; }
  void setEnabled(bool on);
  // follows the scene's shape and locator (rebuilds what changed); call every frame
  void sync(const Scene3D& scene);
  // the plane through q1, q2, q3 (kept across shape changes); false and ignored when they
  // are collinear (core's exact test)
  bool setPlane(Vec3 q1, Vec3 q2, Vec3 q3);
  // the plane the sliders give, through three points derived from them
  void setSliders(PlaneSliders s);
  const PlaneSliders& sliders() const { return sliders_; }
  // the range the offset slider spans: the polyhedron's box radius grown by 15%
  double offsetReach() const { return reach_; }
  // the method whose trace the inspector tells (both are always asked)
  PlaneMethod method() const { return method_; }
  void setMethod(PlaneMethod m);
  // puts the dual view beside the polyhedron along `side` (a unit vector: the camera's
  // right, so that it shows beside whatever way the camera looks)
  void placeDual(glm::dvec3 side);
  // the plane asked (or the sliders' plane) and core's answers; none until synced while on
  const std::optional<PlaneProbe3D>& plane() const { return plane_; }

  // what core built: the dual method's intersector (null until synced while on) and its
  // cube map's cells
  const PlaneIntersector* dualIntersector() const { return dual_.get(); }
  const std::vector<Cell3D>& dualCells() const { return dualCells_; }
  // where the dual view is drawn
  const DualPlace3D& place() const { return place_; }
  // the polyhedron last synced with (null before)
  const ConvexPolyhedron* polyhedron() const { return scene_ ? &scene_->polyhedron() : nullptr; }
  // the polyhedron and the dual view together, for fitting the camera
  Bounds3 both() const;
  // the dual cube's top corner nearest the polyhedron (where its caption goes)
  glm::dvec3 dualCorner() const {
    return place_.middle + dualHalf_ * (glm::dvec3(0.0, 0.0, 1.0) - side_);
  }
  // the polyhedron's box
  const Bounds3& box() const { return box_; }
  // the polyhedron's centre the sliders measure from: the mean of its vertices
  glm::dvec3 centre() const { return centre_; }
  // grows with every change that the drawing shows
  std::uint64_t version() const { return version_; }

 private:
  // the intersectors, the dual's cells and the dual view's place for the scene's shape
  void rebuild(const Scene3D& scene);
  // the dual view beside the box along side_
  void placeAgain();
  // the box the plane's patch is clipped to: the polyhedron's, grown by 15% of its size
  Bounds3 grownBox() const;
  // asks core about the plane asked: both traces, the cells, the patch and the section
  void answer();
  bool enabled_ = false;
  PlaneMethod method_ = PlaneMethod::Dual;
  PlaneSliders sliders_;
  std::optional<std::array<Vec3, 3>> asked_;
  std::unique_ptr<PlaneIntersector> dual_, baseline_;
  std::vector<Cell3D> dualCells_;
  const Scene3D* scene_ = nullptr;
  std::uint64_t shapeSeen_ = ~std::uint64_t{0}, structureSeen_ = ~std::uint64_t{0};
  Bounds3 box_;
  glm::dvec3 centre_{0.0}, side_{1.0, 0.0, 0.0};
  double reach_ = 1.0;
  DualPlace3D place_;
  double dualHalf_ = 1.0;  // half the side of the dual's cube, drawn
  std::optional<PlaneProbe3D> plane_;
  std::uint64_t version_ = 0;
};

// The plane's answer told for a student: the plane, its side function, the dual cell and
// what it proposed, the climb, the extremes with their signs, both methods' answers.
std::vector<TraceLine> describePlane(const PlaneProbe3D& plane, PlaneMethod method,
                                     std::span<const Vec3> dualVertices);

}  // namespace convexloc::viewer
