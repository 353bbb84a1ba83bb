// convexloc fuzzing — checks of a validated polygon and of every 2D method on it.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/locate2d.hpp"
#include "convexloc/polygon.hpp"
#include "fuzz_support.hpp"

namespace fuzz {

using convexloc::ConvexPolygon;
using convexloc::Locator2D;
using convexloc::Method2D;

// What normalisation promises about `poly` built from `input`: at least 3 vertices, strictly
// convex and counter-clockwise, each kept vertex taken from the input, and every input point
// on the boundary of the result (dropping repeats and collinear points leaves the region).
inline void checkPolygon(const ConvexPolygon& poly, std::span<const Vec2> input) {
  auto v = poly.vertices();
  const std::size_t n = v.size();
  if (n < 3) fail("a polygon with " + std::to_string(n) + " vertices was accepted");
  if (poly.sourceIndex().size() != n) fail("sourceIndex() does not match the vertices");
  for (std::size_t i = 0; i < n; ++i) {
    std::uint32_t src = poly.sourceIndex()[i];
    if (src >= input.size() || input[src] != v[i])
      fail("vertex " + std::to_string(i) + " is not the input point its sourceIndex names");
    if (exactOrient(v[i], v[(i + 1) % n], v[(i + 2) % n]) <= 0)
      fail("accepted polygon is not strictly convex counter-clockwise at vertex " +
           std::to_string((i + 1) % n) + " " + show(v[(i + 1) % n]));
  }
  // turning once around: the edge directions make one full turn (a pentagram would not)
  int halfTurns = 0;
  for (std::size_t i = 0; i < n; ++i) {
    Vec2 a = v[i], b = v[(i + 1) % n];
    bool upper = b.y > a.y || (b.y == a.y && b.x > a.x);
    Vec2 c = v[(i + 1) % n], d = v[(i + 2) % n];
    bool nextUpper = d.y > c.y || (d.y == c.y && d.x > c.x);
    if (upper != nextUpper) ++halfTurns;
  }
  if (halfTurns != 2) fail("accepted polygon winds more than once");
  for (std::size_t i = 0; i < input.size(); ++i)
    if (exactLocate(v, input[i]) != Location::Boundary)
      fail("input point " + std::to_string(i) + " " + show(input[i]) +
           " is not on the boundary of the normalised polygon");
  if (poly.droppedCount() != input.size() - n) fail("droppedCount() is wrong");
  auto box = poly.bounds();
  for (Vec2 p : v)
    if (p.x < box.lo.x || p.y < box.lo.y || p.x > box.hi.x || p.y > box.hi.y)
      fail("bounds() does not hold every vertex");
}

// The query points a polygon invites: every vertex and its one-ulp neighbours, edge
// midpoints and their neighbours, and points far out along the axes.
inline void addHardPoints(std::vector<Vec2>& out, std::span<const Vec2> v) {
  const double big = 1.7976931348623157e308;
  for (std::size_t i = 0; i < v.size(); ++i) {
    out.push_back(v[i]);
    addNeighbours(out, v[i]);
    Vec2 a = v[i], b = v[(i + 1) % v.size()];
    Vec2 mid{a.x / 2 + b.x / 2, a.y / 2 + b.y / 2};
    out.push_back(mid);
    addNeighbours(out, mid);
  }
  for (Vec2 p : {Vec2{big, 0}, Vec2{-big, 0}, Vec2{0, big}, Vec2{0, -big}, Vec2{big, big},
                 Vec2{-big, -big}, Vec2{0, 0}, Vec2{-0.0, -0.0}, Vec2{5e-324, -5e-324}})
    out.push_back(p);
}

// a resolution for the grid methods: 0 (automatic), small, or large
inline std::uint32_t resolutionFrom(std::uint8_t b) {
  static constexpr std::array<std::uint32_t, 8> kChoices = {0, 1, 2, 3, 5, 8, 13, 200};
  return kChoices[b % kChoices.size()];
}

// Every method on every point of `queries` against the exact reference, plus batch and
// trace agreeing with single queries. Aborts on the first mismatch.
inline void checkMethods(const ConvexPolygon& poly, std::span<const Vec2> queries,
                         std::uint32_t resolution) {
  auto v = poly.vertices();
  std::vector<Location> reference(queries.size());
  for (std::size_t k = 0; k < queries.size(); ++k) reference[k] = exactLocate(v, queries[k]);
  std::vector<Location> batch(queries.size());
  for (Method2D m : convexloc::kAllMethods2D) {
    const std::string name(convexloc::toString(m));
    std::vector<Locator2D> built;
    try {
      built.emplace_back(poly, m, resolution);
    } catch (const std::exception& e) {
      fail(name + " (resolution " + std::to_string(resolution) +
           ") failed to build on a valid polygon: " + e.what());
    }
    const Locator2D& loc = built.front();
    loc.locate(queries, batch);
    for (std::size_t k = 0; k < queries.size(); ++k) {
      Location got = loc.locate(queries[k]);
      if (got != reference[k])
        fail(name + " (resolution " + std::to_string(resolution) + ") says " +
             std::string(convexloc::toString(got)) + " for " + show(queries[k]) +
             ", exactly it is " + std::string(convexloc::toString(reference[k])) + " (" +
             std::to_string(v.size()) + " vertices)");
      if (batch[k] != got) fail(name + ": batch and single answers differ for " + show(queries[k]));
      if (k < 64 && loc.trace(queries[k]).result != got)
        fail(name + ": trace and locate differ for " + show(queries[k]));
    }
    convexloc::Stats2D st = loc.stats();
    if (st.edges != v.size()) fail(name + ": stats().edges is wrong");
  }
}

}  // namespace fuzz
