// convexloc — doubles to and from text with std::to_chars / std::from_chars, or, where the
// standard library has them for integers only (libc++ 14: the web build's), with an
// equivalent made of snprintf and strtod: the shortest text that reads back to the same
// double, and the from_chars grammar (no leading blank or '+', no hex) read exactly. The
// equivalent is compiled everywhere, so the tests hold it against the standard library's.
#pragma once

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstddef>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <system_error>

namespace convexloc::detail {

// the shortest decimal text that reads back as v, at first (at most 32 chars are written)
inline std::to_chars_result portableDoubleToChars(char* first, char* last, double v) {
  char buf[40];
  int n = 0;
  for (int digits = 1; digits <= 17; ++digits) {
    n = std::snprintf(buf, sizeof buf, "%.*g", digits, v);
    if (!std::isfinite(v) || std::strtod(buf, nullptr) == v) break;
  }
  if (n <= 0 || n > last - first) return {last, std::errc::value_too_large};
  for (int i = 0; i < n; ++i) first[i] = buf[i];
  return {first + n, std::errc()};
}
// the length of the longest prefix of [p, end) that from_chars' general format reads, or 0
inline std::size_t decimalLength(const char* p, const char* end) {
  const char* q = p;
  if (q != end && *q == '-') ++q;
  auto word = [&](const char* w) {
    const char* r = q;
    for (; *w && r != end; ++w, ++r)
      if ((*r | 0x20) != *w) return false;
    return *w == '\0';
  };
  if (word("infinity")) return static_cast<std::size_t>(q + 8 - p);
  if (word("inf") || word("nan")) return static_cast<std::size_t>(q + 3 - p);
  auto digits = [&] {
    const char* s = q;
    while (q != end && *q >= '0' && *q <= '9') ++q;
    return q != s;
  };
  bool any = digits();
  if (q != end && *q == '.') {
    ++q;
    any = digits() || any;
  }
  if (!any) return 0;
  if (q != end && (*q == 'e' || *q == 'E')) {
    const char* mark = q++;
    if (q != end && (*q == '+' || *q == '-')) ++q;
    if (!digits()) q = mark;  // "1e" reads as 1
  }
  return static_cast<std::size_t>(q - p);
}

// a double from [first, last) in from_chars' general format
inline std::from_chars_result portableDoubleFromChars(const char* first, const char* last,
                                                      double& v) {
  const std::size_t n = decimalLength(first, last);
  if (n == 0) return {first, std::errc::invalid_argument};
  const std::string text(first, n);
  errno = 0;
  const double r = std::strtod(text.c_str(), nullptr);
  // strtod says ERANGE for an overflow (HUGE_VAL) and for an underflow to zero, both out of
  // range for from_chars (which then leaves v as it was); a subnormal result is in range
  if (errno == ERANGE && (std::isinf(r) || r == 0.0))
    return {first + n, std::errc::result_out_of_range};
  v = r;
  return {first + n, std::errc()};
}

#if defined(__cpp_lib_to_chars)
inline std::to_chars_result doubleToChars(char* first, char* last, double v) {
  return std::to_chars(first, last, v);
}
inline std::from_chars_result doubleFromChars(const char* first, const char* last, double& v) {
  return std::from_chars(first, last, v, std::chars_format::general);
}
#else
// the shortest decimal text that reads back as v (std::to_chars where there is one)
inline std::to_chars_result doubleToChars(char* first, char* last, double v) {
  return portableDoubleToChars(first, last, v);
}
// a double in from_chars' general format (std::from_chars where there is one)
inline std::from_chars_result doubleFromChars(const char* first, const char* last, double& v) {
  return portableDoubleFromChars(first, last, v);
}
#endif

}  // namespace convexloc::detail
