// convexloc (internal) — what the point reader and the mesh reader agree a line is made of.
#pragma once

namespace convexloc::detail {

// a blank that separates numbers or tokens within a line; a line end is not one
constexpr bool isBlank(char c) noexcept {
  return c == ' ' || c == '\t' || c == '\v' || c == '\f';
}

}  // namespace convexloc::detail
