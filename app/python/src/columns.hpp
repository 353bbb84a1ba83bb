// convexloc Python module — locating points given as separate coordinate arrays (x, y[, z]),
// what LAS and other point-cloud readers hand out, as fast as an (M, dims) array.
//
// The arrays broadcast together as numpy's ufuncs do ((3, 1) with (1, 4) gives (3, 4)). A
// float64 array whose elements lie at one fixed stride (any 1-D view, a contiguous block, a
// broadcast scalar) is read where it lies; any other is converted once. The points are
// gathered block by block into a small buffer on each thread's stack and located through the
// locator's own batch path, so no (M, dims) copy is ever made.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <thread>
#include <vector>

#include "arrays.hpp"

namespace convexloc::python {

// one coordinate array as a base address and a byte stride between consecutive elements
struct Column {
  const char* base = nullptr;
  py::ssize_t stride = 0;
  double at(std::size_t i) const noexcept {
    return *reinterpret_cast<const double*>(base + static_cast<py::ssize_t>(i) * stride);
  }
};

// `array` (broadcast, float64) as a Column when its elements, in C order, lie at one stride;
// otherwise a C-contiguous copy of it is made, kept in `keep`
Column columnOf(const py::array& array, py::object& keep);

// the arrays x, y[, z] checked, converted where they must be, and broadcast together
std::vector<py::array> broadcastColumns(const py::object* columns, std::size_t count);

// the points [begin, end) of `columns` located into out, a block at a time
template <class Locator, class Point>
void locateRange(const Locator& locator, const std::array<Column, kDims<Point>>& columns,
                 std::span<Location> out, std::size_t begin, std::size_t end) {
  constexpr std::size_t kBlock = 1024;
  std::array<Point, kBlock> block;
  for (std::size_t start = begin; start < end; start += kBlock) {
    const std::size_t n = std::min(kBlock, end - start);
    for (std::size_t i = 0; i < n; ++i) {
      if constexpr (kDims<Point> == 2)
        block[i] = {columns[0].at(start + i), columns[1].at(start + i)};
      else
        block[i] = {columns[0].at(start + i), columns[1].at(start + i), columns[2].at(start + i)};
    }
    locator.locate(std::span<const Point>(block.data(), n), out.subspan(start, n));
  }
}

// Locates the points whose coordinates are the broadcast elements of `columns` with the GIL
// released, on up to `workers` threads (0: one per core); the codes have the broadcast shape.
template <class Locator, class Point>
py::array_t<std::int8_t> locateColumns(const Locator& locator,
                                       const std::array<py::object, kDims<Point>>& columns,
                                       unsigned workers) {
  const std::vector<py::array> arrays = broadcastColumns(columns.data(), columns.size());
  std::array<py::object, kDims<Point>> kept;
  std::array<Column, kDims<Point>> read;
  for (std::size_t k = 0; k < read.size(); ++k) read[k] = columnOf(arrays[k], kept[k]);
  auto codes = codeArray(std::vector<py::ssize_t>(arrays[0].shape(), arrays[0].shape() + arrays[0].ndim()));
  const std::span<Location> out = locationsOf(codes);
  py::gil_scoped_release released;
  const std::size_t n = out.size();
  const unsigned t = batchThreads(n, workers);
  constexpr std::size_t kLine = 64;  // answers per cache line: no two threads share one
  const std::size_t share = ((n + t - 1) / t + kLine - 1) / kLine * kLine;
  std::vector<std::jthread> helpers;
  for (unsigned k = 1; k < t && share * k < n; ++k)
    helpers.emplace_back([&, k] {
      locateRange<Locator, Point>(locator, read, out, share * k, std::min(n, share * (k + 1)));
    });
  locateRange<Locator, Point>(locator, read, out, 0, std::min(n, share));
  return codes;  // the helpers join first, as they go out of scope
}

}  // namespace convexloc::python
