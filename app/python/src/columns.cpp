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

Column columnOf(const py::array& array, py::object& keep) {
  // one stride serves when, going out from the innermost axis longer than 1, each such axis's
  // stride is the previous one's times that one's length (every stride 0 counts: a scalar)
  py::ssize_t stride = 0;
  py::ssize_t expected = 0;
  bool inner = true;
  bool uniform = true;
  for (py::ssize_t k = array.ndim(); k-- > 0;) {
    if (array.shape(k) == 1) continue;
    if (inner) stride = array.strides(k);
    uniform = uniform && (inner || array.strides(k) == expected);
    expected = array.strides(k) * array.shape(k);
    inner = false;
  }
  if (!uniform) {
    keep = py::module_::import("numpy").attr("ascontiguousarray")(array);
    return {static_cast<const char*>(py::array(keep).data()), py::ssize_t{sizeof(double)}};
  }
  keep = array;
  return {static_cast<const char*>(array.data()), stride};
}

}  // namespace convexloc::python
