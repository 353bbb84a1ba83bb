// convexloc (internal) — the cube map of a polyhedron's dual, proposing a plane's extreme
// vertices in O(1). The argument heads plane_dual.cpp.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "convexloc/geometry.hpp"
#include "convexloc/locate3d.hpp"
#include "convexloc/polyhedron.hpp"
#include "intersect/graph3d.hpp"

namespace convexloc::detail {

class DualCubemap3D {
 public:
  // builds the dual of the polyhedron (Qhull on its unit face normals, then the cube map)
  DualCubemap3D(const ConvexPolyhedron& polyhedron, const VertexGraph& graph);
  // A proposal for a vertex where the plane's G is largest and one where it is smallest,
  // and how many dual faces each cell listed; false when the dual has no cell for them.
  bool propose(Vec3 q1, Vec3 q2, Vec3 q3, std::uint32_t& largest, std::uint32_t& smallest,
               std::uint32_t& listedLargest, std::uint32_t& listedSmallest) const noexcept;
  // the unit direction along which the plane's G grows (zero for collinear points)
  static Vec3 aim(Vec3 q1, Vec3 q2, Vec3 q3) noexcept;
  // the cube map of the dual polyhedron; none when the dual could not be built
  const CubemapLocator* locator() const noexcept { return cube_ ? &*cube_ : nullptr; }
  std::size_t dualVertices() const noexcept { return dualVertices_; }
  std::size_t dualFaces() const noexcept { return labels_.size(); }
  // per dual face, the vertex it proposes
  const std::vector<std::uint32_t>& labels() const noexcept { return labels_; }
  std::size_t bytes() const noexcept;

 private:
  std::optional<CubemapLocator> cube_;
  std::vector<std::uint32_t> labels_;  // per dual face: the vertex farthest along its middle
  std::size_t dualVertices_ = 0;
};

}  // namespace convexloc::detail
