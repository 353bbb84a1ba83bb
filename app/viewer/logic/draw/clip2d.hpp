// convexloc-viewer — boxes and lines clipped to them, for drawing (never a decision).
#pragma once

#include <glm/vec2.hpp>

#include "convexloc/geometry.hpp"

namespace convexloc::viewer {

// the part of the line through a and b inside the box, if any (drawing only)
bool clipLineToBox(glm::dvec2 a, glm::dvec2 b, const Box2& box, glm::dvec2& p, glm::dvec2& q);

// the box grown by `fraction` of its size on each side
Box2 grow(const Box2& b, double fraction);

}  // namespace convexloc::viewer
