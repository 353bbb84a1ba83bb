// convexloc Python module — the five 2D locator classes, and what only some of them show.
#include "locator_class.hpp"

namespace convexloc::python {

void bindLocators2D(py::module_& m) {
  bindLocator<HalfplaneLocator>(m, "HalfplaneLocator", Method2D::Halfplane);
  bindLocator<WedgeLocator>(m, "WedgeLocator", Method2D::Wedge);
  bindLocator<SlabLocator>(m, "SlabLocator", Method2D::Slab);
  auto uniform = bindLocator<UniformLocator>(m, "UniformLocator", Method2D::Uniform);
  locatorProperty(uniform, "slab_count", &UniformLocator::slabCount, "the number of slabs");
  auto polar = bindLocator<PolarLocator>(m, "PolarLocator", Method2D::Polar);
  defineCentre(polar, "(x, y): the centre of the polar slabs, strictly inside the polygon");
  locatorProperty(polar, "slabs_per_octant", &PolarLocator::slabsPerOctant,
                  "the resolution: slabs in each of the 8 octants");
  polar.def_property_readonly(
      "box",
      [](const Bound<PolarLocator>& b) {
        return py::make_tuple(toPython(b.locator.box().lo), toPython(b.locator.box().hi));
      },
      "((xmin, ymin), (xmax, ymax)): the box the cells are drawn to");
}

}  // namespace convexloc::python
