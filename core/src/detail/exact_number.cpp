// convexloc — exact conversions between doubles and the exact number types (exact_number.hpp).
#include "detail/exact_number.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>

namespace convexloc::detail {
namespace {

// the number of bits of a non-negative integer (0 for 0)
long bitLength(const ExactInt& v) {
  return v == 0 ? 0 : static_cast<long>(boost::multiprecision::msb(v)) + 1;
}

}  // namespace

void setScaledInteger(ExactInt& out, double v, int shift) {
  if (v == 0.0) {
    out = 0u;
    return;
  }
  const DoubleParts d = doubleParts(v);
  out = d.significand;
  const int k = d.exponent + shift;
  if (k > 0) out <<= static_cast<unsigned>(k);
  if (k < 0) out >>= static_cast<unsigned>(-k);  // the caller's shift leaves no fraction
  if (d.negative) out.backend().negate();
}

ExactInt scaledInteger(double v, int shift) {
  ExactInt out;
  setScaledInteger(out, v, shift);
  return out;
}

ExactRational exactRational(double v) {
  if (v == 0.0) return ExactRational(0);
  DoubleParts d = doubleParts(v);
  // an odd significand over a power of two is already in lowest terms
  const int zeros = std::min(std::countr_zero(d.significand), std::max(0, -d.exponent));
  d.significand >>= zeros;
  d.exponent += zeros;
  ExactInt num(d.significand);
  if (d.negative) num = -num;
  if (d.exponent >= 0) return ExactRational(ExactInt(num << static_cast<unsigned>(d.exponent)));
  return ExactRational(num, ExactInt(ExactInt(1) << static_cast<unsigned>(-d.exponent)));
}

long binaryExponent(const ExactRational& q) {
  return bitLength(abs(numerator(q))) - bitLength(denominator(q));
}

ExactRational timesPowerOfTwo(const ExactRational& q, long k) {
  if (k >= 0)
    return ExactRational(ExactInt(numerator(q) << static_cast<unsigned>(k)), denominator(q));
  return ExactRational(numerator(q), ExactInt(denominator(q) << static_cast<unsigned>(-k)));
}

double toDouble(const ExactRational& q, Rounding mode) {
  const int sign = q.sign();
  if (sign == 0) return 0.0;
  const ExactInt num = abs(numerator(q)), den = denominator(q);
  const long bits = bitLength(num) - bitLength(den);
  if (bits > 1100) return sign * HUGE_VAL;
  // the quotient num / den / 2^exponent then has 53 or 54 bits, or fewer for a subnormal
  long exponent = std::max(bits - 53, -1074L);
  ExactInt m, r, scaledNum, scaledDen;
  for (int pass = 0; pass < 2; ++pass) {
    scaledNum = num;
    scaledDen = den;
    if (exponent >= 0)
      scaledDen <<= static_cast<unsigned>(exponent);
    else
      scaledNum <<= static_cast<unsigned>(-exponent);
    boost::multiprecision::divide_qr(scaledNum, scaledDen, m, r);
    if (bitLength(m) <= 53) break;
    ++exponent;  // 54 bits: one more halving leaves 53
  }
  if (mode == Rounding::Nearest) {
    const int half = ExactInt(r * 2).compare(scaledDen);
    if (half > 0 || (half == 0 && boost::multiprecision::bit_test(m, 0))) ++m;
  }
  const double mantissa = static_cast<double>(m.convert_to<std::uint64_t>());  // at most 2^53
  return sign * std::ldexp(mantissa, static_cast<int>(exponent));
}

}  // namespace convexloc::detail
