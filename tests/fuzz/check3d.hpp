// convexloc fuzzing — checks of a validated polyhedron and of every 3D method on it.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <utility>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/locate3d.hpp"
#include "convexloc/mesh_reader.hpp"
#include "convexloc/polyhedron.hpp"
#include "fuzz_support.hpp"

namespace fuzz {

using convexloc::ConvexPolyhedron;
using convexloc::Locator3D;
using convexloc::MeshData;
using convexloc::Method3D;

// What a reader's MeshData promises: consistent face offsets, indices in range, one source
// line per vertex and per face when lines are given.
inline void checkMesh(const MeshData& mesh) {
  if (mesh.faceStart.empty() || mesh.faceStart.front() != 0) fail("faceStart must start at 0");
  if (mesh.faceStart.back() != mesh.indices.size()) fail("faceStart must end at indices.size()");
  for (std::size_t f = 0; f + 1 < mesh.faceStart.size(); ++f)
    if (mesh.faceStart[f + 1] < mesh.faceStart[f] + 3) fail("a face with fewer than 3 indices");
  for (std::uint32_t i : mesh.indices)
    if (i >= mesh.vertices.size()) fail("an index past the vertices: " + std::to_string(i));
  if (!mesh.vertexLines.empty() && mesh.vertexLines.size() != mesh.vertices.size())
    fail("vertexLines does not match the vertices");
  if (!mesh.faceLines.empty() && mesh.faceLines.size() != mesh.faceCount())
    fail("faceLines does not match the faces");
}

// Two meshes read from the same text must be the same, bit for bit.
inline void checkSameMesh(const MeshData& a, const MeshData& b) {
  if (a.vertices.size() != b.vertices.size() || a.indices != b.indices ||
      a.faceStart != b.faceStart || a.vertexLines != b.vertexLines || a.faceLines != b.faceLines)
    fail("the FILE and the text readers disagree on the mesh");
  for (std::size_t i = 0; i < a.vertices.size(); ++i)
    if (std::memcmp(&a.vertices[i], &b.vertices[i], sizeof(Vec3)) != 0)
      fail("the FILE and the text readers disagree on vertex " + std::to_string(i));
}

// What validation promises: a closed, consistently oriented, convex triangle surface of
// positive volume, counter-clockwise from outside; the centre (when there is one) strictly
// inside. Exact checks, O(F V): only for small polyhedra.
inline void checkPolyhedron(const ConvexPolyhedron& poly) {
  auto v = poly.vertices();
  auto tri = poly.triangles();
  auto nb = poly.neighbours();
  if (tri.size() < 4 || v.size() < 4) fail("a polyhedron with fewer than 4 faces or vertices");
  if (nb.size() != tri.size()) fail("neighbours() does not match triangles()");
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> edges;
  for (std::size_t t = 0; t < tri.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      std::uint32_t a = tri[t][k], b = tri[t][(k + 1) % 3];
      if (a >= v.size() || b >= v.size()) fail("a triangle index past the vertices");
      if (!edges.emplace(std::pair{a, b}, static_cast<std::uint32_t>(t)).second)
        fail("the directed edge " + std::to_string(a) + "->" + std::to_string(b) +
             " is used twice");
    }
  for (std::size_t t = 0; t < tri.size(); ++t)
    for (int k = 0; k < 3; ++k) {
      auto it = edges.find({tri[t][(k + 1) % 3], tri[t][k]});
      if (it == edges.end()) fail("the surface is open at triangle " + std::to_string(t));
      if (nb[t][k] != it->second) fail("neighbours() is wrong at triangle " + std::to_string(t));
    }
  // Euler: V - E + F = 2 for a sphere (every vertex is used: vertices() keeps only those)
  const long long euler = static_cast<long long>(v.size()) -
                          static_cast<long long>(edges.size() / 2) +
                          static_cast<long long>(tri.size());
  if (euler != 2) fail("Euler characteristic " + std::to_string(euler) + ", not a sphere");
  for (std::size_t t = 0; t < tri.size(); ++t) {
    bool someInside = false;
    for (std::size_t i = 0; i < v.size(); ++i) {
      int s = exactOrient3d(v[tri[t][0]], v[tri[t][1]], v[tri[t][2]], v[i]);
      if (s < 0)
        fail("not convex: vertex " + std::to_string(i) + " " + show(v[i]) +
             " is outside the plane of triangle " + std::to_string(t));
      someInside |= s > 0;
    }
    if (!someInside) fail("triangle " + std::to_string(t) + ": every vertex on its plane");
  }
  if (auto c = poly.centre())
    if (exactLocate3d(v, tri, *c) != Location::Inside) fail("centre() is not strictly inside");
}

// The query points a polyhedron invites: vertices and their one-ulp neighbours, edge
// midpoints, triangle centroids, the centre, and far points.
inline void addHardPoints3d(std::vector<Vec3>& out, const ConvexPolyhedron& poly) {
  auto v = poly.vertices();
  for (Vec3 p : v) {
    out.push_back(p);
    addNeighbours3d(out, p);
  }
  for (const auto& t : poly.triangles()) {
    Vec3 a = v[t[0]], b = v[t[1]], c = v[t[2]];
    out.push_back({a.x / 2 + b.x / 2, a.y / 2 + b.y / 2, a.z / 2 + b.z / 2});
    // the centroid (a sum of thirds may round past the largest double: then infinite)
    out.push_back(
        {a.x / 3 + b.x / 3 + c.x / 3, a.y / 3 + b.y / 3 + c.y / 3, a.z / 3 + b.z / 3 + c.z / 3});
  }
  if (auto c = poly.centre()) {
    out.push_back(*c);
    addNeighbours3d(out, *c);
  }
  const double big = 1.7976931348623157e308, inf = HUGE_VAL;
  for (Vec3 p :
       {Vec3{big, 0, 0}, Vec3{0, -big, 0}, Vec3{0, 0, big}, Vec3{big, big, big}, Vec3{0, 0, 0},
        Vec3{-0.0, -0.0, -0.0}, Vec3{inf, 0, 0}, Vec3{0, -inf, 0}, Vec3{0, 0, std::nan("")}})
    out.push_back(p);
}

// a cubemap resolution: 0 (automatic), small, or large
inline std::uint32_t resolution3dFrom(std::uint8_t b) {
  static constexpr std::array<std::uint32_t, 8> kChoices = {0, 1, 2, 3, 5, 8, 13, 64};
  return kChoices[b % kChoices.size()];
}

// Every 3D method on every query against the exact reference, plus batch and trace.
inline void checkMethods3d(const ConvexPolyhedron& poly, std::span<const Vec3> queries,
                           std::uint32_t resolution) {
  auto v = poly.vertices();
  auto tri = poly.triangles();
  std::vector<Location> reference(queries.size());
  // a point with an infinite or NaN coordinate is Outside (locate3d.hpp's contract)
  auto finite = [](Vec3 p) {
    return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
  };
  for (std::size_t k = 0; k < queries.size(); ++k)
    reference[k] = finite(queries[k]) ? exactLocate3d(v, tri, queries[k]) : Location::Outside;
  std::vector<Location> batch(queries.size());
  for (Method3D m : convexloc::kAllMethods3D) {
    const std::string name(convexloc::toString(m));
    std::vector<Locator3D> built;
    try {
      built.emplace_back(poly, m, resolution);
    } catch (const std::exception& e) {
      fail(name + " (resolution " + std::to_string(resolution) +
           ") failed to build on a valid polyhedron: " + e.what());
    }
    const Locator3D& loc = built.front();
    loc.locate(queries, batch);
    for (std::size_t k = 0; k < queries.size(); ++k) {
      Location got = loc.locate(queries[k]);
      if (got != reference[k])
        fail(name + " (resolution " + std::to_string(resolution) + ") says " +
             std::string(convexloc::toString(got)) + " for " + show(queries[k]) +
             ", exactly it is " + std::string(convexloc::toString(reference[k])) + " (" +
             std::to_string(tri.size()) + " triangles)");
      if (batch[k] != got) fail(name + ": batch and single answers differ for " + show(queries[k]));
      if (k < 64 && loc.trace(queries[k]).result != got)
        fail(name + ": trace and locate differ for " + show(queries[k]));
    }
    if (loc.stats().faces != poly.planeCount() || loc.stats().triangles != tri.size())
      fail(name + ": stats() counts the faces or the triangles wrong");
  }
}

}  // namespace fuzz
