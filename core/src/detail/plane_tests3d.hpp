// convexloc (internal) — the plane tests every 3D locator ends with.
//
// A face is a triangle of the surface, counter-clockwise from outside, so orient3d of its
// corners and p is > 0 for p on its inner side. Given faces that include one through which
// the ray from a centre strictly inside through p leaves the polyhedron, "any negative:
// Outside; else any zero: Boundary; else Inside" is exact (eq. 2); over every face it needs
// no centre at all.
#pragma once

#include <cmath>
#include <cstdint>

#include "convexloc/locate3d.hpp"
#include "convexloc/predicates.hpp"

namespace convexloc::detail {

// the mark for "no face" (a walk that gave up, a missing neighbour)
inline constexpr std::uint32_t kNoFace = 0xffffffffu;

// all three coordinates are finite
[[gnu::always_inline]] inline bool isFinite(Vec3 p) {
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// true, and the sink told, when p has an infinite or NaN coordinate (then p is Outside)
template <class Sink>
bool refusedAsNonFinite(Vec3 p, Sink& sink) {
  if (isFinite(p)) return false;
  sink.nonFinite();
  return true;
}

// orient3d of p against face f: > 0 on the inner side
[[gnu::always_inline]] inline int planeSign(const SurfaceCopy& surface, std::uint32_t f, Vec3 p) {
  const ConvexPolyhedron::Triangle& t = surface.faces[f];
  return orient3d(surface.vertices[t[0]], surface.vertices[t[1]], surface.vertices[t[2]], p);
}

// the class of p from the plane of a face its ray from the centre leaves through
[[gnu::always_inline]] inline Location fromExit(int s) {
  return s > 0 ? Location::Inside : (s == 0 ? Location::Boundary : Location::Outside);
}

// Tests p against faces faceAt(0) .. faceAt(count - 1), stopping at the first outer side:
// any outer side is Outside, else any plane through p is Boundary, else Inside.
template <class Sink, class FaceAt>
[[gnu::always_inline]] inline Location testFaces(const SurfaceCopy& surface, std::uint32_t count,
                                                 FaceAt faceAt, Vec3 p, Sink& sink) {
  bool zero = false;
  for (std::uint32_t k = 0; k < count; ++k) {
    const std::uint32_t f = faceAt(k);
    int s = planeSign(surface, f, p);
    sink.face(f, s);
    if (s < 0) return Location::Outside;
    zero |= s == 0;
  }
  return zero ? Location::Boundary : Location::Inside;
}

// tests p against every face (eq. 2)
template <class Sink>
Location testAll(const SurfaceCopy& surface, Vec3 p, Sink& sink) {
  const auto count = static_cast<std::uint32_t>(surface.faces.size());
  return testFaces(
      surface, count, [](std::uint32_t k) { return k; }, p, sink);
}

// tests p against the listed faces, which include a face its ray from the centre leaves
// through (in line: the cube map's leaf test)
template <class Sink>
[[gnu::always_inline]] inline Location testList(const SurfaceCopy& surface,
                                                const std::uint32_t* first,
                                                const std::uint32_t* last, Vec3 p, Sink& sink) {
  const auto count = static_cast<std::uint32_t>(last - first);
  return testFaces(
      surface, count, [first](std::uint32_t k) { return first[k]; }, p, sink);
}

// the statistics every 3D method shares; `ownBytes` is what the locator holds beside its
// surface copy (its own size included)
inline Stats3D baseStats(const SurfaceCopy& surface, std::size_t ownBytes, double buildSeconds) {
  Stats3D s;
  s.faces = surface.faces.size();
  s.triangles = surface.triangles;
  s.vertices = surface.vertices.size();
  s.bytes = ownBytes + surface.bytes();
  s.bytesPerFace =
      s.triangles ? static_cast<double>(s.bytes) / static_cast<double>(s.triangles) : 0.0;
  s.buildSeconds = buildSeconds;
  return s;
}

}  // namespace convexloc::detail
