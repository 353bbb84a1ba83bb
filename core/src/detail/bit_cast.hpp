// convexloc — std::bit_cast, or the compiler's builtin where the standard library has none
// (libc++ 14, the web build's).
#pragma once

#include <bit>

namespace convexloc::detail {

#if defined(__cpp_lib_bit_cast)
using std::bit_cast;
#else
// the object representation of `from` read as a To (both trivially copyable, one size)
template <class To, class From>
constexpr To bit_cast(const From& from) noexcept {
  static_assert(sizeof(To) == sizeof(From), "bit_cast between types of one size");
  return __builtin_bit_cast(To, from);
}
#endif

}  // namespace convexloc::detail
