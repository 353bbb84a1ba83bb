// convexloc Python module — locating points given as separate coordinate arrays (x, y[, z]),
// what LAS and other point-cloud readers hand out, as fast as an (M, dims) array.
//
// The arrays broadcast together as numpy's ufuncs do ((3, 1) with (1, 4) gives (3, 4)). Seen
// without its length-1 axes, the broadcast shape is rows x a last axis; a float64 array whose
// rows lie at one stride (any 1-D view, a contiguous block, a broadcast row or column) is read
// where it lies; any other is converted once. The points are gathered 256 at a time into a
// small buffer on each thread's stack and located through the locator's own batch path, so
// no (M, dims) copy is ever made.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <string>
#include <thread>
#include <vector>

#include "arrays.hpp"

namespace convexloc::python {

// one coordinate array read as rows: element (row, i) at base + row * outer + i * inner bytes
struct Column {
  const char* base = nullptr;
  py::ssize_t outer = 0;
  py::ssize_t inner = 0;
};

// the arrays x, y[, z] checked, converted where they must be, and broadcast together
std::vector<py::array> broadcastColumns(const py::object* columns, std::size_t count);

// the length of the last axis longer than 1 of the broadcast shape (1 when there is none)
std::size_t rowLength(const py::array& broadcast);

// `array` (broadcast, float64) as a Column of rows of `length` elements when its rows lie at
// one stride; otherwise a C-contiguous copy of it is made, kept in `keep`
Column columnOf(const py::array& array, std::size_t length, py::object& keep);

// n points into `block`, coordinate d read from from[d] at strides[d] bytes; the plain case
// (every stride one double) is a loop of its own, which the compiler vectorises
template <class Point>
void gather(Point* block, std::size_t n, const std::array<const char*, kDims<Point>>& from,
            const std::array<py::ssize_t, kDims<Point>>& strides) {
  constexpr int dims = kDims<Point>;
  const bool plain = std::all_of(strides.begin(), strides.end(),
                                 [](py::ssize_t s) { return s == py::ssize_t{sizeof(double)}; });
  if (plain) {
    const auto* x = reinterpret_cast<const double*>(from[0]);
    const auto* y = reinterpret_cast<const double*>(from[1]);
    if constexpr (dims == 2) {
      for (std::size_t r = 0; r < n; ++r) block[r] = {x[r], y[r]};
    } else {
      const auto* z = reinterpret_cast<const double*>(from[2]);
      for (std::size_t r = 0; r < n; ++r) block[r] = {x[r], y[r], z[r]};
    }
    return;
  }
  auto at = [&](int d, std::size_t r) {
    const auto k = static_cast<std::size_t>(d);
    return *reinterpret_cast<const double*>(from[k] + static_cast<py::ssize_t>(r) * strides[k]);
  };
  if constexpr (dims == 2) {
    for (std::size_t r = 0; r < n; ++r) block[r] = {at(0, r), at(1, r)};
  } else {
    for (std::size_t r = 0; r < n; ++r) block[r] = {at(0, r), at(1, r), at(2, r)};
  }
}

// the points [begin, end) of `columns` (rows of `length`) located into out, a block at a time
template <class Locator, class Point>
void locateRange(const Locator& locator, const std::array<Column, kDims<Point>>& columns,
                 std::size_t length, std::span<Location> out, std::size_t begin, std::size_t end) {
  // small blocks: the hardware keeps streaming the columns in while the locator works on one,
  // where a large block's gather would be a pass of its own that waits on memory
  constexpr std::size_t kBlock = 256;
  std::array<Point, kBlock> block;
  std::size_t row = begin / length;
  std::size_t at = begin % length;
  for (std::size_t start = begin; start < end; start += kBlock) {
    const std::size_t n = std::min(kBlock, end - start);
    for (std::size_t k = 0; k < n;) {
      const std::size_t run = std::min(n - k, length - at);
      std::array<const char*, kDims<Point>> from;
      std::array<py::ssize_t, kDims<Point>> strides;
      for (std::size_t d = 0; d < from.size(); ++d) {
        const Column& c = columns[d];
        from[d] = c.base + static_cast<py::ssize_t>(row) * c.outer +
                  static_cast<py::ssize_t>(at) * c.inner;
        strides[d] = c.inner;
      }
      gather(block.data() + k, run, from, strides);
      k += run;
      at += run;
      if (at == length) at = 0, ++row;
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
  const std::size_t length = rowLength(arrays[0]);
  std::array<py::object, kDims<Point>> kept;
  std::array<Column, kDims<Point>> read;
  for (std::size_t k = 0; k < read.size(); ++k) read[k] = columnOf(arrays[k], length, kept[k]);
  auto codes =
      codeArray(std::vector<py::ssize_t>(arrays[0].shape(), arrays[0].shape() + arrays[0].ndim()));
  const std::span<Location> out = locationsOf(codes);
  const std::size_t n = out.size();
  if (n == 0) return codes;  // (then a row may be empty: nothing to divide by)
  py::gil_scoped_release released;
  const unsigned t = batchThreads(n, workers);
  constexpr std::size_t kLine = 64;  // answers per cache line: no two threads share one
  const std::size_t share = ((n + t - 1) / t + kLine - 1) / kLine * kLine;
  std::vector<std::jthread> helpers;
  for (unsigned k = 1; k < t && share * k < n; ++k)
    helpers.emplace_back([&, k] {
      locateRange<Locator, Point>(locator, read, length, out, share * k,
                                  std::min(n, share * (k + 1)));
    });
  locateRange<Locator, Point>(locator, read, length, out, 0, std::min(n, share));
  return codes;  // the helpers join first, as they go out of scope
}

}  // namespace convexloc::python
