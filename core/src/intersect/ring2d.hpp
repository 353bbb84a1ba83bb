// convexloc (internal) — exact steps over a polygon's ring for a line's side function.
//
// For the line through p1, p2 and f(x) = (p2 - p1) x (x - p1), the difference f(v) - f(u) is
// (p2 - p1) x (v - u): crossDiff2d gives its exact sign, so two vertices are compared along
// the line's normal exactly, with the filtered predicate's cost. Reversing the line (p2, p1)
// negates f: the vertex where f is smallest is the one where the reversed line's f is
// largest, so every search below is written for the largest only.
//
// Along the counter-clockwise ring of a strictly convex polygon, f rises to its largest value
// and falls to its smallest once each, with at most two equal vertices at either end (an edge
// parallel to the line; three would be collinear). Hence a vertex neither of whose neighbours
// is strictly larger is a largest one: the climb below stops only there, whatever vertex it
// starts from.
#pragma once

#include <cmath>
#include <cstdint>
#include <span>

#include "convexloc/geometry.hpp"
#include "convexloc/predicates.hpp"

namespace convexloc::detail {

// the vertex after i on a ring of n
inline std::uint32_t nextOf(std::uint32_t i, std::size_t n) noexcept {
  return i + 1 == n ? 0 : i + 1;
}
// the vertex before i on a ring of n
inline std::uint32_t prevOf(std::uint32_t i, std::size_t n) noexcept {
  return i == 0 ? static_cast<std::uint32_t>(n - 1) : i - 1;
}

// a line through two distinct points, and a count of the vertex comparisons made along it
struct LineProbe {
  Vec2 p1, p2;
  std::uint32_t comparisons = 0;
  // the exact sign of f(v) - f(u)
  int rise(Vec2 u, Vec2 v) noexcept {
    ++comparisons;
    return crossDiff2d(p1, p2, u, v);
  }
  // the same line, reversed
  LineProbe reversed() const noexcept { return {p2, p1, 0}; }
};

// Moves `at` uphill along the ring to a vertex where f is largest, in at most `maxSteps`
// moves (each counted in `steps`); false when it ran out of moves first.
inline bool climbToLargest(std::span<const Vec2> ring, LineProbe& line, std::uint32_t& at,
                           std::uint32_t maxSteps, std::uint32_t& steps) noexcept {
  const std::size_t n = ring.size();
  bool forward = true;
  std::uint32_t next = nextOf(at, n);
  if (line.rise(ring[at], ring[next]) <= 0) {
    next = prevOf(at, n);
    if (line.rise(ring[at], ring[next]) <= 0) return true;  // neither neighbour is larger
    forward = false;
  }
  // `next` is strictly larger: move, then keep going the same way while it rises
  for (;;) {
    if (steps == maxSteps) return false;
    at = next;
    ++steps;
    next = forward ? nextOf(at, n) : prevOf(at, n);
    if (line.rise(ring[at], ring[next]) <= 0) return true;
  }
}

// Which of window v[1], v[2] (four consecutive ring vertices) is a largest vertex, read
// from the window alone: 1 or 2 when neither of its ring neighbours is strictly larger, 0
// when neither is confirmed (one of them still has a larger neighbour).
inline int largestInWindow(const Vec2 (&v)[4], LineProbe& line) noexcept {
  if (line.rise(v[1], v[2]) > 0) return line.rise(v[2], v[3]) > 0 ? 0 : 2;
  return line.rise(v[1], v[0]) > 0 ? 0 : 1;
}

// crossDiff2d(a, b, c, d), its sign read without a branch where the filter decides it (the
// same filter; where it does not decide, crossDiff2d decides as ever)
inline int crossSign(Vec2 a, Vec2 b, Vec2 c, Vec2 d) noexcept {
  const double left = (b.x - a.x) * (d.y - c.y), right = (b.y - a.y) * (d.x - c.x);
  const double det = left - right, permanent = std::fabs(left) + std::fabs(right);
  const bool sure = (permanent >= detail::kTinyPermanent) &
                    (std::fabs(det) > detail::kCcwBound * permanent + detail::kUnderflowSlack);
  if (sure) [[likely]]
    return static_cast<int>(det > 0) - static_cast<int>(det < 0);
  return crossDiff2d(a, b, c, d);
}

// largestInWindow's answer for the line p1 -> p2, every comparison made and the choice read
// without a branch (a random line's choice is a coin toss a predictor would miss)
inline int largestInWindowFlat(const Vec2 (&v)[4], Vec2 p1, Vec2 p2) noexcept {
  const int r12 = crossSign(p1, p2, v[1], v[2]), r23 = crossSign(p1, p2, v[2], v[3]);
  const int r10 = crossSign(p1, p2, v[1], v[0]);
  const int up = static_cast<int>(r12 > 0);
  const int confirmed = up ? static_cast<int>(r23 <= 0) : static_cast<int>(r10 <= 0);
  return confirmed * (1 + up);
}

// a vertex where f is largest, by bisection over the ring: O(log N) exact comparisons
std::uint32_t bisectLargest(std::span<const Vec2> ring, LineProbe& line) noexcept;

}  // namespace convexloc::detail
