// convexloc Python module — the coordinate arrays of columns.hpp, checked and broadcast.
#include "columns.hpp"

namespace convexloc::python {

std::vector<py::array> broadcastColumns(const py::object* columns, std::size_t count) {
  static constexpr const char* kNames[] = {"x", "y", "z"};
  const py::module_ numpy = py::module_::import("numpy");
  py::list arrays;
  for (std::size_t k = 0; k < count; ++k) {
    py::array a = numberArray(columns[k], kNames[k]);
    if (!a.dtype().equal(py::dtype::of<double>()) || !a.attr("flags").attr("aligned").cast<bool>())
      a = numpy.attr("require")(a, numpy.attr("float64"), py::make_tuple("A"));
    arrays.append(a);
  }
  py::list shapes;
  for (const py::handle a : arrays) shapes.append(a.attr("shape"));
  py::object broadcast;
  try {
    broadcast = numpy.attr("broadcast_arrays")(*arrays);
  } catch (py::error_already_set& e) {
    if (!e.matches(PyExc_ValueError)) throw;
    std::string text;
    for (std::size_t k = 0; k < count; ++k)
      text += std::string(k ? ", " : "") + kNames[k] + " " + std::string(py::str(shapes[k]));
    throw py::value_error("the coordinate arrays do not broadcast together: " + text);
  }
  std::vector<py::array> out;
  for (const py::handle a : broadcast) out.push_back(py::reinterpret_borrow<py::array>(a));
  return out;
}

std::size_t rowLength(const py::array& broadcast) {
  for (py::ssize_t k = broadcast.ndim(); k-- > 0;)
    if (broadcast.shape(k) != 1) return static_cast<std::size_t>(broadcast.shape(k));
  return 1;
}

Column columnOf(const py::array& array, std::size_t length, py::object& keep) {
  // the last axis longer than 1 is the row; the axes outside it, those longer than 1, must
  // step by one stride: each one's stride the next inner one's times that one's length
  py::ssize_t inner = 0;
  py::ssize_t outer = 0;
  py::ssize_t expected = 0;
  bool found = false;
  bool first = true;
  bool uniform = true;
  for (py::ssize_t k = array.ndim(); k-- > 0;) {
    if (array.shape(k) == 1) continue;
    if (!found) {
      inner = array.strides(k);
      found = true;
      continue;
    }
    if (first) outer = array.strides(k);
    uniform = uniform && (first || array.strides(k) == expected);
    expected = array.strides(k) * array.shape(k);
    first = false;
  }
  if (!uniform) {
    keep = py::module_::import("numpy").attr("ascontiguousarray")(array);
    const auto width = static_cast<py::ssize_t>(sizeof(double));
    return {static_cast<const char*>(py::array(keep).data()),
            width * static_cast<py::ssize_t>(length), width};
  }
  keep = array;
  return {static_cast<const char*>(array.data()), outer, inner};
}

}  // namespace convexloc::python
