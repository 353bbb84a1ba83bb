// convexloc (internal) — the canonical surface of an exact 3D hull (hull_surface.cpp).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "convexloc/geometry.hpp"

namespace convexloc::detail {

// A hull's surface written one way only: its extreme points in lexicographic order of their
// coordinates, each plane face as a fan from its smallest corner, the faces in order of their
// first two corners. The same surface gives the same arrays, however it was triangulated.
struct CanonicalSurface {
  std::vector<std::uint32_t> corners;                   // indices into the points
  std::vector<std::array<std::uint32_t, 3>> triangles;  // over positions in `corners`
};

// The canonical form of a closed convex surface over `points`: `triangles` counter-clockwise
// from outside, nondegenerate, with distinct corners, neighbours[t][k] the triangle across
// edge k of t (corner k to corner k + 1). Adjacent triangles are merged where exactly
// coplanar (orient3d), and a corner is kept where it is exactly not on the line through its
// neighbours on some face's boundary: then it is an extreme point. Throws std::logic_error
// should a face's boundary not be one loop (a convex surface's faces are discs).
CanonicalSurface canonicalSurface(std::span<const Vec3> points,
                                  std::span<const std::array<std::uint32_t, 3>> triangles,
                                  std::span<const std::array<std::uint32_t, 3>> neighbours);

}  // namespace convexloc::detail
