// convexloc (internal) — the walk over face adjacency, shared by the walk locator and the
// cube map's crowded cells.
//
// From a centre c strictly inside, each triangle spans a cone of directions, and the cones
// tile the sphere of directions with the triangles' adjacency. At a triangle,
// orient3d(c, a, b, p) > 0 for one of its edges (a, b) means the direction p - c lies beyond
// that edge: the walk crosses into the neighbour there. A triangle where no edge says so
// holds the direction in its closed cone, so the ray from c through p leaves the polyhedron
// through it; one test against its plane face then classifies p exactly (see
// plane_tests3d.hpp).
#pragma once

#include <cstdint>
#include <vector>

#include "convexloc/locate3d.hpp"
#include "convexloc/predicates.hpp"
#include "detail/plane_tests3d.hpp"

namespace convexloc::detail {

// Remembering stochastic walk toward the face whose cone from the centre c holds p - c. The
// edges of a face are tried from a random one (the edge just crossed is skipped). Returns
// that face, or kNoFace after `cap` faces. Deterministic: the random source restarts per
// query. Out of line: it is the rare path of the cube map's leaf test, which stays small.
template <class Sink>
[[gnu::noinline]] std::uint32_t walkToExit(
    const SurfaceCopy& surface, const WalkMesh& mesh, Vec3 c, Vec3 p, std::uint32_t start,
    std::uint32_t cap, Sink& sink) {
  const std::vector<Vec3>& v = surface.vertices;
  const std::vector<ConvexPolyhedron::Triangle>& neighbours = mesh.neighbours;
  const std::vector<ConvexPolyhedron::Triangle>& triangles = mesh.trianglesOf(surface);
  std::uint32_t face = start, from = kNoFace;
  std::uint32_t rng = 0x9e3779b9u;
  for (std::uint32_t visited = 0; visited < cap; ++visited) {
    sink.visit(face);
    rng ^= rng << 13;
    rng ^= rng >> 17;
    rng ^= rng << 5;
    const std::uint32_t r = rng % 3;
    std::uint32_t next = kNoFace;
    for (std::uint32_t j = 0; j < 3 && next == kNoFace; ++j) {
      const std::uint32_t k = (r + j) % 3;
      if (neighbours[face][k] == from) continue;
      const ConvexPolyhedron::Triangle& t = triangles[face];
      int s = orient3d(c, v[t[k]], v[t[(k + 1) % 3]], p);
      sink.step(face, static_cast<std::uint8_t>(k), s);
      if (s > 0) next = neighbours[face][k];
    }
    if (next == kNoFace) return face;
    from = face;
    face = next;
  }
  return kNoFace;
}

// walks from triangle `start` and tests p against the plane face of the triangle the walk
// ends at; giveUp() answers instead when the walk runs past `cap` triangles
template <class Sink, class GiveUp>
Location walkAndTest(const SurfaceCopy& surface, const WalkMesh& mesh, Vec3 c, Vec3 p,
                     std::uint32_t start, std::uint32_t cap, Sink& sink, GiveUp&& giveUp) {
  const std::uint32_t exit = walkToExit(surface, mesh, c, p, start, cap, sink);
  if (exit == kNoFace) return giveUp();
  const std::uint32_t plane = mesh.plane(exit);
  const int s = planeSign(surface, plane, p);
  sink.face(plane, s);
  return fromExit(s);
}

}  // namespace convexloc::detail
