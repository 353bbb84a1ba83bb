// convexloc — plain value types shared by every part.
#pragma once

#include <cstdint>
#include <string_view>

namespace convexloc {

// a point or a vector in the plane
struct Vec2 {
  double x = 0.0;
  double y = 0.0;
  friend bool operator==(const Vec2&, const Vec2&) = default;
};

// a point or a vector in space
struct Vec3 {
  double x = 0.0;
  double y = 0.0;
  double z = 0.0;
  friend bool operator==(const Vec3&, const Vec3&) = default;
};

// Where a point lies with respect to a closed convex region. Exact for the doubles given:
// Boundary means exactly on the boundary, never "within some tolerance".
enum class Location : std::uint8_t { Inside, Boundary, Outside };

// "inside", "boundary" or "outside"
constexpr std::string_view toString(Location l) {
  switch (l) {
    case Location::Inside: return "inside";
    case Location::Boundary: return "boundary";
    case Location::Outside: return "outside";
  }
  return "?";
}

// an axis-aligned box; empty when lo > hi
struct Box2 {
  Vec2 lo{};
  Vec2 hi{};
};

}  // namespace convexloc
