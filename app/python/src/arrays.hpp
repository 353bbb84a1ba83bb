// convexloc Python module — numpy arrays in and out, and the batch that runs between them.
//
// The conversion rules, the same for every locator and shape: anything numpy.asarray takes;
// integer and floating dtypes are converted to float64 once, and only when every value is
// exactly a double (an int64 beyond 2^53 or a long double that is not is a ValueError naming
// the element; a masked array with masked elements is a TypeError);
// booleans, complex numbers, strings and objects are a TypeError; a C-contiguous, aligned,
// native float64 array is read where it lies, without a copy. Points come as an (M, dims)
// array (an empty 1-D array counts as no points); a wrong shape is a ValueError naming it.
// Answers go out as an int8 array of Location codes (INSIDE 0, BOUNDARY 1, OUTSIDE 2), whose
// buffer the locators write directly. The locating itself runs with the GIL released.
#pragma once

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "convexloc/batch.hpp"
#include "convexloc/geometry.hpp"

namespace convexloc::python {

namespace py = pybind11;

static_assert(sizeof(Vec2) == 2 * sizeof(double) && alignof(Vec2) == alignof(double));
static_assert(sizeof(Vec3) == 3 * sizeof(double) && alignof(Vec3) == alignof(double));
static_assert(sizeof(Location) == sizeof(std::int8_t));

// the coordinates a point of this type has
template <class Point>
inline constexpr int kDims = sizeof(Point) / sizeof(double);

// numbers as a numpy array of integers or floating-point numbers, each exactly a double (the
// input itself when it is an array already, in any layout); `what` names the argument
py::array numberArray(const py::object& values, const char* what);

// numbers as one C-contiguous, aligned, native float64 array (the input itself when it is
// one already), of any shape; `what` names the argument in errors
py::array floatArray(const py::object& values, const char* what);

// `points` as an (M, dims) float64 array (see floatArray), M >= 0
py::array pointArray(const py::object& points, int dims, const char* what);

// an uninitialised int8 array of the given shape, for Location codes
py::array_t<std::int8_t> codeArray(const std::vector<py::ssize_t>& shape);

// "(3, 2)": a shape as numpy prints it
std::string shapeText(const std::vector<py::ssize_t>& shape);

// the integer argument `name`, checked: a Python int (or anything with __index__) in
// [lo, hi], else ValueError naming the value given (TypeError for a non-integer)
long long integerArgument(const py::object& value, const char* name, long long lo, long long hi,
                          const char* meaning);

// the threads of a batch from workers= (as scipy: None 1, k > 0 threads, -1 every core, -k
// every core but k - 1) or from its deprecated old name threads= (0: every core); the result
// 0 means every core
unsigned workerCount(const py::object& workers, const py::object& threads);

// the resolution argument of a locator, checked (0 chooses from the shape)
std::uint32_t resolutionOf(const py::object& resolution);

// one point given as `dims` numbers, for trace()
template <class Point>
Point onePoint(const py::object& point) {
  const py::array xs = floatArray(point, "point");
  if (xs.ndim() != 1 || xs.shape(0) != kDims<Point>)
    throw py::value_error("point must be " + std::to_string(kDims<Point>) + " numbers, got shape " +
                          shapeText(std::vector<py::ssize_t>(xs.shape(), xs.shape() + xs.ndim())));
  return *reinterpret_cast<const Point*>(xs.data());
}

// the points as an (N, dims) float64 array (a copy)
template <class Point>
py::array_t<double> coordinateArray(std::span<const Point> points) {
  py::array_t<double> out({static_cast<py::ssize_t>(points.size()), py::ssize_t{kDims<Point>}});
  auto* to = reinterpret_cast<Point*>(out.mutable_data());
  for (std::size_t i = 0; i < points.size(); ++i) to[i] = points[i];
  return out;
}

// the indices as an int64 array of shape (N,)
py::array_t<std::int64_t> indexArray(std::span<const std::uint32_t> indices);

// the points of an (M, dims) float64 array from pointArray
template <class Point>
std::span<const Point> pointsOf(const py::array& array) {
  const auto count = static_cast<std::size_t>(array.shape(0));
  return {reinterpret_cast<const Point*>(array.data()), count};
}

// the answers an int8 array from codeArray holds
inline std::span<Location> locationsOf(py::array_t<std::int8_t>& codes) {
  return {reinterpret_cast<Location*>(codes.mutable_data()),
          static_cast<std::size_t>(codes.size())};
}

// Locates every row of `points` ((M, dims) array-like) with the GIL released, on up to
// `workers` threads (0: one per core); returns the (M,) int8 codes.
template <class Locator, class Point>
py::array_t<std::int8_t> locateRows(const Locator& locator, const py::object& points,
                                    unsigned workers) {
  const py::array rows = pointArray(points, kDims<Point>, "points");
  auto codes = codeArray({rows.shape(0)});
  const std::span<const Point> in = pointsOf<Point>(rows);
  const std::span<Location> out = locationsOf(codes);
  {
    py::gil_scoped_release released;
    locateParallel(locator, in, out, workers);
  }
  return codes;
}

}  // namespace convexloc::python
