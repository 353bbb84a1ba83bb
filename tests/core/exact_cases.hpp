// The cases of the exact-stage tests (test_exact_stage.cpp, test_exact_alloc.cpp): inputs
// built to defeat the filter, and the GMP rational reference they are checked against,
// which shares no code with core.
#pragma once

#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "convexloc/generate2d.hpp"
#include "convexloc/predicates.hpp"

namespace exact_cases {

using namespace convexloc;

struct Cross {
  Vec2 p0, p1, q0, q1;
};
struct Orient {
  Vec3 a, b, c, d;
};

// === The reference: GMP rationals

inline int sgn(const mpq_class& v) {
  return mpq_sgn(v.get_mpq_t());
}
inline mpq_class minus(double a, double b) {
  return mpq_class(a) - mpq_class(b);
}
inline int refCross(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1) {
  return sgn(
      mpq_class(minus(p1.x, p0.x) * minus(q1.y, q0.y) - minus(p1.y, p0.y) * minus(q1.x, q0.x)));
}
inline int refOrient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const mpq_class u[3] = {minus(a.x, d.x), minus(a.y, d.y), minus(a.z, d.z)};
  const mpq_class v[3] = {minus(b.x, d.x), minus(b.y, d.y), minus(b.z, d.z)};
  const mpq_class w[3] = {minus(c.x, d.x), minus(c.y, d.y), minus(c.z, d.z)};
  return sgn(mpq_class(u[0] * (v[1] * w[2] - v[2] * w[1]) + u[1] * (v[2] * w[0] - v[0] * w[2]) +
                       u[2] * (v[0] * w[1] - v[1] * w[0])));
}

// === Inputs

// a double with a random 53-bit mantissa, an exponent in [lo, hi] and a random sign
inline double wild(Rng& r, int lo, int hi) {
  const double m = 1 + r.uniform();
  const int e = lo + static_cast<int>(r.below(static_cast<std::uint64_t>(hi - lo + 1)));
  return (r.below(2) ? -1 : 1) * std::ldexp(m, e);
}
// a random integer in [-n, n]
inline double integer(Rng& r, std::uint64_t n) {
  return static_cast<double>(r.below(2 * n + 1)) - static_cast<double>(n);
}
// the double next to v, up or down at random
inline double ulpOff(Rng& r, double v) {
  return std::nextafter(v, r.below(2) ? HUGE_VAL : -HUGE_VAL);
}

