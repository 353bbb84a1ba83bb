// convexloc Python module — the array conversion rules of arrays.hpp.
//
// numpy itself does the converting (asarray, then require float64, C order, aligned), so
// what it reads, how it casts and when it copies are numpy's documented rules; this file
// only decides what it accepts, with errors that name the argument and what was wrong.
#include "arrays.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <thread>
#include <type_traits>

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

// "[3, 1]": element `flat` (C order) of an array of `shape`, as numpy indexes it
std::string elementText(const std::vector<py::ssize_t>& shape, py::ssize_t flat) {
  std::vector<py::ssize_t> index(shape.size());
  for (std::size_t k = shape.size(); k-- > 0;) {
    index[k] = flat % shape[k];
    flat /= shape[k];
  }
  std::string text = "[";
  for (std::size_t k = 0; k < index.size(); ++k) {
    if (k > 0) text += ", ";
    text += std::to_string(index[k]);
  }
  return text + "]";
}

// whether the integer v is exactly a double (every |v| <= 2^53 is; beyond, only some)
template <class Int>
bool exactInteger(Int v) {
  const double d = static_cast<double>(v);
  constexpr double kLimit = 2.0 * static_cast<double>(std::numeric_limits<Int>::max() / 2 + 1);
  return d < kLimit && static_cast<Int>(d) == v;  // d < 2^63 (2^64) makes the cast defined
}

// whether the long double v is exactly a double (NaN counts: it stays NaN)
bool exactLong(long double v) {
  return std::isnan(v) || static_cast<long double>(static_cast<double>(v)) == v;
}

// The flat index (C order) of the first element of `array` that T does not hold exactly as a
// double, or -1. `array` holds T, C-contiguous.
template <class T>
py::ssize_t firstInexact(const py::array& array) {
  const T* values = static_cast<const T*>(array.data());
  const py::ssize_t count = array.size();
  for (py::ssize_t i = 0; i < count; ++i) {
    if constexpr (std::is_integral_v<T>) {
      if (!exactInteger(values[i])) return i;
    } else if (!exactLong(values[i])) {
      return i;
    }
  }
  return -1;
}

// ValueError unless every element converts to a double without rounding: int64 and uint64
// beyond 2^53 and long double may not (narrower types always do)
void requireLossless(const py::array& any, const char* what) {
  const py::dtype dtype = any.dtype();
  const char kind = dtype.kind();
  const bool wide = (kind == 'i' || kind == 'u') ? dtype.itemsize() > 4 : dtype.itemsize() > 8;
  if (!wide) return;
  const py::array dense = numpy().attr("ascontiguousarray")(any, dtype.attr("newbyteorder")("="));
  py::ssize_t bad = -1;
  if (kind == 'i') bad = firstInexact<std::int64_t>(dense);
  if (kind == 'u') bad = firstInexact<std::uint64_t>(dense);
  if (kind == 'f' && dense.itemsize() == sizeof(long double))
    bad = firstInexact<long double>(dense);
  if (kind == 'f' && dense.itemsize() != sizeof(long double))
    throw py::type_error(std::string(what) + ": " + std::string(py::str(py::object(dtype))) +
                         " is not supported (float64, long double or narrower)");
  if (bad < 0) return;
  const std::vector<py::ssize_t> shape(any.shape(), any.shape() + any.ndim());
  const py::object value = dense.attr("flat")[py::int_(bad)];
  const py::object nearest =
      kind == 'f' ? py::object(py::float_(value)) : py::object(py::int_(py::float_(value)));
  const std::string exact = kind == 'f'
                                ? std::string(py::str(numpy().attr("format_float_positional")(
                                      value, py::arg("unique") = true)))
                                : std::string(py::str(value));
  throw py::value_error(std::string(what) + elementText(shape, bad) + " = " + exact +
                        " is not exactly a float64 (the nearest is " +
                        std::string(py::repr(nearest)) +
                        "); convexloc does not round its input: pass float64 values");
}

// a Python float, or an int that a double holds exactly (ValueError naming `where` otherwise)
double exactDouble(const py::handle& value, const std::string& where) {
  if (PyFloat_Check(value.ptr())) return PyFloat_AsDouble(value.ptr());
  const auto number = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
  if (!number) throw py::error_already_set();
  const double d = PyLong_AsDouble(number.ptr());
  if (d == -1.0 && PyErr_Occurred()) {
    PyErr_Clear();
    throw py::value_error(where + " = " + std::string(py::str(number)) +
                          " is beyond the largest float64; convexloc does not round its input");
  }
  if (py::int_(py::float_(d)).equal(number)) return d;
  throw py::value_error(where + " = " + std::string(py::str(number)) +
                        " is not exactly a float64 (the nearest is " +
                        std::string(py::repr(py::float_(d))) +
                        "); convexloc does not round its input: pass float64 values");
}

