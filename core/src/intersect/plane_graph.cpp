// convexloc — the vertex graph of a polyhedron and the exact fallback of a plane's vertex
// comparison (graph3d.hpp).
#include <array>
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

// every operand times 2^-lo is an integer, so the determinant's sign is decided in integers
int det3DifferencesExact(const Vec3 (&from)[3], const Vec3 (&to)[3]) noexcept {
  const int shift = -commonLowestSetBit(std::array<double, 18>{
      from[0].x, from[0].y, from[0].z, from[1].x, from[1].y, from[1].z, from[2].x, from[2].y,
      from[2].z, to[0].x, to[0].y, to[0].z, to[1].x, to[1].y, to[1].z, to[2].x, to[2].y,
      to[2].z});
  auto exact = [shift](double v) { return scaledInteger(v, shift); };
  ExactInt r[3][3];
  for (int k = 0; k < 3; ++k) {
    r[k][0] = exact(to[k].x) - exact(from[k].x);
    r[k][1] = exact(to[k].y) - exact(from[k].y);
    r[k][2] = exact(to[k].z) - exact(from[k].z);
  }
  ExactInt det = 0;
  for (int k = 0; k < 3; ++k) {
    const int i = (k + 1) % 3, j = (k + 2) % 3;
    det += r[0][k] * (r[1][i] * r[2][j] - r[1][j] * r[2][i]);
  }
  return det.sign();
}

}  // namespace convexloc::detail
