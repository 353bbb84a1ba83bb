// convexloc — how a line meets a polygon, or a plane a polyhedron.
#pragma once

#include <cstdint>
#include <string_view>

namespace convexloc {

// How a line (a plane) meets a closed convex region. Exact for the doubles given: touches
// means it meets the boundary and not the interior.
enum class Crossing : std::uint8_t { Misses, Touches, Crosses };

// "misses", "touches" or "crosses"
constexpr std::string_view toString(Crossing c) {
  switch (c) {
    case Crossing::Misses: return "misses";
    case Crossing::Touches: return "touches";
    case Crossing::Crosses: return "crosses";
  }
  return "?";
}

// The vertices where a line's (plane's) side function is largest and smallest, and its exact
// signs there: what every method's trace reports.
struct ExtremeVertices {
  std::uint32_t largest = 0, smallest = 0;
  int largestSign = 0, smallestSign = 0;
};

// The crossing of a line (plane) from the exact signs of its side function at the vertices
// where it is largest and smallest: crosses when they are strictly opposite, touches when
// one is zero and the other is not strictly opposite, misses otherwise.
constexpr Crossing crossingOf(int maxSign, int minSign) {
  if (minSign > 0 || maxSign < 0) return Crossing::Misses;
  if (minSign < 0 && maxSign > 0) return Crossing::Crosses;
  return Crossing::Touches;
}

}  // namespace convexloc
