// convexloc — polyhedra and point sets for demos, tests and benchmarks. Deterministic:
// the same kind, size and seed give the same doubles on every platform (the hull kinds go
// through the exact hullOf, deterministic for the same input).
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "convexloc/generate2d.hpp"
#include "convexloc/geometry.hpp"
#include "convexloc/polyhedron.hpp"

namespace convexloc {

// === Polyhedra

enum class PolyhedronKind : std::uint8_t {
  Tetrahedron,    // the regular tetrahedron on alternate corners of [-1, 1]^3 (n ignored)
  Cube,           // [-1, 1]^3 as 6 squares (n ignored)
  Octahedron,     // the unit octahedron (n ignored)
  Dodecahedron,   // a pyritohedron near the regular dodecahedron, 12 exactly planar pentagons
  Icosahedron,    // the icosahedron (0, +-1, +-phi) and its permutations (n ignored)
  Geodesic,       // the unit icosahedron subdivided nu times per edge, 20 nu^2 faces, nu from n
  SphereHull,     // the hull of n / 2 + 2 random points on the unit sphere (about n faces)
  CubeHull,       // the hull of n random points in [-1, 1]^3 (far fewer than n faces)
  EllipsoidHull,  // the hull of n / 2 + 2 random points on the ellipsoid with axes 2, 1, 0.5
  ThinSlab,       // the box [0, 1]^2 x [0, 1e-9], its big faces split into grids (about n faces)
  Offset,         // a geodesic sphere (about n faces) of radius max(1, nu / 32) centred at 1e9
  TinyFaces,      // [-1, 1]^3 with its (1, 1, 1) corner rounded by a cap of radius 1e-4 made of
                  // about n tiny triangles: face areas differ by more than 10^10
  Coplanar,       // [-1, 1]^3 with each face split into a k x k grid of squares (about n faces)
  Cylinder,       // a cylinder over the regular polygon with n / 4 + 1 sides, z in [-1, 1], its
                  // quads split in two and its caps fanned from one corner as CAD programs
                  // export them (n triangles, 4 + n / 4 plane faces)
  Prism,          // a tilted prism over a convex lattice polygon of about n / 4 corners,
                  // integer coordinates, triangulated like the cylinder (about n triangles)
};

std::string_view toString(PolyhedronKind k);
std::optional<PolyhedronKind> parsePolyhedronKind(std::string_view name);
inline constexpr PolyhedronKind kAllPolyhedronKinds[] = {
    PolyhedronKind::Tetrahedron,  PolyhedronKind::Cube,        PolyhedronKind::Octahedron,
    PolyhedronKind::Dodecahedron, PolyhedronKind::Icosahedron, PolyhedronKind::Geodesic,
    PolyhedronKind::SphereHull,   PolyhedronKind::CubeHull,    PolyhedronKind::EllipsoidHull,
    PolyhedronKind::ThinSlab,     PolyhedronKind::Offset,      PolyhedronKind::TinyFaces,
    PolyhedronKind::Coplanar,     PolyhedronKind::Cylinder,    PolyhedronKind::Prism};

// A mesh of that kind with about `n` triangles (see each kind), faces counter-clockwise seen
// from outside; ConvexPolyhedron accepts every one. Throws UsageError for n < 4 or
// n > 2^24 (the hull kinds: n > 2^22).
MeshData generatePolyhedron(PolyhedronKind kind, std::size_t n, std::uint64_t seed);

// The convex hull of a small point set, exactly (O(n^4): at most 64 points), as polygon
// faces counter-clockwise from outside over indices into `points`. For the platonic solids.
MeshData smallHull(std::span<const Vec3> points);

// === Points

// `count` query points for `polyhedron`: uniform in its bounding box enlarged by 10% on each
// side, or, with `nearBoundary`, hard cases: vertices, points one ulp off them, points on
// edges and faces (exactly, where a double lies there; checked with exact predicates), points
// one ulp off faces, and points a hair inside or outside.
std::vector<Vec3> generatePoints3D(const ConvexPolyhedron& polyhedron, std::size_t count,
                                   std::uint64_t seed, bool nearBoundary);

}  // namespace convexloc
