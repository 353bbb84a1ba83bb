// convexloc — the narrow-integer stage of the exact predicates (internal).
//
// Most coordinates that defeat the filter are close in scale: CAD lattices, points in one
// box. Let 2^E <= max |v| < 2^(E+1) over the coordinates. Where every coordinate is an
// integer multiple of 2^(E-60) (the span from the lowest set bit to the highest leading bit
// is at most 61 bits), the coordinates times 2^(60-E) are integers below 2^61; their
// differences fit in 62 bits, the 2x2 minors in 125 (Int128), the 3x3 determinant in 189
// (three 64-bit limbs). Everything is exact integer arithmetic, a few dozen instructions,
// and nothing is allocated. Otherwise the stage declines, and the expansions of
// predicates.cpp decide.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <initializer_list>

#include "convexloc/geometry.hpp"
#include "detail/bit_cast.hpp"

#ifndef __SIZEOF_INT128__
#error "the narrow-integer stage needs __int128 (GCC and Clang have it, WebAssembly included)"
#endif

namespace convexloc::detail::narrow {

__extension__ typedef __int128 Int128;
__extension__ typedef unsigned __int128 Uint128;

// the bit pattern of |v|: ordered as the magnitudes are, for finite v
inline std::uint64_t magnitudeBits(double v) noexcept {
  return detail::bit_cast<std::uint64_t>(v) & ~(1ULL << 63);
}

// The largest and the smallest non-zero magnitude of a set of doubles, as bit patterns
// (scalar code: the values stay in registers).
class Magnitudes {
 public:
  Magnitudes(std::initializer_list<double> values) noexcept {
    for (double v : values) {
      const std::uint64_t m = magnitudeBits(v);
      largest_ = std::max(largest_, m);
      smallestLess1_ = std::min(smallestLess1_, m - 1);  // a zero wraps to the top
    }
  }
  // whether every non-zero value is a normal double with 2^lo <= |v| < 2^(hi+1)
  bool within(int lo, int hi) const noexcept {
    return largest_ == 0 ||
           (biased(largest_) <= hi + 1023 && biased(smallestLess1_ + 1) >= lo + 1023);
  }
  // The scale 2^(60 - E), E the largest magnitude's exponent: every value times it is below
  // 2^61 in magnitude and, if not zero, at least 1/2 (a normal double: the product is exact).
  // 0 (the stage declines) where all are zero, E is outside [-900, 900], or a value below
  // 2^(E-61), which cannot be an integer at this scale.
  double scale() const noexcept {
    const int e = biased(largest_);
    if (largest_ == 0 || e < 1023 - 900 || e > 1023 + 900) return 0.0;
    if (biased(smallestLess1_ + 1) < e - 61) return 0.0;
    return detail::bit_cast<double>(static_cast<std::uint64_t>(2 * 1023 + 60 - e) << 52);
  }

 private:
  static int biased(std::uint64_t m) noexcept { return static_cast<int>(m >> 52); }
  std::uint64_t largest_ = 0, smallestLess1_ = ~std::uint64_t{0};
};

// v * scale as an integer (|v * scale| < 2^61, so the conversion is defined); `exact` is
// cleared where v * scale, exact for Magnitudes::scale, is not an integer
inline std::int64_t toInteger(double v, double scale, bool& exact) noexcept {
  const double t = v * scale;
  const auto i = static_cast<std::int64_t>(t);
  exact &= static_cast<double>(i) == t;
  return i;
}

// what cross and orient3d return when a coordinate is not an integer at their scale
inline constexpr int kDeclined = 2;

// a 192-bit two's complement accumulator of products of an Int128 and an int64
class Wide {
 public:
  // adds m * u, |m| < 2^125 and |u| < 2^62 (without branches: the signs are masks)
  void addProduct(Int128 m, std::int64_t u) noexcept {
    const Uint128 mSign = Uint128(m >> 127);
    const std::uint64_t uSign = std::uint64_t(u >> 63);
    const Uint128 am = (Uint128(m) ^ mSign) - mSign;
    const std::uint64_t au = (std::uint64_t(u) ^ uSign) - uSign;
    const Uint128 lo = Uint128(std::uint64_t(am)) * au;
    const Uint128 hi = Uint128(std::uint64_t(am >> 64)) * au;
    const Uint128 mid = (lo >> 64) + std::uint64_t(hi);
    // the magnitude's limbs, complemented where the product is negative: -p = ~p + 1
    const std::uint64_t flip = std::uint64_t(mSign) ^ uSign;
    const std::uint64_t p0 = std::uint64_t(lo) ^ flip, p1 = std::uint64_t(mid) ^ flip,
                        p2 = (std::uint64_t(hi >> 64) + std::uint64_t(mid >> 64)) ^ flip;
    Uint128 s = Uint128(w0_) + p0 + (flip & 1);
    w0_ = std::uint64_t(s);
    s = Uint128(w1_) + p1 + std::uint64_t(s >> 64);
    w1_ = std::uint64_t(s);
    w2_ += p2 + std::uint64_t(s >> 64);
  }
  // the sign of the sum (|sum| < 2^190)
  int sign() const noexcept {
    if (static_cast<std::int64_t>(w2_) < 0) return -1;
    return (w0_ | w1_ | w2_) != 0 ? 1 : 0;
  }

 private:
  std::uint64_t w0_ = 0, w1_ = 0, w2_ = 0;
};

// sign of (p1 - p0) x (q1 - q0), or kDeclined; m: the Magnitudes of the eight coordinates
inline int cross(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1, const Magnitudes& m) noexcept {
  const double scale = m.scale();
  if (scale == 0.0) return kDeclined;
  bool exact = true;
  auto z = [&](double v) { return toInteger(v, scale, exact); };
  const std::int64_t px = z(p1.x) - z(p0.x), py = z(p1.y) - z(p0.y);
  const std::int64_t qx = z(q1.x) - z(q0.x), qy = z(q1.y) - z(q0.y);
  if (!exact) return kDeclined;
  const Int128 det = Int128(px) * qy - Int128(py) * qx;
  return (det > 0) - (det < 0);
}

// sign of det[a-d; b-d; c-d], or kDeclined; m: the Magnitudes of the twelve coordinates
inline int orient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d, const Magnitudes& m) noexcept {
  const double scale = m.scale();
  if (scale == 0.0) return kDeclined;
  bool exact = true;
  auto z = [&](double v) { return toInteger(v, scale, exact); };
  const std::int64_t dx = z(d.x), dy = z(d.y), dz = z(d.z);
  const std::int64_t ux = z(a.x) - dx, uy = z(a.y) - dy, uz = z(a.z) - dz;
  const std::int64_t vx = z(b.x) - dx, vy = z(b.y) - dy, vz = z(b.z) - dz;
  const std::int64_t wx = z(c.x) - dx, wy = z(c.y) - dy, wz = z(c.z) - dz;
  if (!exact) return kDeclined;
  Wide det;
  det.addProduct(Int128(vy) * wz - Int128(vz) * wy, ux);
  det.addProduct(Int128(vz) * wx - Int128(vx) * wz, uy);
  det.addProduct(Int128(vx) * wy - Int128(vy) * wx, uz);
  return det.sign();
}

}  // namespace convexloc::detail::narrow
