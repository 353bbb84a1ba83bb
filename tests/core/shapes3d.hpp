// Polyhedra for the 3D tests: small meshes written out by hand (valid and invalid), and the
// matrix of generated shapes with the number of random points each gets.
#pragma once

#include <cmath>
#include <cstddef>
#include <string>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/polyhedron.hpp"

namespace shapes3d {

using convexloc::MeshData;
using convexloc::Vec3;

// the cube [-1, 1]^3 as 6 squares, counter-clockwise from outside
inline MeshData cube() {
  MeshData m;
  for (double x : {-1.0, 1.0})
    for (double y : {-1.0, 1.0})
      for (double z : {-1.0, 1.0}) m.addVertex({x, y, z});
  // vertex index = 4 * (x > 0) + 2 * (y > 0) + (z > 0)
  m.addFace({0, 1, 3, 2});  // x = -1
  m.addFace({4, 6, 7, 5});  // x = +1
  m.addFace({0, 4, 5, 1});  // y = -1
  m.addFace({2, 3, 7, 6});  // y = +1
  m.addFace({0, 2, 6, 4});  // z = -1
  m.addFace({1, 5, 7, 3});  // z = +1
  return m;
}

// the box with corners lo and hi, faces as in cube()
inline MeshData box(Vec3 lo, Vec3 hi) {
  MeshData m = cube();
  for (Vec3& v : m.vertices)
    v = {v.x < 0 ? lo.x : hi.x, v.y < 0 ? lo.y : hi.y, v.z < 0 ? lo.z : hi.z};
  return m;
}

// a tetrahedron with the given corners, counter-clockwise from outside when a, b, c turn
// counter-clockwise seen from d's far side
inline MeshData tetrahedron(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  MeshData m;
  m.vertices = {a, b, c, d};
  m.addFace({0, 2, 1});
  m.addFace({0, 1, 3});
  m.addFace({1, 2, 3});
  m.addFace({2, 0, 3});
  return m;
}

// a mesh with every face reversed
inline MeshData reversed(MeshData m) {
  for (std::size_t f = 0; f < m.faceCount(); ++f)
    std::reverse(m.indices.begin() + m.faceStart[f], m.indices.begin() + m.faceStart[f + 1]);
  return m;
}

// The bipyramid over the star polygon {7/2}: locally convex at every edge, a topological
// sphere, yet it winds twice around the axis.
inline MeshData starBipyramid() {
  MeshData m;
  const int n = 7;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * 3.14159265358979323846 * 2 * i / n;
    m.addVertex({std::cos(a), std::sin(a), 0});
  }
  const std::uint32_t top = m.addVertex({0, 0, 1}), bottom = m.addVertex({0, 0, -1});
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    m.addFace({i, j, top});
    m.addFace({j, i, bottom});
  }
  return m;
}

// A square torus: a 4 x 4 grid of quads around a ring (Euler characteristic 0).
inline MeshData torus() {
  MeshData m;
  const int n = 4;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double a = 2 * 3.14159265358979323846 * i / n, b = 2 * 3.14159265358979323846 * j / n;
      const double r = 3 + std::cos(b);
      m.addVertex({r * std::cos(a), r * std::sin(a), std::sin(b)});
    }
  auto at = [&](int i, int j) {
    return static_cast<std::uint32_t>(((i + n) % n) * n + (j + n) % n);
  };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) m.addFace({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
  return m;
}

// the message and line of the error building a polyhedron from `m` throws, or "" if none
struct Failure {
  std::string message;
  std::size_t line = 0;
  bool geometry = false;
};
inline Failure failureOf(const MeshData& m) {
  try {
    convexloc::ConvexPolyhedron p(m);
  } catch (const convexloc::GeometryError& e) {
    return {e.what(), e.line(), true};
  } catch (const convexloc::Error& e) {
    return {e.what(), e.line(), false};
  }
  return {};
}

// one generated shape of the test matrix
struct ShapeCase {
  convexloc::PolyhedronKind kind;
  std::size_t n;             // the size asked of the generator
  std::size_t randomPoints;  // uniform points in the enlarged box
  std::size_t nearPoints;    // the generator's near-boundary points
};

// Every kind, including every degenerate preset, small enough that the exact reference
// (all faces per point) stays quick; the large ones get fewer points.
inline const std::vector<ShapeCase>& matrix() {
  using K = convexloc::PolyhedronKind;
  static const std::vector<ShapeCase> cases = {
      {K::Tetrahedron, 4, 60000, 40000},     {K::Cube, 12, 60000, 40000},
      {K::Octahedron, 8, 60000, 40000},      {K::Dodecahedron, 36, 60000, 40000},
      {K::Icosahedron, 20, 60000, 40000},    {K::Geodesic, 320, 60000, 40000},
      {K::SphereHull, 200, 60000, 40000},    {K::CubeHull, 400, 60000, 40000},
      {K::EllipsoidHull, 200, 60000, 40000}, {K::ThinSlab, 200, 60000, 40000},
      {K::Offset, 320, 60000, 40000},        {K::TinyFaces, 200, 60000, 40000},
      {K::Coplanar, 300, 60000, 40000},      {K::Geodesic, 5120, 3000, 3000},
      {K::TinyFaces, 6000, 3000, 3000},      {K::ThinSlab, 5000, 3000, 3000},
      {K::Cylinder, 256, 60000, 40000},      {K::Cylinder, 16380, 3000, 3000},
      {K::Prism, 1000, 20000, 20000},        {K::Prism, 8000, 3000, 3000},
  };
  return cases;
}

}  // namespace shapes3d
