// convexloc Python module — shapes from Python values: a polygon from vertices or from any
// object with __geo_interface__ (Shapely's polygons among them), the exact 2D hull of points,
// and the checks that name the user's own numbers before core sees them.
#include <pybind11/numpy.h>

#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include "arrays.hpp"
#include "bindings.hpp"
#include "convexloc/generate2d.hpp"
#include "errors.hpp"

namespace convexloc::python {

namespace {

// a GeometryError about a shape built in memory (no file to name)
[[noreturn]] void geometryError(const std::string& problem) {
  throw FileFailure(ErrorKind::Geometry, "", 0, problem);
}

// position `k` of a ring as (x, y): a z (or any further coordinate) is dropped, as Shapely's
// 2D predicates ignore it
py::tuple planarPosition(const py::handle& position, std::size_t k) {
  const py::sequence coordinates = py::reinterpret_borrow<py::sequence>(position);
  if (coordinates.size() < 2)
    geometryError("the exterior ring's position " + std::to_string(k) + " has " +
                  std::to_string(coordinates.size()) + " coordinate(s), not x and y");
  return py::make_tuple(coordinates[0], coordinates[1]);
}

// A ring whose positions all have the same 2 or more numbers as one numpy array: its x and y
// columns without the closing repeat (the fast path for large rings); None otherwise
py::object planarRows(const py::handle& ring) {
  py::array rows;
  try {
    rows = py::module_::import("numpy").attr("asarray")(ring);
  } catch (const py::error_already_set&) {
    return py::none();  // ragged: the positions are read one by one
  }
  const char kind = rows.dtype().kind();
  if (rows.ndim() != 2 || rows.shape(1) < 2 || (kind != 'f' && kind != 'i' && kind != 'u'))
    return py::none();
  const py::ssize_t count = rows.shape(0);
  py::object xy = rows[py::make_tuple(py::slice(0, count, 1), py::slice(0, 2, 1))];
  const py::object first = xy[py::int_(0)];
  const py::object last = xy[py::int_(count - 1)];
  if (count > 1 && py::bool_(first.attr("__eq__")(last).attr("all")()))
    xy = xy[py::slice(0, count - 1, 1)];
  return xy;
}

// the one polygon of a GeoJSON-like geometry mapping: a Polygon, a Feature's, or the only part
// of a MultiPolygon; anything else is refused with what it is
py::object polygonCoordinates(const py::object& geo) {
  const py::object kind = geo.attr("get")("type");
  const std::string type = kind.is_none() ? std::string("None") : std::string(py::str(kind));
  if (type == "Feature") return polygonCoordinates(geo.attr("get")("geometry", py::dict()));
  const py::object coordinates = geo.attr("get")("coordinates", py::list());
  if (type == "Polygon") return coordinates;
  if (type == "MultiPolygon") {
    const py::list parts(coordinates);
    if (parts.size() == 1) return parts[0];
    geometryError("a MultiPolygon of " + std::to_string(parts.size()) +
                  " parts: a convex polygon is one part; take its parts one by one "
                  "(shapely: list(geometry.geoms))");
  }
  if (type == "FeatureCollection")
    throw py::type_error(
        "a FeatureCollection (a whole GeoSeries or GeoDataFrame?) is many shapes: pass one "
        "polygon (series.iloc[k]) or build one locator per footprint");
  throw py::type_error("a Polygon needs a polygon geometry (GeoJSON type 'Polygon'), got type " +
                       std::string(py::repr(kind)));
}

// the exterior ring of a GeoJSON-like Polygon mapping as (x, y) positions, without its closing
// repeat; holes are refused
py::object exteriorRing(const py::object& geo) {
  const py::list rings(polygonCoordinates(geo));
  if (rings.empty()) geometryError("the polygon's geometry has no exterior ring");
  if (rings.size() > 1)
    geometryError("the polygon has " + std::to_string(rings.size() - 1) +
                  " interior ring(s): a convex polygon has no holes");
  if (py::object rows = planarRows(rings[0]); !rows.is_none()) return rows;
  py::list ring;
  std::size_t k = 0;
  for (const py::handle position : py::iter(rings[0])) ring.append(planarPosition(position, k++));
  if (ring.size() > 1 && py::bool_(ring[0].equal(ring[ring.size() - 1]))) ring.attr("pop")();
  return ring;
}

}  // namespace

ConvexPolygon polygonFrom(const py::object& vertices, const char* what) {
  if (py::isinstance<ConvexPolyhedron>(vertices))
    throw py::type_error(std::string(what) +
                         " must be a polygon (a convexloc.Polygon, an object with "
                         "__geo_interface__, a GeoJSON mapping or (N, 2) vertices), got a "
                         "Polyhedron");
  py::object source = vertices;
  if (py::hasattr(vertices, "__geo_interface__"))
    source = exteriorRing(vertices.attr("__geo_interface__"));
  else if (py::isinstance<py::dict>(vertices))
    source = exteriorRing(vertices);
  const py::array points = pointArray(source, 2, what);
  const std::span<const Vec2> read = pointsOf<Vec2>(points);
  py::gil_scoped_release released;
  return ConvexPolygon(read);
}

ConvexPolygon polygonHull(const py::object& pointsArg) {
  const py::array points = pointArray(pointsArg, 2, "points");
  const std::span<const Vec2> read = pointsOf<Vec2>(points);
  for (std::size_t i = 0; i < read.size(); ++i)
    if (!std::isfinite(read[i].x) || !std::isfinite(read[i].y))
      geometryError("points[" + std::to_string(i) + "] = (" +
                    std::string(py::repr(py::float_(read[i].x))) + ", " +
                    std::string(py::repr(py::float_(read[i].y))) + ") is not finite");
  std::optional<std::vector<Vec2>> hull;
  {
    py::gil_scoped_release released;
    hull.emplace(convexHull(read));
  }
  if (hull->size() < 3) {
    const std::string count =
        std::to_string(read.size()) + (read.size() == 1 ? " point" : " points");
    if (read.size() < 3)
      geometryError("a hull needs at least 3 points not on one line, got " + count);
    geometryError("the hull of the " + count + " has no area: they all lie on one line");
  }
  py::gil_scoped_release released;
  return ConvexPolygon(*hull);
}

void requireHullPoints(std::size_t count) {
  if (count < 4)
    geometryError("a hull needs at least 4 points not in one plane, got " + std::to_string(count) +
                  (count == 1 ? " point" : " points"));
}

std::uint32_t faceVertex(const py::handle& index, std::size_t vertexCount, std::size_t face) {
  const auto number = py::reinterpret_steal<py::object>(PyNumber_Index(index.ptr()));
  if (!number) throw py::error_already_set();
  int overflow = 0;
  const long long value = PyLong_AsLongLongAndOverflow(number.ptr(), &overflow);
  if (overflow != 0 || value < 0 || static_cast<unsigned long long>(value) >= vertexCount)
    geometryError("face " + std::to_string(face) + " refers to vertex " +
                  std::string(py::str(number)) + ", but " +
                  (vertexCount == 0 ? std::string("there are no vertices")
                                    : "the vertices are 0 to " + std::to_string(vertexCount - 1)));
  return static_cast<std::uint32_t>(value);
}

}  // namespace convexloc::python
