// convexloc-viewer — radii as arcs.
#include "logic/draw/radii_arc.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace convexloc::viewer {

std::vector<glm::dvec2> wedgeArc(glm::dvec2 c, double r, glm::dvec2 lo, glm::dvec2 hi) {
  constexpr double kTurn = 2.0 * std::numbers::pi;
  constexpr double kMaxStep = kTurn / 96.0;
  double a0 = 0.0, span = kTurn;
  const bool wedge = lo != glm::dvec2(0.0) && hi != glm::dvec2(0.0) && lo != hi;
  if (wedge) {
    a0 = std::atan2(lo.y, lo.x);
    span = std::atan2(hi.y, hi.x) - a0;
    if (span <= 0.0) span += kTurn;
  }
  const int steps = std::max(2, static_cast<int>(std::ceil(span / kMaxStep)));
  std::vector<glm::dvec2> points;
  points.reserve(static_cast<std::size_t>(steps) + 1);
  for (int k = 0; k <= steps; ++k) {
    const double a = a0 + span * k / steps;
    points.push_back(c + r * glm::dvec2(std::cos(a), std::sin(a)));
  }
  // the ends exactly along the rays' directions (no drift of the angles' rounding)
  if (wedge) {
    points.front() = c + r * glm::normalize(lo);
    points.back() = c + r * glm::normalize(hi);
  }
  return points;
}

}  // namespace convexloc::viewer
