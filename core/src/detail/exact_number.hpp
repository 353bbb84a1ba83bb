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

namespace convexloc::detail {

#if CONVEXLOC_USE_GMP
using ExactInt = boost::multiprecision::mpz_int;
using ExactRational = boost::multiprecision::mpq_rational;
#else
using ExactInt = boost::multiprecision::cpp_int;
using ExactRational = boost::multiprecision::cpp_rational;
#endif

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
