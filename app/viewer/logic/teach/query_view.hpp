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
  glm::dvec3 normal{0.0};  // the face's outward unit normal
};
std::optional<RayExit> rayExitFace(const ConvexPolyhedron& shape, glm::dvec3 centre,
                                   glm::dvec3 point);

// A view across the query's ray: the direction to look along (a unit vector), square to
// the ray from `centre` through `point` toward the side the exit face leans to, turned `turn`
// radians about the ray so that the solid shows its depth, then leaned `lean` radians toward
// the point's end so that the exit face (whose normal runs near the ray) is seen from its
// front. x_T and x then lie apart on the page by cos(lean) of the ray's length. Any view
// square to the ray where the face's normal runs along it.
glm::dvec3 viewAcrossRay(glm::dvec3 centre, glm::dvec3 point, glm::dvec3 faceNormal,
                         double turn = 0.35, double lean = 0.6);

}  // namespace convexloc::viewer