// TypeError for a masked array with any element masked (numpy.asarray would drop the mask)
void refuseMasked(const py::object& values, const char* what) {
  const py::module_ ma = numpy().attr("ma");
  if (!py::isinstance(values, ma.attr("MaskedArray"))) return;
  if (!py::bool_(ma.attr("getmaskarray")(values).attr("any")())) return;
  throw py::type_error(std::string(what) +
                       ": a masked array with masked elements (their values are not points); "
                       "keep the unmasked points or pass .filled(numpy.nan) (NaN is OUTSIDE)");
}

// "<NA>" for pandas' NA and None: a missing value, not a number
bool missingValue(const py::handle& value) {
  return value.is_none() || std::string(py::str(value.get_type().attr("__name__"))) == "NAType";
}

// An object array of Python numbers (what numpy makes of a list holding an int beyond int64,
// or of a pandas nullable column) as float64, each value exactly a double; a missing value,
// a non-number or an int no double holds is an error naming the element.
py::array objectNumbers(const py::array& objects, const char* what) {
  const std::vector<py::ssize_t> shape(objects.shape(), objects.shape() + objects.ndim());
  py::array_t<double> out(shape);
  double* to = out.mutable_data();
  const py::object flat = objects.attr("flat");
  py::ssize_t k = 0;
  for (const py::handle value : py::iter(flat)) {
    const std::string where = std::string(what) + elementText(shape, k);
    if (missingValue(value))
      throw py::type_error(where + " is a missing value (" + std::string(py::str(value)) +
                           "): every point needs numbers; drop those rows (.dropna()) or pass "
                           ".to_numpy(dtype=float, na_value=numpy.nan) (NaN is OUTSIDE)");
    if (PyBool_Check(value.ptr()) || !(PyFloat_Check(value.ptr()) || PyIndex_Check(value.ptr())))
      throw py::type_error(std::string(what) + " must be numbers (integer or float), got " + where +
                           " = " + std::string(py::repr(value)) + " (dtype object)");
    to[k++] = exactDouble(value, where);
  }
  return out;
}

}  // namespace

std::string shapeText(const std::vector<py::ssize_t>& shape) {
  std::string text = "(";
  for (std::size_t k = 0; k < shape.size(); ++k) text += (k ? ", " : "") + std::to_string(shape[k]);
  return text + (shape.size() == 1 ? ",)" : ")");
}

py::array numberArray(const py::object& values, const char* what) {
  refuseMasked(values, what);
  py::array any;
  try {
    any = numpy().attr("asarray")(values);
  } catch (py::error_already_set& e) {
    if (!e.matches(PyExc_ValueError)) throw;
    throw py::value_error(std::string(what) + ": " + py::str(e.value()).cast<std::string>());
  }
  if (any.dtype().kind() == 'O' && any.ndim() > 0) any = objectNumbers(any, what);
  requireNumbers(any, what);
  requireLossless(any, what);
  return any;
}

py::array floatArray(const py::object& values, const char* what) {
  const py::array any = numberArray(values, what);
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

long long integerArgument(const py::object& value, const char* name, long long lo, long long hi,
                          const char* meaning) {
  if (!PyIndex_Check(value.ptr()) || PyBool_Check(value.ptr()))
    throw py::type_error(std::string(name) + " must be an integer, got " +
                         std::string(py::repr(value)));
  const auto number = py::reinterpret_steal<py::object>(PyNumber_Index(value.ptr()));
  if (!number) throw py::error_already_set();
  int overflow = 0;
  const long long v = PyLong_AsLongLongAndOverflow(number.ptr(), &overflow);
  if (overflow != 0 || v < lo || v > hi)
    throw py::value_error(std::string(name) + " must be " + meaning + ", got " +
                          std::string(py::str(number)));
  return v;
}

unsigned workerCount(const py::object& workers, const py::object& threads) {
  constexpr long long kMost = 4096;
  const long long cores = std::max(1u, std::thread::hardware_concurrency());
  if (!threads.is_none()) {
    if (!workers.is_none())
      throw py::type_error("give workers= or its old name threads=, not both");
    PyErr_WarnEx(PyExc_DeprecationWarning,
                 "threads= is now workers= (as scipy names it; -1 for every core)", 1);
    const long long t =
        integerArgument(threads, "threads", 0, kMost, "from 0 (every core) to 4096");
    return static_cast<unsigned>(t);
  }
  if (workers.is_none()) return 1;  // scipy's default: one thread
  const char* meaning =
      "a thread count from 1 to 4096, or -1 for every core (-2 every core "
      "but one, ...)";
  const long long w = integerArgument(workers, "workers", -kMost, kMost, meaning);
  if (w == 0) throw py::value_error(std::string("workers must be ") + meaning + ", not 0");
  return static_cast<unsigned>(w > 0 ? w : std::max(1LL, cores + 1 + w));
}

std::uint32_t resolutionOf(const py::object& resolution) {
  return static_cast<std::uint32_t>(
      integerArgument(resolution, "resolution", 0, std::numeric_limits<std::uint32_t>::max(),
                      "from 0 (chosen from the shape) to 4294967295"));
}

}  // namespace convexloc::python
