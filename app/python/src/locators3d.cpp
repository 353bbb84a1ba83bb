// convexloc Python module — the three 3D locator classes, and what only some of them show.
#include "locator_class.hpp"

namespace convexloc::python {

void bindLocators3D(py::module_& m) {
  bindLocator<HalfspaceLocator>(m, "HalfspaceLocator", Method3D::Halfspace);
  auto walk = bindLocator<WalkLocator>(m, "WalkLocator", Method3D::Walk);
  defineCentre(walk, "(x, y, z) strictly inside, or None (then every query tests all faces)");
  auto cubemap = bindLocator<CubemapLocator>(m, "CubemapLocator", Method3D::Cubemap);
  defineCentre(cubemap, "(x, y, z): the centre of the cube map, or None (then no cells)");
  locatorProperty(cubemap, "resolution", &CubemapLocator::resolution,
                  "G: the base grid is G x G on each cube face (0: no cells)");
  locatorProperty(cubemap, "cube_half_size", &CubemapLocator::cubeHalfSize,
                  "half the side of the cube around the centre that cells() draws on");
  locatorProperty(cubemap, "loaded", &CubemapLocator::loaded,
                  "whether it was loaded from a pickle's tables rather than built "
                  "(stats()['build_seconds'] is then the build's)");
}

}  // namespace convexloc::python
