// convexloc — the exact integer and rational types of core (internal), and the exact
// conversions between them and doubles.
//
// Boost.Multiprecision over GMP where GMP is available (CMake option CONVEXLOC_USE_GMP, the
// native default), over its own header-only cpp_int otherwise (WebAssembly, and the test
// build that checks that path). Nothing else in core names a multiprecision library: code
// that needs exact numbers uses ExactInt and ExactRational from here, with Boost's generic
// operations (arithmetic, .sign(), numerator, denominator, msb, divide_qr, bit_test).
// These types allocate; the predicates use them only for extreme exponents (predicates.cpp).
#pragma once

#ifndef CONVEXLOC_USE_GMP
#error "CONVEXLOC_USE_GMP must be defined to 0 or 1 (core/CMakeLists.txt sets it)"
#endif

#if CONVEXLOC_USE_GMP
#include <boost/multiprecision/gmp.hpp>
#else
#include <boost/multiprecision/cpp_int.hpp>
#endif

#include <bit>
#include <cstdint>

#include "detail/bit_cast.hpp"

namespace convexloc::detail {

#if CONVEXLOC_USE_GMP
using ExactInt = boost::multiprecision::mpz_int;
using ExactRational = boost::multiprecision::mpq_rational;
#else
using ExactInt = boost::multiprecision::cpp_int;
using ExactRational = boost::multiprecision::cpp_rational;
#endif

// A finite non-zero double's bits: v = (negative ? -1 : 1) * significand * 2^exponent, with
// the integer significand below 2^53 and exponent the weight of its last place (-1074 for a
// subnormal). Read from the representation: std::frexp takes a slow path for subnormals,
// which the exact stages meet all the time.
struct DoubleParts {
  std::uint64_t significand;
  int exponent;
  bool negative;
};
inline DoubleParts doubleParts(double v) noexcept {
  const std::uint64_t bits = bit_cast<std::uint64_t>(v);
  const int field = static_cast<int>((bits >> 52) & 0x7ff);
  const std::uint64_t fraction = bits & ((std::uint64_t{1} << 52) - 1);
  if (field == 0) return {fraction, -1074, (bits >> 63) != 0};
  return {fraction | (std::uint64_t{1} << 52), field - 1075, (bits >> 63) != 0};
}

// the exponent of v's lowest set bit: v is an odd integer times 2^lowestSetBit(v) (v finite,
// non-zero); scaling by 2^-(the least of these) makes a set of doubles the smallest integers
inline int lowestSetBit(double v) noexcept {
  const DoubleParts p = doubleParts(v);
  return p.exponent + std::countr_zero(p.significand);
}

// the least lowestSetBit over the non-zero values (0 when all are zero): times 2^-(it) they
// are all integers, the smallest that they can be
template <class Doubles>
int commonLowestSetBit(const Doubles& values) noexcept {
  int lo = 0;
  bool any = false;
  for (double v : values) {
    if (v == 0.0) continue;
    const int e = lowestSetBit(v);
    if (!any || e < lo) lo = e;
    any = true;
  }
  return lo;
}

// out = v * 2^shift, for a finite v that it makes an integer; in place, so that an integer
// kept from call to call keeps its limbs
void setScaledInteger(ExactInt& out, double v, int shift);

// v * 2^shift as an exact integer, for a finite v that it makes an integer
ExactInt scaledInteger(double v, int shift);

// the finite double v as an exact rational
ExactRational exactRational(double v);

// b with |q| in [2^(b-1), 2^(b+1)) for a non-zero q: its exponent to within one
long binaryExponent(const ExactRational& q);

// q * 2^k, exactly
ExactRational timesPowerOfTwo(const ExactRational& q, long k);

// How a rational that is not a double becomes one.
enum class Rounding { Nearest, TowardZero };

// q as a double: to nearest (ties to even) or toward zero; +-infinity where |q| is beyond
// the largest double (toward zero: at least 2^1024), subnormals exact to their grid
double toDouble(const ExactRational& q, Rounding mode);

}  // namespace convexloc::detail
