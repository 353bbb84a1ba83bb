// convexloc — Locator3D, any of the three 3D methods chosen at run time, and the surface
// copy they all keep.
#include "convexloc/locate3d.hpp"

namespace convexloc {

detail::SurfaceCopy::SurfaceCopy(const ConvexPolyhedron& polyhedron)
    : vertices(polyhedron.vertices().begin(), polyhedron.vertices().end()),
      faces(polyhedron.triangles().begin(), polyhedron.triangles().end()) {}

std::size_t detail::SurfaceCopy::bytes() const noexcept {
  return bytesOf(vertices) + bytesOf(faces);
}

namespace {
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

Locator3D::Locator3D(const ConvexPolyhedron& polyhedron, Method3D method, std::uint32_t resolution)
    : impl_(build(polyhedron, method, resolution)) {}

Location Locator3D::locate(Vec3 p) const noexcept {
  return std::visit([&](const auto& l) { return l.locate(p); }, impl_);
}
void Locator3D::locate(std::span<const Vec3> points, std::span<Location> out) const noexcept {
  std::visit([&](const auto& l) { l.locate(points, out); }, impl_);
}
Trace3D Locator3D::trace(Vec3 p) const {
  return std::visit([&](const auto& l) { return l.trace(p); }, impl_);
}
Stats3D Locator3D::stats() const {
  return std::visit([&](const auto& l) { return l.stats(); }, impl_);
}
std::vector<Cell3D> Locator3D::cells() const {
  return std::visit([&](const auto& l) { return l.cells(); }, impl_);
}

}  // namespace convexloc
