// convexloc — Locator2D: the five 2D locators behind one type, the method chosen at run time.
#include <cstdint>
#include <variant>

#include "convexloc/locate2d.hpp"
#include "detail/locator_variant.hpp"

namespace convexloc {
namespace {

// the locator of `method`
std::variant<HalfplaneLocator, WedgeLocator, SlabLocator, UniformLocator, PolarLocator> build(
    const ConvexPolygon& polygon, Method2D method, std::uint32_t resolution) {
  switch (method) {
    case Method2D::Halfplane: return HalfplaneLocator(polygon);
    case Method2D::Wedge: return WedgeLocator(polygon);
    case Method2D::Slab: return SlabLocator(polygon);
    case Method2D::Uniform: return UniformLocator(polygon, resolution);
    case Method2D::Polar: break;
  }
  return PolarLocator(polygon, resolution);
}

}  // namespace

template class detail::LocatorVariant<Method2D, Vec2, Trace2D, Stats2D, Cell2D, HalfplaneLocator,
                                      WedgeLocator, SlabLocator, UniformLocator, PolarLocator>;

Locator2D::Locator2D(const ConvexPolygon& polygon, Method2D method, std::uint32_t resolution)
    : LocatorVariant(build(polygon, method, resolution)) {}

}  // namespace convexloc
