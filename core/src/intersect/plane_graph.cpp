// convexloc — the vertex graph of a polyhedron and the exact fallback of a plane's vertex
// comparison (graph3d.hpp).
#include <cstdint>
#include <vector>

#include "detail/exact_number.hpp"
#include "intersect/graph3d.hpp"

namespace convexloc::detail {

VertexGraph::VertexGraph(const ConvexPolyhedron& polyhedron) {
  // every edge of a closed surface lies in two triangles, once in each direction: the
  // directed edges a -> b of all triangles list each neighbour of a exactly once
  const std::size_t n = polyhedron.vertexCount();
  offsets.assign(n + 1, 0);
  for (const auto& t : polyhedron.triangles())
    for (int k = 0; k < 3; ++k) ++offsets[t[k] + 1];
  for (std::size_t v = 0; v < n; ++v) offsets[v + 1] += offsets[v];
  neighbours.resize(offsets[n]);
  std::vector<std::uint32_t> cursor(offsets.begin(), offsets.end() - 1);
  for (const auto& t : polyhedron.triangles())
    for (int k = 0; k < 3; ++k) neighbours[cursor[t[k]]++] = t[(k + 1) % 3];
}

int det3DifferencesExact(const Vec3 (&from)[3], const Vec3 (&to)[3]) noexcept {
  ExactRational r[3][3];
  for (int k = 0; k < 3; ++k) {
    r[k][0] = exactRational(to[k].x) - exactRational(from[k].x);
    r[k][1] = exactRational(to[k].y) - exactRational(from[k].y);
    r[k][2] = exactRational(to[k].z) - exactRational(from[k].z);
  }
  ExactRational det = 0;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    det += r[0][k] * (r[1][i] * r[2][j] - r[1][j] * r[2][i]);
  }
  return det.sign();
}

}  // namespace convexloc::detail