// four points on a line of lattice points, times 2^s: the differences are exact
inline Cross latticeLine(Rng& r, int s) {
  const Vec2 o{integer(r, 1 << 30), integer(r, 1 << 30)}, d{integer(r, 1024), integer(r, 1024)};
  auto at = [&](double t) {
    return Vec2{std::ldexp(o.x + t * d.x, s), std::ldexp(o.y + t * d.y, s)};
  };
  return {at(integer(r, 1024)), at(integer(r, 1024)), at(integer(r, 1024)), at(integer(r, 1024))};
}
// four points on y = k x (k = 1, -1, 2 or 1/2) with full mantissas: the differences have tails
inline Cross diagonalLine(Rng& r, int lo, int hi) {
  const double k[] = {1, -1, 2, 0.5};
  const double slope = k[r.below(4)];
  auto at = [&]() {
    const double x = wild(r, lo, hi);
    return Vec2{x, slope * x};
  };
  return {at(), at(), at(), at()};
}
// four points of a lattice plane, times 2^s: the differences are exact
inline Orient latticePlane(Rng& r, int s) {
  const double o[3] = {integer(r, 1 << 30), integer(r, 1 << 30), integer(r, 1 << 30)};
  const double e[3] = {integer(r, 512), integer(r, 512), integer(r, 512)};
  const double f[3] = {integer(r, 512), integer(r, 512), integer(r, 512)};
  auto at = [&]() {
    const double i = integer(r, 512), j = integer(r, 512);
    return Vec3{std::ldexp(o[0] + i * e[0] + j * f[0], s),
                std::ldexp(o[1] + i * e[1] + j * f[1], s),
                std::ldexp(o[2] + i * e[2] + j * f[2], s)};
  };
  return {at(), at(), at(), at()};
}
// four points with one coordinate k times another (a plane through the origin's axis) and
// full mantissas: the determinant is 0 and the differences have tails
inline Orient columnPlane(Rng& r, int lo, int hi) {
  const double k[] = {1, -1, 2, 0.5};
  const double slope = k[r.below(4)];
  const int from = static_cast<int>(r.below(3)), to = (from + 1 + static_cast<int>(r.below(2))) % 3;
  auto at = [&]() {
    double c[3] = {wild(r, lo, hi), wild(r, lo, hi), wild(r, lo, hi)};
    c[to] = slope * c[from];
    return Vec3{c[0], c[1], c[2]};
  };
  return {at(), at(), at(), at()};
}
// coordinates at the narrow-integer stage's rim: a double in [2^60, 2^61) ([2^61, 2^62)
// when `beyond`), a small odd integer, or either at random; either sign
inline double rimBig(Rng& r, bool beyond) {
  return (r.below(2) ? -1 : 1) * std::ldexp(1 + r.uniform(), beyond ? 61 : 60);
}
inline double rimSmall(Rng& r) {
  return (r.below(2) ? -1 : 1) * (2 * static_cast<double>(r.below(1 << 20)) + 1);
}
inline double rimValue(Rng& r, bool beyond) {
  return r.below(2) ? rimBig(r, beyond) : rimSmall(r);
}
// four points of the rim, at random or all on the line y = x; the first two hold a big and
// a small odd coordinate, so that the span is 61 bits (62 when `beyond`)
inline Cross rimLine(Rng& r, bool beyond) {
  const bool line = r.below(2);
  auto at = [&](double x) { return Vec2{x, line ? x : rimValue(r, beyond)}; };
  return {at(rimBig(r, beyond)), at(rimSmall(r)), at(rimValue(r, beyond)), at(rimValue(r, beyond))};
}
// four points of the rim, at random or all on the plane z = x, spanning as above
inline Orient rimPlane(Rng& r, bool beyond) {
  const bool plane = r.below(2);
  auto at = [&](double x) { return Vec3{x, rimValue(r, beyond), plane ? x : rimValue(r, beyond)}; };
  return {at(rimBig(r, beyond)), at(rimSmall(r)), at(rimValue(r, beyond)), at(rimValue(r, beyond))};
}
// four points of a box: uniform coordinates in [lo, hi)
inline Cross boxLine(Rng& r, double lo, double hi) {
  auto at = [&] { return Vec2{r.uniform(lo, hi), r.uniform(lo, hi)}; };
  return {at(), at(), at(), at()};
}
inline Orient boxPlane(Rng& r, double lo, double hi) {
  auto at = [&] { return Vec3{r.uniform(lo, hi), r.uniform(lo, hi), r.uniform(lo, hi)}; };
  return {at(), at(), at(), at()};
}
inline Cross scaled(Cross c, int s) {
  auto f = [s](Vec2 p) { return Vec2{std::ldexp(p.x, s), std::ldexp(p.y, s)}; };
  return {f(c.p0), f(c.p1), f(c.q0), f(c.q1)};
}
inline Orient scaled(Orient o, int s) {
  auto f = [s](Vec3 p) { return Vec3{std::ldexp(p.x, s), std::ldexp(p.y, s), std::ldexp(p.z, s)}; };
  return {f(o.a), f(o.b), f(o.c), f(o.d)};
}

// === Checks

// the stages' counts since `from`
inline ExactStageCounts countsSince(const ExactStageCounts& from) {
  const ExactStageCounts now = exactStageCounts();
  return {now.narrowIntegers - from.narrowIntegers, now.expansions - from.expansions,
          now.multiprecision - from.multiprecision};
}

// every case through the exact stage against the reference; returns which stages decided
template <class Case, class Exact, class Ref>
ExactStageCounts expectAllMatch(const std::vector<Case>& cases, Exact exact, Ref ref) {
  const ExactStageCounts before = exactStageCounts();
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const int got = exact(cases[i]), want = ref(cases[i]);
    if (got != want) {
      ADD_FAILURE() << "case " << i << ": exact stage " << got << ", rational " << want;
      break;
    }
  }
  return countsSince(before);
}
inline int crossStage(const Cross& c) {
  return detail::crossExact(c.p0, c.p1, c.q0, c.q1);
}
inline int crossRef(const Cross& c) {
  return refCross(c.p0, c.p1, c.q0, c.q1);
}
inline int orientStage(const Orient& o) {
  return detail::orient3dExact(o.a, o.b, o.c, o.d);
}
inline int orientRef(const Orient& o) {
  return refOrient3d(o.a, o.b, o.c, o.d);
}

// n cases from a generator
template <class Make>
inline auto make(int n, Make f) {
  std::vector<decltype(f())> out;
  for (int i = 0; i < n; ++i) out.push_back(f());
  return out;
}

inline constexpr int kCases = 20000;

}  // namespace exact_cases
