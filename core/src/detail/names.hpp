// convexloc (internal) — an enumeration's names as a table in the enumeration's order: one
// table gives both directions, toString (names[k]) and parsing (enumNamed).
#pragma once

#include <cstddef>
#include <optional>
#include <string_view>

namespace convexloc::detail {

// the enumerator whose name in `names` (in the enumeration's order) is `name`, if any
template <class Enum, std::size_t N>
std::optional<Enum> enumNamed(const std::string_view (&names)[N], std::string_view name) noexcept {
  for (std::size_t i = 0; i < N; ++i)
    if (names[i] == name) return static_cast<Enum>(i);
  return std::nullopt;
}

// the name of `value` in `names` (in the enumeration's order), "?" past its end
template <class Enum, std::size_t N>
std::string_view nameOf(const std::string_view (&names)[N], Enum value) noexcept {
  const auto i = static_cast<std::size_t>(value);
  return i < N ? names[i] : "?";
}

}  // namespace convexloc::detail
