// convexloc-viewer — a 3D query as a slide shows it: the face of the polyhedron that the ray
// from the centre x_T through the point x leaves by. For drawing and for the slide's record
// only (doubles, no predicate): the classification is core's trace. GL-free.
#pragma once

#include <cstddef>
#include <optional>

#include <glm/glm.hpp>

#include "convexloc/polyhedron.hpp"

namespace convexloc::viewer {

// the face (plane index) the ray from `centre` (strictly inside) through `point` leaves the
// polyhedron by, and the middle of its vertices; none where point == centre
struct RayExit {
  std::size_t plane = 0;
  glm::dvec3 faceMiddle{0.0};
};
std::optional<RayExit> rayExitFace(const ConvexPolyhedron& shape, glm::dvec3 centre,
                                   glm::dvec3 point);

}  // namespace convexloc::viewer
