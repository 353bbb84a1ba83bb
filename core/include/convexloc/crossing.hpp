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
  // misses when both signs are on one side, crosses when strictly on both; written without
  // branches, so a caller's next query is never discarded for a mispredicted one
  const bool meets = (minSign <= 0) & (maxSign >= 0), both = (minSign < 0) & (maxSign > 0);
  return static_cast<Crossing>(static_cast<int>(meets) * (1 + static_cast<int>(both)));
}

}  // namespace convexloc
