// convexloc — polygons and point sets for demos, tests and benchmarks. Deterministic:
// the same kind, size and seed give the same doubles on every platform.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "convexloc/geometry.hpp"
#include "convexloc/polygon.hpp"

namespace convexloc {

// a small, portable random source (SplitMix64)
class Rng {
 public:
  explicit Rng(std::uint64_t seed) : s_(seed) {}
  std::uint64_t next() noexcept {
    std::uint64_t z = (s_ += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  // uniform in [0, 1)
  double uniform() noexcept { return static_cast<double>(next() >> 11) * 0x1p-53; }
  // uniform in [lo, hi)
  double uniform(double lo, double hi) noexcept { return lo + (hi - lo) * uniform(); }
  // uniform integer in [0, n)
  std::uint64_t below(std::uint64_t n) noexcept { return n ? next() % n : 0; }

 private:
  std::uint64_t s_;
};

// === Polygons

enum class PolygonKind : std::uint8_t {
  Regular,     // regular N-gon on the unit circle
  Random,      // random convex polygon, Valtr's method
  Ellipse,     // N points on an ellipse with axes 2 and 1
  Sliver,      // a needle: an ellipse 10^9 times longer than wide, rotated 30 degrees
  TinyEdges,   // three long edges and N-3 edges 10^10 times shorter, packed at one corner
  Offset,      // a regular N-gon of radius 1 centred at (1e9, -1e9)
  Degenerate,  // a square whose sides carry collinear vertices and whose corners repeat
  Triangle,    // a random triangle (N is ignored)
};

std::string_view toString(PolygonKind k);
std::optional<PolygonKind> parsePolygonKind(std::string_view name);
inline constexpr PolygonKind kAllPolygonKinds[] = {
    PolygonKind::Regular,   PolygonKind::Random, PolygonKind::Ellipse,    PolygonKind::Sliver,
    PolygonKind::TinyEdges, PolygonKind::Offset, PolygonKind::Degenerate, PolygonKind::Triangle};

// The vertex list of a polygon of that kind with about `n` vertices (n >= 3), counter-
// clockwise. Every kind but Degenerate is strictly convex as given; Degenerate is a valid
// input that normalisation reduces to a square. Throws UsageError for n < 3 or n > 2^26.
std::vector<Vec2> generatePolygon(PolygonKind kind, std::size_t n, std::uint64_t seed);

// === Points

// `count` query points for `polygon`: uniform in its bounding box enlarged by 10% on each
// side, or, with `nearBoundary`, hard cases: vertices, points exactly on edges, points one
// ulp off vertices and edges, and points a hair inside or outside.
std::vector<Vec2> generatePoints(const ConvexPolygon& polygon, std::size_t count,
                                 std::uint64_t seed, bool nearBoundary);

// The strictly convex hull of `points` (exact predicates), counter-clockwise.
std::vector<Vec2> convexHull(std::span<const Vec2> points);

}  // namespace convexloc
