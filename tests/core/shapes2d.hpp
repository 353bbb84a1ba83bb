// The matrix of 2D shapes the locator tests run over: every generator kind at several sizes
// and seeds, and hand-made shapes that stress one thing each (axis-aligned edges, extreme
// magnitudes, slivers thinner than the double grid, clockwise input, repeats, collinear runs).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "convexloc/generate2d.hpp"
#include "convexloc/geometry.hpp"
#include "reference2d.hpp"

namespace shapes {

using convexloc::Vec2;

// one shape of the matrix
struct ShapeCase {
  std::string name;          // a gtest-safe name: letters, digits, underscores
  std::vector<Vec2> input;   // the vertex list as given to ConvexPolygon
  std::size_t randomPoints;  // how many uniform random queries to run against it
};

// the points scaled by 2^e (exact unless the result leaves the normal range)
inline std::vector<Vec2> scaled(std::vector<Vec2> v, int e) {
  for (Vec2& p : v) p = {std::ldexp(p.x, e), std::ldexp(p.y, e)};
  return v;
}

// the points in reverse order
inline std::vector<Vec2> reversed(std::vector<Vec2> v) {
  return {v.rbegin(), v.rend()};
}

// a regular n-gon of radius 1 around the origin, made strictly convex by the reference hull
inline std::vector<Vec2> regular(std::size_t n) {
  std::vector<Vec2> v(n);
  for (std::size_t i = 0; i < n; ++i) {
    double t = 2 * 3.14159265358979323846 * static_cast<double>(i) / static_cast<double>(n);
    v[i] = {std::cos(t), std::sin(t)};
  }
  return ref::hull(v);
}

// the generator kind's name with '-' made gtest-safe
inline std::string safeName(convexloc::PolygonKind k) {
  std::string s(convexloc::toString(k));
  for (char& c : s)
    if (c == '-') c = '_';
  return s;
}

// random query counts: representative shapes, the rest, large N
inline constexpr std::size_t full = 100000, fewer = 30000, few = 12000;

// Every shape of the matrix. `full` random points go to the representative shapes, fewer to
// the rest (large N, where the O(N) reference and halfplane dominate, and extreme magnitudes,
// where core's exact fallback does); adversarial points come on top for every shape.
inline std::vector<ShapeCase> buildCases() {
  using convexloc::generatePolygon;
  using convexloc::PolygonKind;
  std::vector<ShapeCase> out;
  for (PolygonKind kind : convexloc::kAllPolygonKinds) {
    const bool seeded =
        kind == PolygonKind::Random || kind == PolygonKind::Offset || kind == PolygonKind::Triangle;
    const std::vector<std::size_t> sizes = kind == PolygonKind::Triangle
                                               ? std::vector<std::size_t>{3}
                                               : std::vector<std::size_t>{3, 4, 17, 256, 4096};
    const std::vector<std::uint64_t> seeds =
        kind == PolygonKind::Triangle
            ? std::vector<std::uint64_t>{1, 2, 3, 4}
            : (seeded ? std::vector<std::uint64_t>{1, 2} : std::vector<std::uint64_t>{1});
    for (std::size_t n : sizes)
      for (std::uint64_t seed : seeds) {
        std::string name = safeName(kind) + "_n" + std::to_string(n) + "_s" + std::to_string(seed);
        std::size_t count = n <= 256 && seed == 1 ? full : (n <= 256 ? fewer : few);
        out.push_back({name, convexloc::generatePolygon(kind, n, seed), count});
      }
  }
  const double ulp1 = 0x1p-53;  // one ulp below 1
  auto add = [&](std::string name, std::vector<Vec2> v, std::size_t count = full) {
    out.push_back({name, v, count});
  };
  add("square", {{0, 0}, {1, 0}, {1, 1}, {0, 1}});
  add("rectangle", {{-3, -1}, {5, -1}, {5, 2}, {-3, 2}});
  add("diamond", {{1, 0}, {0, 1}, {-1, 0}, {0, -1}});
  add("octagon_axis_diagonal", {{1, 0}, {2, 0}, {3, 1}, {3, 2}, {2, 3}, {1, 3}, {0, 2}, {0, 1}});
  add("aspect_wide", {{0, 0}, {1e12, 0}, {1e12, 1e-6}, {0, 1e-6}});
  add("aspect_tall_thin", {{0, 0}, {0x1p-40, 0}, {0x1p-40, 1}, {0, 1}});
  add("triangle_right", {{0, 0}, {3, 0}, {0, 2}});
  add("triangle_generic", {{0.1, 0.2}, {0.9, 0.35}, {0.3, 0.7}});
  // a lattice polygon at the smallest subnormal scale: every coordinate exact
  add("subnormal_lattice", scaled({{0, 0}, {4, 1}, {6, 3}, {5, 6}, {2, 7}, {-1, 4}}, -1074), fewer);
  // a 17-gon rounded into the subnormal range, then made strictly convex again
  add("subnormal_17gon", ref::hull(scaled(regular(17), -1066)), fewer);
  add("tiny_1e_300", scaled(regular(17), -997), fewer);
  // differences rounded as normal numbers, their products subnormal: where a filter without
  // an underflow guard goes wrong
  add("products_subnormal_2e_537", scaled(regular(17), -537), few);
  add("products_subnormal_2e_528", scaled(generatePolygon(PolygonKind::Random, 17, 3), -528), few);
  add("huge_1e300", scaled(regular(17), 997), fewer);
  add("huge_near_max", scaled(regular(17), 1022), fewer);
  add("span_1e_150_1e150", {{0, 0}, {1e-150, 0}, {1e150, 1e150}, {0, 1e-150}});
  // needles 10^150 long and 10^12 wide: the distance from the centre to a long edge fits in
  // a double, its cross product squared does not (the polygon reader's fuzz target found the
  // polar radii taking that overflow for an infinite inner radius)
  add("needle_1e150_by_1e12", {{4e-150, 1e-150}, {115e10, 1e150}, {75, 2e150}}, fewer);
  add("needle_1e154_by_1e3_tilted", {{0, 0}, {3e154, 1e154 + 1e138}, {1.5e154, 5e153}}, fewer);
  // no double point lies strictly inside: the polar locator has no centre and falls back
  add("ulp_sliver", {{0, 0}, {1, 1}, {1, 1 - ulp1}});
  add("two_ulp_sliver", {{0, 0}, {1, 1}, {0.5, 0.5 + ulp1}});
  add("clockwise_17gon", reversed(regular(17)));
  add("clockwise_square_mid_start", {{0.5, 1}, {1, 1}, {1, 0}, {0, 0}, {0, 1}});
  add("repeats_and_collinear",
      {{0, 0}, {0, 0}, {1, 0}, {2, 0}, {2, 0}, {2, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}, {0, 0}});
  add("collinear_diagonals_clockwise",
      reversed({{0, 0}, {0.1, -0.1}, {1, -1}, {2, 0}, {1.5, 0.5}, {1, 1}, {0.25, 0.25}}));
  add("regular_4096_reversed", reversed(regular(4096)), few);
  return out;
}

// the matrix, built once
inline const std::vector<ShapeCase>& cases() {
  static const std::vector<ShapeCase> all = buildCases();
  return all;
}

// the indices of the matrix, as gtest parameters
inline std::vector<std::size_t> caseIndices() {
  std::vector<std::size_t> idx(cases().size());
  for (std::size_t i = 0; i < idx.size(); ++i) idx[i] = i;
  return idx;
}

// a gtest parameter's name: the shape's name
struct CaseName {
  template <class ParamInfo>
  std::string operator()(const ParamInfo& param) const {
    return cases()[param.param].name;
  }
};

}  // namespace shapes
