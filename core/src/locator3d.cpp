// convexloc — Locator3D, any of the three 3D methods chosen at run time, and the surface
// copy they all keep.
#include "convexloc/locate3d.hpp"
#include "detail/locator_variant.hpp"

namespace convexloc {

detail::SurfaceCopy::SurfaceCopy(const ConvexPolyhedron& polyhedron)
    : vertices(polyhedron.vertices().begin(), polyhedron.vertices().end()),
      faces(polyhedron.planes().begin(), polyhedron.planes().end()),
      triangles(polyhedron.faceCount()) {}

std::size_t detail::SurfaceCopy::bytes() const noexcept {
  return bytesOf(vertices) + bytesOf(faces);
}

detail::WalkMesh::WalkMesh(const ConvexPolyhedron& polyhedron)
    : neighbours(polyhedron.neighbours().begin(), polyhedron.neighbours().end()) {
  if (polyhedron.planeCount() == polyhedron.faceCount()) return;  // plane face t is triangle t
  triangles.assign(polyhedron.triangles().begin(), polyhedron.triangles().end());
  planeOf.assign(polyhedron.planeOf().begin(), polyhedron.planeOf().end());
  firstTriangle.reserve(polyhedron.planeCount());
  for (std::size_t f = 0; f < polyhedron.planeCount(); ++f)
    firstTriangle.push_back(polyhedron.planeTriangles(f)[0]);
}

std::size_t detail::WalkMesh::bytes() const noexcept {
  return bytesOf(triangles) + bytesOf(neighbours) + bytesOf(planeOf) + bytesOf(firstTriangle);
}

namespace {

// the locator of `method`
std::variant<HalfspaceLocator, WalkLocator, CubemapLocator> build(
    const ConvexPolyhedron& polyhedron, Method3D method, std::uint32_t resolution) {
  switch (method) {
    case Method3D::Halfspace: return HalfspaceLocator(polyhedron);
    case Method3D::Walk: return WalkLocator(polyhedron);
    case Method3D::Cubemap: break;
  }
  return CubemapLocator(polyhedron, resolution);
}
}  // namespace

template class detail::LocatorVariant<Method3D, Vec3, Trace3D, Stats3D, Cell3D, HalfspaceLocator,
                                      WalkLocator, CubemapLocator>;

Locator3D::Locator3D(const ConvexPolyhedron& polyhedron, Method3D method, std::uint32_t resolution)
    : LocatorVariant(build(polyhedron, method, resolution)) {}

}  // namespace convexloc
