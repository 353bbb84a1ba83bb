// convexloc Python module — the one-call questions: is each point in this polygon, in the hull
// of this cloud? Each builds the O(1) locator (polar, cube map) and locates the batch.
#include <pybind11/numpy.h>

#include <optional>

#include "arrays.hpp"
#include "bindings.hpp"

namespace convexloc::python {

namespace {

// codes to booleans: inside, and on the boundary when `boundary`
py::array_t<bool> insideOf(py::array_t<std::int8_t>& codes, bool boundary) {
  py::array_t<bool> out(codes.size());
  const std::span<const Location> where = locationsOf(codes);
  bool* to = out.mutable_data();
  py::gil_scoped_release released;
  for (std::size_t i = 0; i < where.size(); ++i)
    to[i] = where[i] == Location::Inside || (boundary && where[i] == Location::Boundary);
  return out;
}

// the polygon itself, or the one its vertices make
const ConvexPolygon& polygonOf(const py::object& shape, std::optional<ConvexPolygon>& made) {
  if (py::isinstance<ConvexPolygon>(shape)) return shape.cast<const ConvexPolygon&>();
  const py::array vertices = pointArray(shape, 2, "polygon_vertices");
  const std::span<const Vec2> read = pointsOf<Vec2>(vertices);
  py::gil_scoped_release released;
  return made.emplace(read);
}

// the polyhedron itself, or the hull of the cloud
const ConvexPolyhedron& hullOf(const py::object& shape, std::optional<ConvexPolyhedron>& made) {
  if (py::isinstance<ConvexPolyhedron>(shape)) return shape.cast<const ConvexPolyhedron&>();
  const py::array cloud = pointArray(shape, 3, "cloud");
  const std::span<const Vec3> read = pointsOf<Vec3>(cloud);
  py::gil_scoped_release released;
  return made.emplace(ConvexPolyhedron::hullOf(read));
}

// builds Locator over `shape` without the GIL, then answers the batch as booleans
template <class Locator, class Point, class Shape>
py::array_t<bool> containsIn(const Shape& shape, const py::object& points, bool boundary,
                             long threads) {
  std::optional<Locator> locator;
  {
    py::gil_scoped_release released;
    locator.emplace(shape);
  }
  auto codes = locateRows<Locator, Point>(*locator, points, threads);
  return insideOf(codes, boundary);
}

// Defines `name`(shape, points, *, boundary=True, threads=0): makes the shape when it is
// not one already (with `make`), then answers with Locator.
template <class Locator, class Point, class Shape, class Make>
void defineContains(py::module_& m, const char* name, const char* shapeArg, Make make,
                    const char* doc) {
  m.def(
      name,
      [make](const py::object& shape, const py::object& points, bool boundary, long threads) {
        std::optional<Shape> made;
        return containsIn<Locator, Point>(make(shape, made), points, boundary, threads);
      },
      py::arg(shapeArg), py::arg("points"), py::kw_only(), py::arg("boundary") = true,
      py::arg("threads") = 0, doc);
}

}  // namespace

void bindConveniences(py::module_& m) {
  defineContains<PolarLocator, Vec2, ConvexPolygon>(
      m, "contains", "polygon_vertices", &polygonOf,
      "For each of the (M, 2) points, whether it lies in the convex polygon (its (N, 2) "
      "vertices, or a Polygon): an (M,) bool array, exact. A point on the boundary counts "
      "unless boundary=False. Builds a PolarLocator, then locates the batch.");
  defineContains<CubemapLocator, Vec3, ConvexPolyhedron>(
      m, "hull_contains", "cloud", &hullOf,
      "For each of the (M, 3) points, whether it lies in the convex hull of the (K, 3) cloud "
      "(or in a Polyhedron): an (M,) bool array, exact for the hull Qhull gives. A point on "
      "the boundary counts unless boundary=False. Builds a CubemapLocator, then locates.");
}

}  // namespace convexloc::python
