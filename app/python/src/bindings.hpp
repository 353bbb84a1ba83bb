// convexloc Python module — what each binding file adds to the module convexloc._core.
#pragma once

#include <pybind11/pybind11.h>

#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "convexloc/locate2d.hpp"
#include "convexloc/locate3d.hpp"

namespace convexloc::python {

namespace py = pybind11;

// === Registration, one function per file

// Polygon, Polyhedron, read_polygon, read_polyhedron (shapes.cpp)
void bindShapes(py::module_& m);
// the five 2D locator classes (locators2d.cpp)
void bindLocators2D(py::module_& m);
// the three 3D locator classes (locators3d.cpp)
void bindLocators3D(py::module_& m);
// contains, hull_contains (conveniences.cpp)
void bindConveniences(py::module_& m);

// === Shapes from Python values (shape_input.cpp)

// a polygon from (N, 2) vertices or from an object with a Polygon __geo_interface__ (or such
// a GeoJSON mapping, a Feature, a one-part MultiPolygon): its exterior ring, z dropped;
// GeometryError for holes and for several parts; `what` names the argument in errors
ConvexPolygon polygonFrom(const py::object& vertices, const char* what = "vertices");
// the polygon that is the exact convex hull of (M, 2) points (core's convexHull)
ConvexPolygon polygonHull(const py::object& points);
// GeometryError naming the count when fewer than 4 points cannot make a 3D hull
void requireHullPoints(std::size_t count);
// vertex index `index` of face `face`, checked against the vertex count (GeometryError)
std::uint32_t faceVertex(const py::handle& index, std::size_t vertexCount, std::size_t face);

// === Text signatures: inspect.signature reads "name(params)\n--\n\n" at a docstring's start

// the docstring `doc` led by the signature of `name` with `params` ("(self, x, *, k=0)")
const char* signedDoc(const char* name, const char* params, const std::string& doc);

// === Introspection as plain Python values: dicts, lists, tuples and numpy arrays

// what one 2D query did (introspect.cpp)
py::dict traceToPython(const Trace2D& trace);
// the size and shape of a 2D subdivision
py::dict statsToPython(const Stats2D& stats);
// a 2D subdivision, one dict per cell
py::list cellsToPython(const std::vector<Cell2D>& cells);

// what one 3D query did
py::dict traceToPython(const Trace3D& trace);
// the size and shape of a 3D subdivision
py::dict statsToPython(const Stats3D& stats);
// a cube-map subdivision, one dict per cell
py::list cellsToPython(const std::vector<Cell3D>& cells);

// (x, y) and (x, y, z) as tuples
py::tuple toPython(Vec2 v);
py::tuple toPython(Vec3 v);

// a centre as (x, y[, z]), or None: accepts a point or an optional one
template <class Centre>
py::object centreToPython(const Centre& centre) {
  if constexpr (std::is_same_v<Centre, Vec2> || std::is_same_v<Centre, Vec3>)
    return toPython(centre);
  else
    return centre ? py::object(toPython(*centre)) : py::object(py::none());
}

}  // namespace convexloc::python
