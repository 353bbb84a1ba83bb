// convexloc-viewer — a plane's section of a convex polyhedron as one polygon (where the
// plane cuts the polyhedron's edges, in order around the plane's normal), so that the
// section is drawn with straight sides instead of the staircase of its samples. A drawing
// matter: double arithmetic, nothing decided (the samples' classes are core's).
#pragma once

#include <vector>

#include <glm/glm.hpp>

#include "convexloc/polyhedron.hpp"

namespace convexloc::viewer {

// The section of `polyhedron` by the plane through `corner` spanned by `du` and `dv`,
// counter-clockwise about du x dv; empty where the plane misses it or only touches it.
std::vector<glm::dvec3> sectionPolygon(const ConvexPolyhedron& polyhedron, glm::dvec3 corner,
                                       glm::dvec3 du, glm::dvec3 dv);

}  // namespace convexloc::viewer
