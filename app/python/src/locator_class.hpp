// convexloc Python module — one Python class per locator, written once for 2D and 3D.
//
// Every class has the same face: built from a shape (and a resolution where the method has
// one) with the GIL released; locate(points, workers=) and locate_xy / locate_xyz through
// arrays.hpp's batch; trace(point), stats(), cells() as plain values (bindings.hpp). A
// locator holds its own copy of the shape's geometry and a reference to the shape object
// (what pickling carries).
#pragma once

#include <pybind11/pybind11.h>

#include <array>
#include <cstdint>
#include <limits>
#include <list>
#include <optional>
#include <string>
#include <type_traits>

#include "arrays.hpp"
#include "bindings.hpp"
#include "columns.hpp"
#include "convexloc/methods.hpp"
#include "shape_protocols.hpp"

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

// A locator as the Python class holds it: with the shape it was built from (the Python
// object, shared, not copied) and the resolution asked for, which is what pickling carries:
// a locator is rebuilt on load, from the shape's exact doubles and that resolution (a cube
// map's pickle carries its tables too, and loads them instead).
template <class Locator>
struct Bound {
  Locator locator;
  py::object shape;
  std::uint32_t resolution = 0;
};

// the locator of `shape`, built without the GIL, with `resolution` where the method has one
// `shape` as the Shape of the dimension: a polygon from anything Polygon() takes (a Shapely
// polygon, a GeoJSON mapping, vertices), a polyhedron only as itself
template <class Method>
py::object shapeArgument(const py::object& shape) {
  using Shape = typename Dimension<Method>::Shape;
  if (py::isinstance<Shape>(shape)) return shape;
  if constexpr (Dimension<Method>::kPlanar) {
    return py::cast(polygonFrom(shape, "polygon"));
  } else {
    throw py::type_error("polyhedron must be a convexloc.Polyhedron, got " +
                         std::string(py::str(shape.get_type().attr("__name__"))));
  }
}

template <class Locator, class Method>
Bound<Locator> buildBound(const py::object& shapeArg, std::uint32_t resolution) {
  using Shape = typename Dimension<Method>::Shape;
  const py::object shape = shapeArgument<Method>(shapeArg);
  const Shape& s = shape.cast<const Shape&>();
  std::optional<Locator> built;
  {
    py::gil_scoped_release released;  // the build; `shape` is copied (a reference taken) after
    if constexpr (std::is_constructible_v<Locator, const Shape&, std::uint32_t>)
      built.emplace(s, resolution);
    else
      built.emplace(s);
  }
  return Bound<Locator>{std::move(*built), shape, resolution};
}

// what the constructor's docstring says of the shape it takes
template <class Method>
constexpr const char* shapeNote() {
  return Dimension<Method>::kPlanar ? " (the polygon: anything Polygon() takes, a Shapely "
                                      "polygon or a GeoJSON mapping among them)"
                                    : "";
}

// pickling a CubemapLocator: its tables travel, loaded without building (cubemap_tables.cpp)
void defineCubemapPickle(py::class_<Bound<CubemapLocator>>& c);

// the constructor (from the shape, and a resolution where the method has one) and pickling
template <class Locator, class Method>
void defineInit(py::class_<Bound<Locator>>& c, Method method) {
  using Shape = typename Dimension<Method>::Shape;
  const auto& info = methodInfo(method);
  const py::arg shape(Dimension<Method>::kShape);
  if constexpr (std::is_constructible_v<Locator, const Shape&, std::uint32_t>) {
    const std::string params =
        std::string("(self, ") + Dimension<Method>::kShape + ", resolution=0)";
    const char* doc = signedDoc("__init__", keep(params),
                                "Builds the locator" + std::string(shapeNote<Method>()) +
                                    ". resolution: " + std::string(info.resolution) +
                                    " (0 chooses from the shape).");
    c.def(py::init([](const py::object& s, const py::object& resolution) {
            return buildBound<Locator, Method>(s, resolutionOf(resolution));
          }),
          shape, py::arg("resolution") = 0, doc);
  } else {
    const std::string params = std::string("(self, ") + Dimension<Method>::kShape + ")";
    c.def(py::init([](const py::object& s) { return buildBound<Locator, Method>(s, 0); }), shape,
          signedDoc("__init__", keep(params),
                    "Builds the locator" + std::string(shapeNote<Method>()) + "."));
  }
  if constexpr (std::is_same_v<Locator, CubemapLocator>)
    defineCubemapPickle(c);
  else
    c.def(py::pickle(
        [](const Bound<Locator>& b) { return py::make_tuple(1, b.shape, b.resolution); },
        [](const py::tuple& state) {
          if (state.size() != 3 || state[0].cast<int>() != 1)
            throw py::value_error(
                "cannot unpickle this locator: it was pickled by another version of convexloc");
          return buildBound<Locator, Method>(state[1], state[2].cast<std::uint32_t>());
        }));
  pickleAnyProtocol(c);
  c.def_property_readonly(
      "shape", [](const Bound<Locator>& b) { return b.shape; }, "the shape it was built from");
}

// the docstring of locate and of locate_xy / locate_xyz
inline const char* locateDoc(int dims, bool columns) {
  const char* name = columns ? (dims == 2 ? "locate_xy" : "locate_xyz") : "locate";
  const char* params = columns ? (dims == 2 ? "(self, x, y, *, workers=1, threads=None)"
                                            : "(self, x, y, z, *, workers=1, threads=None)")
                               : "(self, points, *, workers=1, threads=None)";
  const std::string what =
      columns ? std::string("Locates the points whose coordinates are the elements of x, y") +
                    (dims == 3 ? ", z" : "") +
                    ", broadcast together as numpy's ufuncs do; the int8 answer has the "
                    "broadcast shape."
              : "Locates (M, " + std::to_string(dims) +
                    ") points: an (M,) int8 array of INSIDE, BOUNDARY or OUTSIDE.";
  return signedDoc(
      name, params,
      what +
          " Exact for the doubles given (NaN and infinite coordinates are OUTSIDE). Runs "
          "without the GIL, on `workers` threads for large batches (scipy's workers=: 1 by "
          "default, -1 one per core; threads= is its deprecated old name, 0 meaning every "
          "core).");
}

