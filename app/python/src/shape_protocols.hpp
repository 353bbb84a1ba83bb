// convexloc Python module — what lets a shape travel and compare: pickling (so copy and
// deepcopy), equality and hashing, read-only views of its coordinates, and its history.
//
// A pickled shape is its exact doubles (and a polyhedron's triangles) plus its history (what
// it remembers of its input: source indices, dropped count, orientation); loading validates
// the doubles again, which gives back the same shape, and restores the history into the
// instance's __dict__, where the history properties look first.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <span>
#include <type_traits>

#include "bindings.hpp"
#include "convexloc/polygon.hpp"
#include "convexloc/polyhedron.hpp"

namespace convexloc::python {

namespace py = pybind11;

// __getstate__ / __setstate__, __eq__ and __hash__ of Polygon
void defineShapeProtocols(py::class_<ConvexPolygon>& c);
// the same for Polyhedron
void defineShapeProtocols(py::class_<ConvexPolyhedron>& c);

// __reduce_ex__ as protocol 2 reduces, for every protocol: pickle's protocols 0 and 1 would
// otherwise try to make the object through its base class, which pybind11 refuses (abort)
template <class T>
void pickleAnyProtocol(py::class_<T>& c) {
  c.def(
      "__reduce_ex__",
      [](const py::object& self, const py::object&) {
        return py::module_::import("builtins").attr("object").attr("__reduce_ex__")(self, 2);
      },
      py::arg("protocol"),
      signedDoc("__reduce_ex__", "(self, protocol, /)",
                "As protocol 2 (and above) reduce: the state, then __setstate__."));
}

// a read-only numpy view of `count` rows of `dims` doubles at `data`, kept alive by `owner`
py::array coordinateView(const double* data, std::size_t count, int dims, py::handle owner);

// item `slot` of the history a load restored into `self`'s __dict__, or None
py::object restoredHistory(py::handle self, std::size_t slot);

// The read-only property `name`: item `slot` of a restored history when there is one,
// otherwise what `get` (Shape -> Python value) gives.
template <class Shape, class Get>
void historyProperty(py::class_<Shape>& c, const char* name, std::size_t slot, Get get,
                     const char* doc) {
  c.def_property_readonly(
      name,
      [slot, get](const py::object& self) -> py::object {
        py::object restored = restoredHistory(self, slot);
        if (!restored.is_none()) return restored;
        auto value = get(self.cast<const Shape&>());
        if constexpr (std::is_base_of_v<py::object, decltype(value)>)
          return value;
        else
          return py::cast(value);
      },
      doc);
}

}  // namespace convexloc::python
