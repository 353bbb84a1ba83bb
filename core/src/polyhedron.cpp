// convexloc — a validated convex polyhedron: the constructor runs the checks of
// detail/polyhedron_build.hpp in order (local ones in polyhedron_checks.cpp, the centre and
// the winding in polyhedron_centre.cpp) and keeps what they leave.
#include "convexloc/polyhedron.hpp"

#include <cmath>
#include <sstream>
#include <string>

#include "convexloc/predicates.hpp"
#include "detail/polyhedron_build.hpp"

namespace convexloc {

namespace detail {

std::string show(Vec3 p) {
  std::ostringstream s;
  s.precision(17);
  s << '(' << p.x << ", " << p.y << ", " << p.z << ')';
  return s.str();
}

bool collinear(Vec3 a, Vec3 b, Vec3 c) {
  return orient2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}) == 0 &&
         orient2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}) == 0 &&
         orient2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x}) == 0;
}

long double sixVolume(Vec3 o, Vec3 a, Vec3 b, Vec3 c, long double (&p)[3][3]) {
  const Vec3 abc[3] = {a, b, c};
  for (int k = 0; k < 3; ++k) {
    p[k][0] = static_cast<long double>(abc[k].x) - o.x;
    p[k][1] = static_cast<long double>(abc[k].y) - o.y;
    p[k][2] = static_cast<long double>(abc[k].z) - o.z;
  }
  return p[0][0] * (p[1][1] * p[2][2] - p[1][2] * p[2][1]) -
         p[0][1] * (p[1][0] * p[2][2] - p[1][2] * p[2][0]) +
         p[0][2] * (p[1][0] * p[2][1] - p[1][1] * p[2][0]);
}

}  // namespace detail

ConvexPolyhedron::ConvexPolyhedron(const MeshData& mesh) : ConvexPolyhedron(mesh, nullptr) {}

ConvexPolyhedron::ConvexPolyhedron(const MeshData& mesh, std::vector<std::uint32_t>* suspects,
                                   bool hullByConstruction) {
  detail::PolyhedronBuilder check(*this, mesh, suspects);
  check.checkArrays();
  check.checkFiniteVertices();
  check.checkFaces();
  check.mergeVertices();
  check.fanTriangulate();
  check.pairEdges();
  check.checkOnePieceSphere();
  check.checkPlanarFaces();
  check.findTetrahedron();
  check.flipSlivers();
  check.checkConvexEdges();
  check.mergePlanes();
  check.findCentre();
  // the solid-angle sum is floating point: it cannot resolve a needle whose directions from
  // the inside point round to two antipodal ones (vertices near 1e-222 and 1e154 in one
  // cloud); an exact hull needs no such check (see hullOf)
  if (!hullByConstruction) check.checkWindsOnce();
  check.findBounds();
}

int ConvexPolyhedron::side(std::size_t t, Vec3 p) const noexcept {
  const Triangle& f = triangles_[t];
  return orient3d(vertices_[f[0]], vertices_[f[1]], vertices_[f[2]], p);
}

double ConvexPolyhedron::volume() const noexcept {
  const Vec3 o = vertices_[0];
  long double six = 0;
  for (const Triangle& t : triangles_) {
    long double p[3][3];
    six += detail::sixVolume(o, vertices_[t[0]], vertices_[t[1]], vertices_[t[2]], p);
  }
  return static_cast<double>(six / 6);
}

double ConvexPolyhedron::area() const noexcept {
  long double twice = 0;
  for (const Triangle& t : triangles_) {
    const Vec3 a = vertices_[t[0]], b = vertices_[t[1]], c = vertices_[t[2]];
    long double ux = static_cast<long double>(b.x) - a.x, uy = static_cast<long double>(b.y) - a.y,
                uz = static_cast<long double>(b.z) - a.z;
    long double wx = static_cast<long double>(c.x) - a.x, wy = static_cast<long double>(c.y) - a.y,
                wz = static_cast<long double>(c.z) - a.z;
    long double nx = uy * wz - uz * wy, ny = uz * wx - ux * wz, nz = ux * wy - uy * wx;
    twice += std::sqrt(nx * nx + ny * ny + nz * nz);
  }
  return static_cast<double>(twice / 2);
}

}  // namespace convexloc