// locate, and the same from separate coordinate arrays
template <class Locator, class Method>
void defineLocate(py::class_<Bound<Locator>>& c) {
  using Point = typename Dimension<Method>::Point;
  constexpr int dims = kDims<Point>;
  const auto workers = py::arg("workers") = py::none();
  const auto threads = py::arg("threads") = py::none();
  c.def(
      "locate",
      [](const Bound<Locator>& b, const py::object& points, const py::object& w,
         const py::object& t) {
        return locateRows<Locator, Point>(b.locator, points, workerCount(w, t));
      },
      py::arg("points"), py::kw_only(), workers, threads, locateDoc(dims, false));
  const char* columns = Dimension<Method>::kColumns;
  if constexpr (dims == 2)
    c.def(
        columns,
        [](const Bound<Locator>& b, const py::object& x, const py::object& y, const py::object& w,
           const py::object& t) {
          return locateColumns<Locator, Point>(b.locator, {x, y}, workerCount(w, t));
        },
        py::arg("x"), py::arg("y"), py::kw_only(), workers, threads, locateDoc(dims, true));
  else
    c.def(
        columns,
        [](const Bound<Locator>& b, const py::object& x, const py::object& y, const py::object& z,
           const py::object& w, const py::object& t) {
          return locateColumns<Locator, Point>(b.locator, {x, y, z}, workerCount(w, t));
        },
        py::arg("x"), py::arg("y"), py::arg("z"), py::kw_only(), workers, threads,
        locateDoc(dims, true));
}

// trace, stats, cells and the method's name
template <class Locator, class Method>
void defineIntrospection(py::class_<Bound<Locator>>& c, Method method) {
  using Point = typename Dimension<Method>::Point;
  c.def(
      "trace",
      [](const Bound<Locator>& b, const py::object& point, bool radii) {
        const Locator& l = b.locator;
        const Point p = onePoint<Point>(point);
        if constexpr (requires { l.trace(p, TraceOptions{}); })
          return traceToPython(l.trace(p, TraceOptions{.radii = radii}));
        else
          return traceToPython(l.trace(p));
      },
      py::arg("point"), py::kw_only(), py::arg("radii") = true,
      signedDoc(
          "trace", "(self, point, *, radii=True)",
          "What locating one point does: a dict of the cell chosen, the tests made with their "
          "signs, and the result (as a code and as a name). radii=False runs the polar and "
          "cube-map queries without convexloc's radius filter, as the paper describes them (the "
          "cell's edges or faces decide); the answer is the same."));
  c.def(
      "stats", [](const Bound<Locator>& b) { return statsToPython(b.locator.stats()); },
      signedDoc("stats", "(self)",
                "The size and shape of the subdivision: a dict (cells, entries, max_per_cell, "
                "bytes, build_seconds, histogram, ...)."));
  c.def(
      "cells", [](const Bound<Locator>& b) { return cellsToPython(b.locator.cells()); },
      signedDoc("cells", "(self)",
                "The subdivision as a list of dicts, one per cell: its geometry to draw and the "
                "indices it holds. Empty for a method without cells."));
  const std::string name(methodInfo(method).name);
  c.def_property_readonly_static(
      "method", [name](const py::object&) { return name; }, "the method's name");
}

// the read-only property `centre` of a locator that has one
template <class Locator>
void defineCentre(py::class_<Bound<Locator>>& c, const char* doc) {
  c.def_property_readonly(
      "centre", [](const Bound<Locator>& b) { return centreToPython(b.locator.centre()); }, doc);
}

// the read-only property `name`: what the locator's `get` returns
template <class Locator, class Value>
void locatorProperty(py::class_<Bound<Locator>>& c, const char* name,
                     Value (Locator::*get)() const noexcept, const char* doc) {
  c.def_property_readonly(
      name, [get](const Bound<Locator>& b) { return (b.locator.*get)(); }, doc);
}

// The Python class for `Locator`, which implements `method`.
template <class Locator, class Method>
py::class_<Bound<Locator>> bindLocator(py::module_& m, const char* name, Method method) {
  const auto& info = methodInfo(method);
  std::string doc = std::string(info.name) + ", " + std::string(info.cost);
  if (!info.costNote.empty()) doc += " " + std::string(info.costNote);
  doc += ": " + std::string(info.summary) + ".";
  doc += std::is_same_v<Locator, CubemapLocator>
             ? " Pickle, copy and deepcopy carry the shape, the resolution and the tables, "
               "which load without a build (checked; tables of another version are rebuilt)."
             : " Pickle, copy and deepcopy carry the shape and the resolution; the tables are "
               "rebuilt on load.";
  py::class_<Bound<Locator>> c(m, name, keep(doc));
  defineInit(c, method);
  defineLocate<Locator, Method>(c);
  defineIntrospection(c, method);
  c.def(
      "__repr__",
      [name = std::string(name)](const Bound<Locator>& b) {
        return "<convexloc." + name + " over " + std::to_string(b.locator.stats().cells) +
               " cells>";
      },
      signedDoc("__repr__", "(self, /)", "Return repr(self)."));
  return c;
}

}  // namespace convexloc::python
