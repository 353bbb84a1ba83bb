// convexloc Python module — the one-call questions: is each point in this polygon, in the hull
// of this cloud? Each builds the O(1) locator (polar, cube map) and locates the batch.
#include <pybind11/numpy.h>

#include <optional>
#include <string>

#include "arrays.hpp"
#include "bindings.hpp"
#include "locator_class.hpp"

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

// the polygon itself, or the one Polygon() makes of it (vertices, a Shapely polygon, GeoJSON)
const ConvexPolygon& polygonOf(const py::object& shape, std::optional<ConvexPolygon>& made) {
  if (py::isinstance<ConvexPolygon>(shape)) return shape.cast<const ConvexPolygon&>();
  return made.emplace(polygonFrom(shape, "polygon"));
}

// the polyhedron itself, or the hull of the cloud
const ConvexPolyhedron& hullOf(const py::object& shape, std::optional<ConvexPolyhedron>& made) {
  if (py::isinstance<ConvexPolyhedron>(shape)) return shape.cast<const ConvexPolyhedron&>();
  const py::array cloud = pointArray(shape, 3, "cloud");
  const std::span<const Vec3> read = pointsOf<Vec3>(cloud);
  requireHullPoints(read.size());
  py::gil_scoped_release released;
  return made.emplace(ConvexPolyhedron::hullOf(read));
}

// builds Locator over `shape` without the GIL, then answers the batch as booleans
template <class Locator, class Point, class Shape>
py::array_t<bool> containsIn(const Shape& shape, const py::object& points, bool boundary,
                             unsigned workers) {
  std::optional<Locator> locator;
  {
    py::gil_scoped_release released;
    locator.emplace(shape);
  }
  auto codes = locateRows<Locator, Point>(*locator, points, workers);
  return insideOf(codes, boundary);
}

// whether the boundary counts: `covers`, unless the deprecated boundary= of contains says
bool boundaryCounts(bool covers, const py::object& boundary) {
  if (boundary.is_none()) return covers;
  if (covers) throw py::type_error("covers takes no boundary= (the boundary always counts)");
  PyErr_WarnEx(PyExc_DeprecationWarning,
               "contains(..., boundary=) is deprecated: contains is the interior only, as in "
               "Shapely; covers counts the boundary",
               1);
  return boundary.cast<bool>();
}

// the docstring of contains and covers (or hull_*): `shape` says what the points are tested
// against, `dims` their width, `locator` what answers
std::string containsDoc(bool covers, const char* dims, const char* shape, const char* locator) {
  const std::string counted = covers ? std::string("lies inside or on the boundary of ")
                                     : std::string("lies strictly inside ");
  const std::string scope =
      covers ? "The boundary counts, as in Shapely's covers."
             : "The interior only, as in Shapely's contains; the covers form counts the boundary "
               "too (boundary=True is the deprecated old way to ask for that).";
  return std::string("For each of the (M, ") + dims + ") points, whether it " + counted + shape +
         ": an (M,) bool array, exact. " + scope + " Builds a " + locator +
         ", then locates the batch.";
}

// Defines `name`(shape, points, *, workers=1): makes the shape when it is not one already
// (with `make`), then answers with Locator; `covers` says whether the boundary counts.
template <class Locator, class Point, class Shape, class Make>
void defineContains(py::module_& m, const char* name, bool covers, const char* shapeArg, Make make,
                    const std::string& doc) {
  auto body = [make, covers](const py::object& shape, const py::object& points,
                             const py::object& workers, const py::object& threads,
                             const py::object& boundary) {
    const bool counts = boundaryCounts(covers, boundary);
    const unsigned w = workerCount(workers, threads);
    std::optional<Shape> made;
    return containsIn<Locator, Point>(make(shape, made), points, counts, w);
  };
  if (covers)
    m.def(
        name,
        [body](const py::object& shape, const py::object& points, const py::object& workers,
               const py::object& threads) {
          return body(shape, points, workers, threads, py::none());
        },
        py::arg(shapeArg), py::arg("points"), py::kw_only(), py::arg("workers") = py::none(),
        py::arg("threads") = py::none(),
        signedDoc(name, keep("(" + std::string(shapeArg) + ", points, *, workers=1, threads=None)"),
                  doc));
  else
    m.def(name, body, py::arg(shapeArg), py::arg("points"), py::kw_only(),
          py::arg("workers") = py::none(), py::arg("threads") = py::none(),
          py::arg("boundary") = py::none(),
          signedDoc(name,
                    keep("(" + std::string(shapeArg) +
                         ", points, *, workers=1, threads=None, boundary=None)"),
                    doc));
}

}  // namespace

void bindConveniences(py::module_& m) {
  for (const bool covers : {false, true}) {
    defineContains<PolarLocator, Vec2, ConvexPolygon>(
        m, covers ? "covers" : "contains", covers, "polygon", &polygonOf,
        containsDoc(
            covers, "2",
            "the convex polygon (a Polygon, anything Polygon() takes: a Shapely polygon, GeoJSON, "
            "(N, 2) vertices)",
            "PolarLocator"));
    defineContains<CubemapLocator, Vec3, ConvexPolyhedron>(
        m, covers ? "hull_covers" : "hull_contains", covers, "cloud", &hullOf,
        containsDoc(covers, "3", "the convex hull of the (K, 3) cloud (or a Polyhedron)",
                    "CubemapLocator"));
  }
}

}  // namespace convexloc::python
