// convexloc — exact predicates: a double-precision filter with a proven bound, and an
// exact integer fallback for the rare cases the filter cannot decide.
#include "convexloc/predicates.hpp"

#include <gmpxx.h>

#include <array>
#include <cmath>

namespace convexloc {
namespace {

thread_local unsigned long long tFallbacks = 0;

// exponent of the least significant bit of a non-zero double
int lowBit(double v) {
  int e = 0;
  std::frexp(v, &e);
  return e - 53;
}

// smallest lsb exponent over the non-zero values, so that all scale to integers
template <std::size_t K>
int commonLowBit(const std::array<double, K>& vals) {
  int lo = 0;
  bool any = false;
  for (double v : vals) {
    if (v == 0.0) continue;
    int b = lowBit(v);
    if (!any || b < lo) lo = b;
    any = true;
  }
  return lo;
}

// v * 2^-lo as an exact integer
void scaled(mpz_class& out, double v, int lo) {
  int e = 0;
  double m = std::frexp(v, &e);
  mpz_set_d(out.get_mpz_t(), std::ldexp(m, 53));  // |m| < 1, so this is an exact integer
  int shift = e - 53 - lo;
  if (shift > 0) mpz_mul_2exp(out.get_mpz_t(), out.get_mpz_t(), static_cast<mp_bitcnt_t>(shift));
}

int sign(const mpz_class& v) {
  return mpz_sgn(v.get_mpz_t());
}

}  // namespace

int detail::crossExact(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1) noexcept {
  ++tFallbacks;
  thread_local std::array<mpz_class, 8> z;
  std::array<double, 8> in{p0.x, p0.y, p1.x, p1.y, q0.x, q0.y, q1.x, q1.y};
  int lo = commonLowBit(in);
  for (std::size_t i = 0; i < in.size(); ++i) scaled(z[i], in[i], lo);
  // (p1x - p0x) * (q1y - q0y) - (p1y - p0y) * (q1x - q0x)
  z[2] -= z[0];
  z[3] -= z[1];
  z[6] -= z[4];
  z[7] -= z[5];
  z[0] = z[2] * z[7];
  z[1] = z[3] * z[6];
  z[0] -= z[1];
  return sign(z[0]);
}

// exact sign of det[a-d; b-d; c-d]
int detail::orient3dExact(Vec3 a, Vec3 b, Vec3 c, Vec3 d) noexcept {
  ++tFallbacks;
  thread_local std::array<mpz_class, 12> z;
  thread_local std::array<mpz_class, 3> t;
  std::array<double, 12> in{a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z};
  int lo = commonLowBit(in);
  for (std::size_t i = 0; i < in.size(); ++i) scaled(z[i], in[i], lo);
  for (std::size_t i = 0; i < 9; ++i) z[i] -= z[9 + i % 3];
  // rows (z0 z1 z2), (z3 z4 z5), (z6 z7 z8), expanded along the first row; every step
  // writes into a thread-local integer, so a warm fallback allocates nothing
  auto m = [](mpz_class& v) { return v.get_mpz_t(); };
  auto minor = [&](mpz_class& out, int p, int q, int r, int s) {
    mpz_mul(m(out), m(z[p]), m(z[q]));
    mpz_submul(m(out), m(z[r]), m(z[s]));
  };
  minor(t[0], 4, 8, 5, 7);
  minor(t[1], 5, 6, 3, 8);
  mpz_mul(m(t[2]), m(t[0]), m(z[0]));
  mpz_addmul(m(t[2]), m(t[1]), m(z[1]));
  minor(t[0], 3, 7, 4, 6);
  mpz_addmul(m(t[2]), m(t[0]), m(z[2]));
  return sign(t[2]);
}

unsigned long long exactFallbackCount() noexcept {
  return tFallbacks;
}

}  // namespace convexloc
