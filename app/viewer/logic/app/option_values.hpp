// convexloc-viewer — the values the command line's options take, read from text: whole
// numbers in a range, finite doubles, points "X,Y" and "X,Y,Z", counts written as 1e6.
// Each reader returns false for text that is not such a value, whole.
#pragma once

#include <charconv>
#include <cmath>
#include <cstddef>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "convexloc/geometry.hpp"

namespace convexloc::viewer {

// a whole number in [lo, hi]
template <class T>
bool parseInt(std::string_view s, T lo, T hi, T& out) {
  T v{};
  const auto r = std::from_chars(s.data(), s.data() + s.size(), v);
  if (r.ec != std::errc() || r.ptr != s.data() + s.size() || v < lo || v > hi) return false;
  out = v;
  return true;
}

// a finite double
bool parseDouble(std::string_view s, double& out);
// "X,Y"
bool parsePoint(std::string_view s, Vec2& out);
// "X,Y,Z"
bool parsePoint3(std::string_view s, Vec3& out);
// a count up to 2^26 written plainly or as 1e6
bool parseCount(std::string_view s, std::size_t& out);

// The word of `candidates` closest to `word` by edit distance (a letter inserted, dropped,
// changed or two swapped), when it is close enough to be a typo of it; "" otherwise.
std::string nearestWord(std::string_view word, std::span<const std::string_view> candidates);

// Which part of an option's values is wrong, for its error: with several values or commas,
// the first part that is not a number ("'0.5x' is not a number"); otherwise the values
// themselves ("not 'lots'").
std::string badPart(const std::vector<std::string>& values);

}  // namespace convexloc::viewer
