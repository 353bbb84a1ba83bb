// convexloc-viewer — a polar cell's radii drawn as arcs inside the cell's wedge, not as
// whole circles: r_in and r_out hold for the points of one cell only. GL-free.
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace convexloc::viewer {

// The points of the arc of radius `r` around `c` from the ray along `lo` counter-clockwise
// to the ray along `hi` (a polar cell's bounding directions), the first on `lo`'s ray and
// the last on `hi`'s, at most a 96th of a turn apart; the whole circle (closed) when the
// directions are equal or zero.
std::vector<glm::dvec2> wedgeArc(glm::dvec2 c, double r, glm::dvec2 lo, glm::dvec2 hi);

}  // namespace convexloc::viewer
