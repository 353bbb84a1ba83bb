// convexloc — floating-point expansion arithmetic (internal): error-free transformations of
// doubles and the nonoverlapping expansions built from them, in the manner of Shewchuk,
// "Adaptive Precision Floating-Point Arithmetic and Fast Robust Geometric Predicates" (1997).
//
// An expansion is an array of doubles e[0..n) whose exact sum is the value it stands for,
// ordered by increasing magnitude, nonoverlapping (the lowest set bit of e[i+1] lies above
// the highest set bit of e[i]) and free of zeros; n == 0 stands for zero. Its sign is the
// sign of its last component.
//
// Every function here is exact under one condition, which the callers establish (see
// predicates.cpp): every value involved is an integer multiple of 2^-1074 and below 2^1020 in
// magnitude, the operands of a product below 2^996. Then no operation overflows, and an operation
// whose exact result is a multiple of 2^-1074 rounds exactly as it would with an unbounded exponent
// range (a multiple of 2^-1074 below 2^-1022 is a subnormal, represented exactly), so the theorems
// proven for an unbounded exponent (Knuth's two-sum, Dekker's fast two-sum and product, Shewchuk's
// expansion sum and scale, round to nearest even) hold as stated.
#pragma once

#include <cfloat>
#include <cmath>

#if !defined(FLT_EVAL_METHOD) || FLT_EVAL_METHOD != 0
#error "expansion arithmetic needs doubles evaluated in double precision (FLT_EVAL_METHOD 0)"
#endif

namespace convexloc::detail::expansion {

// === Error-free transformations

// s + e == a + b exactly, s the rounded sum (Knuth)
inline void twoSum(double a, double b, double& s, double& e) noexcept {
  s = a + b;
  const double bv = s - a;
  const double av = s - bv;
  e = (a - av) + (b - bv);
}

// s + e == a + b exactly, s the rounded sum, when |a| >= |b| (Dekker)
inline void fastTwoSum(double a, double b, double& s, double& e) noexcept {
  s = a + b;
  e = b - (s - a);
}

// s + e == a - b exactly, s the rounded difference
inline void twoDiff(double a, double b, double& s, double& e) noexcept {
  s = a - b;
  const double bv = a - s;
  const double av = s + bv;
  e = (a - av) + (bv - b);
}

#if !(defined(__FMA__) || defined(__ARM_FEATURE_FMA))
// a == hi + lo with hi and lo of at most 26 significant bits each (Veltkamp), |a| < 2^996
inline void split(double a, double& hi, double& lo) noexcept {
  const double c = 134217729.0 * a;  // 2^27 + 1
  const double big = c - a;
  hi = c - big;
  lo = a - hi;
}
#endif

// p + e == a * b exactly, p the rounded product: one fused multiply-add where the target
// has the instruction, Dekker's product of split halves otherwise (every step is exact,
// so a compiler that fuses some of them changes nothing)
inline void twoProduct(double a, double b, double& p, double& e) noexcept {
  p = a * b;
#if defined(__FMA__) || defined(__ARM_FEATURE_FMA)
  e = std::fma(a, b, -p);
#else
  double ah, al, bh, bl;
  split(a, ah, al);
  split(b, bh, bl);
  e = ((ah * bh - p) + ah * bl + al * bh) + al * bl;
#endif
}

// === Expansions (h never aliases an input; each returns the length of h)

// h = a - b as an expansion of at most 2 components
inline int difference(double a, double b, double* h) noexcept {
  double s, e;
  twoDiff(a, b, s, e);
  int n = 0;
  if (e != 0.0) h[n++] = e;
  if (s != 0.0) h[n++] = s;
  return n;
}

// h = e * b, at most 2n components (Shewchuk's scale-expansion, zeros dropped)
inline int scale(const double* e, int n, double b, double* h) noexcept {
  if (n == 0 || b == 0.0) return 0;
  int k = 0;
  double q, low;
  twoProduct(e[0], b, q, low);
  if (low != 0.0) h[k++] = low;
  for (int i = 1; i < n; ++i) {
    double p1, p0, sum, out;
    twoProduct(e[i], b, p1, p0);
    twoSum(q, p0, sum, out);
    if (out != 0.0) h[k++] = out;
    fastTwoSum(p1, sum, q, out);
    if (out != 0.0) h[k++] = out;
  }
  if (q != 0.0) h[k++] = q;
  return k;
}

// h = e + f, at most n + m components: merge by magnitude, then one pass of two-sums
// (Shewchuk's fast expansion sum, zeros dropped; it needs round to nearest even)
inline int sum(const double* e, int n, const double* f, int m, double* h) noexcept {
  int i = 0, j = 0, k = 0;
  // the next component of the merge, the smaller in magnitude first
  auto next = [&]() {
    if (j == m || (i < n && std::fabs(e[i]) < std::fabs(f[j]))) return e[i++];
    return f[j++];
  };
  if (n + m == 0) return 0;
  double q = next();
  if (i + j < n + m) {
    double s, out;
    fastTwoSum(next(), q, s, out);  // the second component is at least as large
    if (out != 0.0) h[k++] = out;
    q = s;
  }
  while (i + j < n + m) {
    double s, out;
    twoSum(q, next(), s, out);
    if (out != 0.0) h[k++] = out;
    q = s;
  }
  if (q != 0.0) h[k++] = q;
  return k;
}

// e = -e in place
inline void negate(double* e, int n) noexcept {
  for (int i = 0; i < n; ++i) e[i] = -e[i];
}

// h = e * f, at most 2 n m components; `scratch` holds 4 n m doubles
inline int product(const double* e, int n, const double* f, int m, double* h,
                   double* scratch) noexcept {
  if (m == 0) return 0;
  int len = scale(e, n, f[0], h);
  for (int j = 1; j < m; ++j) {
    double* part = scratch;
    double* acc = scratch + 2 * n;
    const int partLen = scale(e, n, f[j], part);
    for (int i = 0; i < len; ++i) acc[i] = h[i];
    len = sum(acc, len, part, partLen, h);
  }
  return len;
}

// the sign of an expansion: that of its largest component
inline int signOf(const double* e, int n) noexcept {
  if (n == 0) return 0;
  return e[n - 1] > 0 ? 1 : -1;
}

}  // namespace convexloc::detail::expansion
