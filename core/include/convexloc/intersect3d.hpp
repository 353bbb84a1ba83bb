// convexloc — a plane against a convex polyhedron: misses, touches or crosses. Exact for the
// doubles given.
//
// A plane is given by three double points q1, q2, q3, not collinear. With
// G(v) = orient3d(q1, q2, q3, v), exact: the plane misses the polyhedron when every vertex
// has the same strict sign, touches it when no two vertices have strictly opposite signs but
// some lie on it, and crosses it otherwise. Both methods find a vertex where G is largest
// and one where it is smallest and decide from their two exact signs:
//   vertices  O(V)  every vertex's sign (the baseline)
//   dual      O(1)  a cube map of directions, labelled through the dual polyhedron,
//                   proposes the two vertices, an exact climb over the vertex graph confirms
//                   them (see core/src/intersect/dual_cubemap.cpp for when the O(1) holds)
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "convexloc/crossing.hpp"
#include "convexloc/geometry.hpp"
#include "convexloc/polyhedron.hpp"

namespace convexloc {

class CubemapLocator;

namespace detail {
class DualCubemap3D;
struct PlaneProbe;
struct VertexGraph;
}  // namespace detail

// the 3D plane methods, slowest first
enum class PlaneMethod : std::uint8_t { Vertices, Dual };
// every 3D plane method, in order
inline constexpr PlaneMethod kAllPlaneMethods[] = {PlaneMethod::Vertices, PlaneMethod::Dual};
// "vertices", "dual": what --method takes
std::string_view toString(PlaneMethod m) noexcept;
// the cost of one classification: "O(V)", "O(1)"
std::string_view costOf(PlaneMethod m) noexcept;
// the method with that name, if any
std::optional<PlaneMethod> parsePlaneMethod(std::string_view name) noexcept;

// Whether three points lie on one line (or coincide), exactly: then they define no plane.
bool collinear(Vec3 a, Vec3 b, Vec3 c) noexcept;

// What one classification did, step by step.
struct PlaneTrace {
  PlaneMethod method = PlaneMethod::Dual;
  Crossing crossing = Crossing::Misses;
  ExtremeVertices extremes;    // where G is largest and smallest, its exact signs there
  bool proposed = false;       // dual: the direction grid proposed both starting vertices
  std::uint32_t startMax = 0;  // dual: the proposals
  std::uint32_t startMin = 0;
  std::uint32_t listedMax = 0;  // dual: faces the dual's cube-map cells of w and -w list
  std::uint32_t listedMin = 0;
  std::uint32_t climbSteps = 0;   // dual: moves from the proposals to the extremes
  std::uint32_t comparisons = 0;  // exact comparisons of two vertices along the normal
  Vec3 direction{};  // dual: the unit direction along which G grows, whose cube-map cell
                     // proposed startMax (its opposite's proposed startMin); zero otherwise
};

// Size of what a method built.
struct PlaneStats {
  std::size_t vertices = 0;
  std::size_t faces = 0;
  std::size_t dualVertices = 0;  // dual: vertices of the dual polyhedron (unit face normals)
  std::size_t dualFaces = 0;     // dual: its plane faces, which the cube map lists
  std::size_t cells = 0;         // dual: the cube map's leaf cells
  std::size_t bytes = 0;
  double buildSeconds = 0.0;
};

// A convex polyhedron prepared for plane queries by one method. Keeps its own copy of the
// vertices and their adjacency.
class PlaneIntersector {
 public:
  explicit PlaneIntersector(const ConvexPolyhedron& polyhedron,
                            PlaneMethod method = PlaneMethod::Dual);
  ~PlaneIntersector();
  PlaneIntersector(PlaneIntersector&&) noexcept;
  PlaneIntersector& operator=(PlaneIntersector&&) noexcept;

  PlaneMethod method() const noexcept { return method_; }
  // How the plane through q1, q2, q3 meets the polyhedron. Precondition: not collinear.
  Crossing classify(Vec3 q1, Vec3 q2, Vec3 q3) const noexcept;
  // a batch: out[i] for the plane through planes[3i .. 3i + 2]; allocates nothing
  void classify(std::span<const Vec3> planes, std::span<Crossing> out) const noexcept;
  // the steps classify takes
  PlaneTrace trace(Vec3 q1, Vec3 q2, Vec3 q3) const;
  PlaneStats stats() const;
  // dual: the cube map of the dual polyhedron, whose cells' lists trace() counts; null
  // otherwise
  const CubemapLocator* dualLocator() const noexcept;
  // dual: per face of the dual polyhedron (dualLocator()'s faces), the vertex it proposes;
  // empty otherwise
  std::span<const std::uint32_t> dualLabels() const noexcept;

 private:
  PlaneTrace run(Vec3 q1, Vec3 q2, Vec3 q3, bool tracing) const noexcept;
  // dual: a vertex where the probe's G is largest, climbing from the star record at `record`
  // over the records of its neighbours (moves counted in `steps`); its coordinates in `at`
  std::uint32_t largestFrom(const std::uint64_t* record, detail::PlaneProbe& probe, Vec3& at,
                            std::uint32_t& steps) const noexcept;
  // dual: the crossing from the records the grid cells of the plane's w (up) and of -w
  // (down) propose
  Crossing classifyFrom(Vec3 q1, Vec3 q2, Vec3 q3, const std::uint64_t* up,
                        const std::uint64_t* down) const noexcept;
  PlaneMethod method_;
  std::vector<Vec3> vertices_;
  std::unique_ptr<detail::DualCubemap3D> dual_;
  std::size_t faces_ = 0;
  double buildSeconds_ = 0.0;
};

}  // namespace convexloc
