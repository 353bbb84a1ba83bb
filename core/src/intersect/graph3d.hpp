// convexloc (internal) — exact steps over a polyhedron's vertex graph for a plane's side
// function.
//
// For the plane through q1, q2, q3 and G(v) = orient3d(q1, q2, q3, v) = (q1 - v) . N with
// N = (q2 - q1) x (q3 - q1), the difference G(v) - G(u) = (u - v) . N is the determinant of
// the rows u - v, q2 - q1, q3 - q1: each entry one rounded difference, as in orient3d, so
// Shewchuk's orient3d bound holds for it and the same filter decides its sign, with exact
// rationals where it cannot. Swapping q2 and q3 negates G, so a smallest vertex is a largest
// one of the swapped plane.
//
// A vertex of a convex polyhedron none of whose neighbours (in the triangulated surface) has
// a strictly larger G is a largest one: the polyhedron lies in the cone of the edges at that
// vertex, and G is linear. The dual's climb (PlaneIntersector::largestFrom) stops only
// there, whatever vertex it starts from; it ends because G rises strictly at every move.
#pragma once

#include <cmath>
#include <cstdint>
#include <span>
#include <vector>

#include "convexloc/geometry.hpp"
#include "convexloc/polyhedron.hpp"
#include "convexloc/predicates.hpp"

namespace convexloc::detail {

// the neighbours of every vertex, in CSR form
struct VertexGraph {
  std::vector<std::uint32_t> offsets;  // vertex v's neighbours: [offsets[v], offsets[v + 1])
  std::vector<std::uint32_t> neighbours;
  explicit VertexGraph(const ConvexPolyhedron& polyhedron);
  std::span<const std::uint32_t> of(std::uint32_t v) const noexcept {
    return {neighbours.data() + offsets[v], offsets[v + 1] - offsets[v]};
  }
};

// exact sign of the determinant of rows a, b, c given as nine exact differences' operands:
// row k is (to[k] - from[k])
int det3DifferencesExact(const Vec3 (&from)[3], const Vec3 (&to)[3]) noexcept;

// A plane through three points, and a count of the vertex comparisons made against it. The
// rows q2 - q1 and q3 - q1 are the same in every comparison, so their 2 x 2 minors (and the
// magnitudes that bound their rounding) are formed once, with the very operations the full
// expansion would use: every comparison computes the same doubles it would from scratch.
struct PlaneProbe {
  Vec3 q1, q2, q3;
  std::uint32_t comparisons = 0;
  double minor[3] = {}, magnitude[3] = {};  // per column k of the first row: l - r, |l| + |r|
  bool tameRows = false;                    // every entry of the two fixed rows is tame

  PlaneProbe(Vec3 a, Vec3 b, Vec3 c) noexcept : q1(a), q2(b), q3(c) {
    const double rows[2][3] = {{q2.x - q1.x, q2.y - q1.y, q2.z - q1.z},
                               {q3.x - q1.x, q3.y - q1.y, q3.z - q1.z}};
    tameRows = true;
    for (int k = 0; k < 3; ++k) {
      const int i = (k + 1) % 3, j = (k + 2) % 3;
      const double l = rows[0][i] * rows[1][j], r = rows[0][j] * rows[1][i];
      minor[k] = l - r;
      magnitude[k] = std::fabs(l) + std::fabs(r);
      tameRows = tameRows && tame3d(rows[0][k]) && tame3d(rows[1][k]);
    }
  }
  // the exact sign of G(v) - G(u): the determinant of rows u - v, q2 - q1, q3 - q1, expanded
  // along the first row, with the permanent that bounds its rounding
  int rise(Vec3 u, Vec3 v) noexcept {
    ++comparisons;
    const double d[3] = {u.x - v.x, u.y - v.y, u.z - v.z};
    double det = 0.0, permanent = 0.0;
    for (int k = 0; k < 3; ++k) {
      det += d[k] * minor[k];
      permanent += std::fabs(d[k]) * magnitude[k];
    }
    const bool tame = tameRows && tame3d(d[0]) && tame3d(d[1]) && tame3d(d[2]);
    if (tame && std::fabs(det) > kO3dBound * permanent) return det > 0 ? 1 : -1;
    if (tame && permanent == 0.0) return 0;
    return det3DifferencesExact({v, q1, q1}, {u, q2, q3});
  }
  // the same plane with its sides swapped
  PlaneProbe swapped() const noexcept { return {q1, q3, q2}; }
};

}  // namespace convexloc::detail
