// convexloc Python module — the array conversion rules of arrays.hpp.
//
// numpy itself does the converting (asarray, then require float64, C order, aligned), so
// what it reads, how it casts and when it copies are numpy's documented rules; this file
// only decides what it accepts, with errors that name the argument and what was wrong.
#include "arrays.hpp"

#include <string>

namespace convexloc::python {

namespace {

// numpy, imported once per call (a lookup in sys.modules after the first)
py::module_ numpy() {
  return py::module_::import("numpy");
}

// TypeError unless the array holds integers or floating-point numbers
void requireNumbers(const py::array& array, const char* what) {
  const char kind = array.dtype().kind();
  if (kind == 'f' || kind == 'i' || kind == 'u') return;
  const std::string dtype = py::str(array.dtype());
  std::string why = "an array of " + dtype;
  if (kind == 'b') why = "a boolean array";
  if (kind == 'c') why = "complex numbers (" + dtype + ")";
  if (kind == 'O') why = "Python objects (dtype object)";
  if (kind == 'U' || kind == 'S') why = "strings (" + dtype + ")";
  throw py::type_error(std::string(what) + " must be numbers (integer or float), got " + why);
}

}  // namespace

std::string shapeText(const std::vector<py::ssize_t>& shape) {
  std::string text = "(";
  for (std::size_t k = 0; k < shape.size(); ++k) text += (k ? ", " : "") + std::to_string(shape[k]);
  return text + (shape.size() == 1 ? ",)" : ")");
}

py::array floatArray(const py::object& values, const char* what) {
  py::array any;
  try {
    any = numpy().attr("asarray")(values);
  } catch (py::error_already_set& e) {
    if (!e.matches(PyExc_ValueError)) throw;
    throw py::value_error(std::string(what) + ": " + py::str(e.value()).cast<std::string>());
  }
  requireNumbers(any, what);
  return numpy().attr("require")(any, numpy().attr("float64"), py::make_tuple("C", "A"));
}

py::array pointArray(const py::object& points, int dims, const char* what) {
  py::array rows = floatArray(points, what);
  const std::vector<py::ssize_t> shape(rows.shape(), rows.shape() + rows.ndim());
  if (rows.ndim() == 1 && shape[0] == 0) return rows.reshape({py::ssize_t{0}, py::ssize_t{dims}});
  if (rows.ndim() == 2 && shape[1] == dims) return rows;
  const std::string wanted = "(M, " + std::to_string(dims) + ")";
  std::string hint;
  if (rows.ndim() == 0) hint = " (a single number, not an array of points)";
  if (rows.ndim() == 1 && shape[0] == dims) hint = "; for one point pass [[...]], a batch of one";
  throw py::value_error(std::string(what) + " must be an " + wanted + " array, got shape " +
                        shapeText(shape) + hint);
}

py::array_t<std::int8_t> codeArray(const std::vector<py::ssize_t>& shape) {
  return py::array_t<std::int8_t>(shape);
}

py::array_t<std::int64_t> indexArray(std::span<const std::uint32_t> indices) {
  py::array_t<std::int64_t> out(static_cast<py::ssize_t>(indices.size()));
  std::int64_t* to = out.mutable_data();
  for (std::size_t i = 0; i < indices.size(); ++i) to[i] = indices[i];
  return out;
}

unsigned threadCount(long threads) {
  if (threads < 0) throw py::value_error("threads must be >= 0 (0: one per core)");
  constexpr long kMost = 4096;
  return static_cast<unsigned>(threads < kMost ? threads : kMost);
}

}  // namespace convexloc::python
