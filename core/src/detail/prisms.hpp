// convexloc (internal) — prisms as CAD programs export them: side quads split into two
// triangles, caps fan-triangulated from one corner (generate3d's cylinder and prism kinds).
#pragma once

#include <cstddef>

#include "convexloc/polyhedron.hpp"

namespace convexloc::detail {

// the cylinder over the regular polygon with `sides` corners on the unit circle, z in
// [-1, 1]: 4 sides - 4 triangles
MeshData cylinderMesh(std::size_t sides);

// A prism over a convex lattice polygon of about `corners` corners (the primitive integer
// vectors of a square, sorted by angle and summed), its top moved sideways by a third and a
// fifth of its width: a tilted prism with integer coordinates, every face exactly planar.
MeshData latticePrismMesh(std::size_t corners);

}  // namespace convexloc::detail
