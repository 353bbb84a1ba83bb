// convexloc-viewer — the face a 3D query's ray leaves by.
#include "logic/teach/query_view.hpp"

#include <cmath>
#include <cstdint>
#include <limits>

namespace convexloc::viewer {
namespace {

glm::dvec3 at(const ConvexPolyhedron& shape, std::uint32_t v) {
  const Vec3 p = shape.vertices()[v];
  return {p.x, p.y, p.z};
}

}  // namespace

std::optional<RayExit> rayExitFace(const ConvexPolyhedron& shape, glm::dvec3 centre,
                                   glm::dvec3 point) {
  const glm::dvec3 d = point - centre;
  if (d == glm::dvec3(0.0)) return std::nullopt;
  std::optional<RayExit> best;
  double nearest = std::numeric_limits<double>::infinity();
  for (std::size_t f = 0; f < shape.planeCount(); ++f) {
    const ConvexPolyhedron::Triangle& t = shape.planes()[f];
    const glm::dvec3 a = at(shape, t[0]);
    glm::dvec3 n = glm::cross(at(shape, t[1]) - a, at(shape, t[2]) - a);
    // the normal points away from the centre, which lies strictly inside
    if (glm::dot(n, centre - a) > 0.0) n = -n;
    const double along = glm::dot(n, d);
    if (along <= 0.0) continue;  // the ray runs away from this plane
    const double t0 = glm::dot(n, a - centre) / along;
    if (t0 >= nearest) continue;
    nearest = t0;
    glm::dvec3 sum(0.0);
    const auto loop = shape.planeLoop(f);
    for (std::uint32_t v : loop) sum += at(shape, v);
    best = RayExit{f, sum / static_cast<double>(loop.size()), glm::normalize(n)};
  }
  return best;
}

glm::dvec3 viewAcrossRay(glm::dvec3 centre, glm::dvec3 point, glm::dvec3 faceNormal, double turn,
                         double lean) {
  glm::dvec3 d = point - centre;
  d = glm::length(d) > 0.0 ? glm::normalize(d) : glm::dvec3(1.0, 0.0, 0.0);
  // the face's normal square to the ray: looking against it faces the face
  glm::dvec3 n = faceNormal - glm::dot(faceNormal, d) * d;
  if (!(glm::length(n) > 1e-9 * glm::length(faceNormal))) {
    // the ray runs along the normal: any direction square to the ray, away from z if it can
    n = glm::cross(d, std::abs(d.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0));
  }
  n = glm::normalize(n);
  // turned about the ray (Rodrigues; n is square to d)
  const glm::dvec3 turned = std::cos(turn) * n + std::sin(turn) * glm::cross(d, n);
  // the eye raised toward x's side by `lean`: the exit face, whose normal runs near the
  // ray, is seen from its front, and the ray keeps cos(lean) of its length on the page
  const glm::dvec3 eye = std::cos(lean) * turned + std::sin(lean) * d;
  return -eye;
}

}  // namespace convexloc::viewer
