// convexloc Python module — one Python class per locator, written once for 2D and 3D.
//
// Every class has the same face: built from a shape (and a resolution where the method has
// one) with the GIL released; locate(points, threads=) and locate_xy / locate_xyz through
// arrays.hpp's batch; trace(point), stats(), cells() as plain values (bindings.hpp). A
// locator holds its own copy of the shape's geometry, so the shape may go away after.
#pragma once

#include <pybind11/pybind11.h>

#include <array>
#include <cstdint>
#include <limits>
#include <list>
#include <string>
#include <type_traits>

#include "arrays.hpp"
#include "bindings.hpp"
#include "convexloc/methods.hpp"

namespace convexloc::python {

// what a dimension's locators are built from and locate
template <class Method>
struct Dimension {
  static constexpr bool kPlanar = std::is_same_v<Method, Method2D>;
  using Shape = std::conditional_t<kPlanar, ConvexPolygon, ConvexPolyhedron>;
  using Point = std::conditional_t<kPlanar, Vec2, Vec3>;
  static constexpr const char* kShape = kPlanar ? "polygon" : "polyhedron";
  static constexpr const char* kColumns = kPlanar ? "locate_xy" : "locate_xyz";
};

// text that lives as long as the module (pybind11 keeps some docstrings by pointer)
inline const char* keep(std::string text) {
  static std::list<std::string> kept;
  return kept.emplace_back(std::move(text)).c_str();
}

// the resolution argument, checked
inline std::uint32_t resolutionOf(long resolution) {
  if (resolution < 0 || resolution > std::numeric_limits<std::uint32_t>::max())
    throw py::value_error("resolution must be >= 0 (0 chooses from the shape), got " +
                          std::to_string(resolution));
  return static_cast<std::uint32_t>(resolution);
}

// the constructor: from the shape, and a resolution where the method has one
template <class Locator, class Method>
void defineInit(py::class_<Locator>& c, Method method) {
  using Shape = typename Dimension<Method>::Shape;
  const auto& info = methodInfo(method);
  const py::arg shape(Dimension<Method>::kShape);
  if constexpr (std::is_constructible_v<Locator, const Shape&, std::uint32_t>) {
    const char* doc = keep("Builds the locator. resolution: " + std::string(info.resolution) +
                           " (0 chooses from the shape).");
    c.def(py::init([](const Shape& s, long resolution) {
            const std::uint32_t r = resolutionOf(resolution);
            py::gil_scoped_release released;
            return Locator(s, r);
          }),
          shape, py::arg("resolution") = 0, doc);
  } else {
    c.def(py::init([](const Shape& s) {
            py::gil_scoped_release released;
            return Locator(s);
          }),
          shape, "Builds the locator.");
  }
}

// locate, and the same from separate coordinate arrays
template <class Locator, class Method>
void defineLocate(py::class_<Locator>& c) {
  using Point = typename Dimension<Method>::Point;
  constexpr int dims = kDims<Point>;
  c.def(
      "locate",
      [](const Locator& l, const py::object& points, long threads) {
        return locateRows<Locator, Point>(l, points, threads);
      },
      py::arg("points"), py::kw_only(), py::arg("threads") = 0,
      keep("Locates (M, " + std::to_string(dims) +
           ") points: an (M,) int8 array of INSIDE, BOUNDARY or OUTSIDE, exact for the doubles "
           "given (NaN and infinite coordinates are OUTSIDE). Runs without the GIL, on up to "
           "`threads` threads for large batches (0: one per core)."));
  const char* columns = Dimension<Method>::kColumns;
  const char* doc = keep(
      "Locates the points whose coordinates are the elements of arrays of "
      "one shape; the int8 answer has that shape. As locate() otherwise.");
  if constexpr (dims == 2)
    c.def(
        columns,
        [](const Locator& l, const py::object& x, const py::object& y, long threads) {
          return locateColumns<Locator, Point>(l, {x, y}, threads);
        },
        py::arg("x"), py::arg("y"), py::kw_only(), py::arg("threads") = 0, doc);
  else
    c.def(
        columns,
        [](const Locator& l, const py::object& x, const py::object& y, const py::object& z,
           long threads) {
          return locateColumns<Locator, Point>(l, {x, y, z}, threads);
        },
        py::arg("x"), py::arg("y"), py::arg("z"), py::kw_only(), py::arg("threads") = 0, doc);
}

// trace, stats, cells and the method's name
template <class Locator, class Method>
void defineIntrospection(py::class_<Locator>& c, Method method) {
  using Point = typename Dimension<Method>::Point;
  c.def(
      "trace",
      [](const Locator& l, const py::object& point, bool radii) {
        const Point p = onePoint<Point>(point);
        if constexpr (requires { l.trace(p, TraceOptions{}); })
          return traceToPython(l.trace(p, TraceOptions{.radii = radii}));
        else
          return traceToPython(l.trace(p));
      },
      py::arg("point"), py::kw_only(), py::arg("radii") = true,
      "What locating one point does: a dict of the cell chosen, the tests made with their "
      "signs, and the result (as a code and as a name). radii=False runs the polar and "
      "cube-map queries without convexloc's radius filter, as the paper describes them (the "
      "cell's edges or faces decide); the answer is the same.");
  c.def(
      "stats", [](const Locator& l) { return statsToPython(l.stats()); },
      "The size and shape of the subdivision: a dict (cells, entries, max_per_cell, bytes, "
      "build_seconds, histogram, ...).");
  c.def(
      "cells", [](const Locator& l) { return cellsToPython(l.cells()); },
      "The subdivision as a list of dicts, one per cell: its geometry to draw and the indices "
      "it holds. Empty for a method without cells.");
  const std::string name(methodInfo(method).name);
  c.def_property_readonly_static(
      "method", [name](const py::object&) { return name; }, "the method's name");
}

// the read-only property `centre` of a locator that has one
template <class Locator>
void defineCentre(py::class_<Locator>& c, const char* doc) {
  c.def_property_readonly(
      "centre", [](const Locator& l) { return centreToPython(l.centre()); }, doc);
}

// The Python class for `Locator`, which implements `method`.
template <class Locator, class Method>
py::class_<Locator> bindLocator(py::module_& m, const char* name, Method method) {
  const auto& info = methodInfo(method);
  std::string doc = std::string(info.name) + ", " + std::string(info.cost);
  if (!info.costNote.empty()) doc += " " + std::string(info.costNote);
  doc += ": " + std::string(info.summary) + ".";
  py::class_<Locator> c(m, name, keep(doc));
  defineInit(c, method);
  defineLocate<Locator, Method>(c);
  defineIntrospection(c, method);
  c.def("__repr__", [name = std::string(name)](const Locator& l) {
    return "<convexloc." + name + " over " + std::to_string(l.stats().cells) + " cells>";
  });
  return c;
}

}  // namespace convexloc::python
