// convexloc Python module — what each binding file adds to the module convexloc._core.
#pragma once

#include <pybind11/pybind11.h>

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
