// convexloc (benchmarks and tests) — cylinders as a CAD program exports them: N sides, the
// side quads split in two, the caps fanned from one corner, turned by odd angles, perhaps
// moved far from the origin, every coordinate rounded to float32 as binary STL stores it.
// Rounding folds most of them slightly (reflex by a few ulps); those are read as their hull,
// as `convexloc --hull` reads them.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include "convexloc/error.hpp"
#include "convexloc/polyhedron.hpp"

namespace cadfamily {

using convexloc::ConvexPolyhedron;
using convexloc::MeshData;
using convexloc::Vec3;

// one member of the family
struct Part {
  std::size_t sides = 64;
  double heightRadii = 1;  // the height in radii
  bool moved = false;      // moved by 10^6 on every axis
};

// the radius: large enough that float32 at 10^6 keeps the 65536 corners apart
inline constexpr double kRadius = 1e4;

// x turned by odd angles (about z by 0.7, y by 0.31, x by 1.13 radians), then moved
inline Vec3 place(Vec3 p, bool moved) {
  const double a = 0.7, b = 0.31, c = 1.13;
  const Vec3 z{std::cos(a) * p.x - std::sin(a) * p.y, std::sin(a) * p.x + std::cos(a) * p.y, p.z};
  const Vec3 y{std::cos(b) * z.x + std::sin(b) * z.z, z.y, -std::sin(b) * z.x + std::cos(b) * z.z};
  const Vec3 x{y.x, std::cos(c) * y.y - std::sin(c) * y.z, std::sin(c) * y.y + std::cos(c) * y.z};
  const double shift = moved ? 1e6 : 0.0;
  return {x.x + shift, x.y + shift, x.z + shift};
}

// the nearest float32, as binary STL stores a coordinate
inline Vec3 toFloat32(Vec3 p) {
  return {static_cast<double>(static_cast<float>(p.x)),
          static_cast<double>(static_cast<float>(p.y)),
          static_cast<double>(static_cast<float>(p.z))};
}

// the exported triangles: 4N - 4 of them, counter-clockwise from outside
inline MeshData mesh(const Part& part) {
  MeshData m;
  const auto n = static_cast<std::uint32_t>(part.sides);
  const double half = 0.5 * part.heightRadii * kRadius;
  for (std::uint32_t k = 0; k < n; ++k) {
    const double phi = 2 * 3.14159265358979323846 * k / n;
    const double x = kRadius * std::cos(phi), y = kRadius * std::sin(phi);
    m.addVertex(toFloat32(place({x, y, -half}, part.moved)));  // 2k: bottom
    m.addVertex(toFloat32(place({x, y, half}, part.moved)));   // 2k + 1: top
  }
  for (std::uint32_t k = 0; k < n; ++k) {
    const std::uint32_t b0 = 2 * k, t0 = b0 + 1, b1 = 2 * ((k + 1) % n), t1 = b1 + 1;
    m.addFace({b0, b1, t1});
    m.addFace({b0, t1, t0});
  }
  for (std::uint32_t k = 1; k + 1 < n; ++k) {
    m.addFace({1, 2 * k + 1, 2 * k + 3});  // top, seen from above: counter-clockwise
    m.addFace({0, 2 * k + 2, 2 * k});      // bottom, seen from below
  }
  return m;
}

// the part as read: the mesh where it is convex as rounded, else its exact hull
inline ConvexPolyhedron polyhedron(const Part& part, bool* hull = nullptr) {
  const MeshData m = mesh(part);
  try {
    ConvexPolyhedron p(m);
    if (hull) *hull = false;
    return p;
  } catch (const convexloc::GeometryError&) {
    if (hull) *hull = true;
    return ConvexPolyhedron::hullOf(m.vertices);
  }
}

}  // namespace cadfamily
