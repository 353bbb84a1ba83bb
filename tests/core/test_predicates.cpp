// orient2d / orient3d against a plain rational evaluation (GMP mpq), which shares no code
// with the filter or the integer fallback in core.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <utility>

#include "convexloc/generate2d.hpp"
#include "convexloc/predicates.hpp"
#include "scale.hpp"

using namespace convexloc;

namespace {

int sgn(const mpq_class& v) {
  return mpq_sgn(v.get_mpq_t());
}

int refOrient2d(Vec2 a, Vec2 b, Vec2 c) {
  mpq_class ax(a.x), ay(a.y), bx(b.x), by(b.y), cx(c.x), cy(c.y);
  return sgn(mpq_class((ax - cx) * (by - cy) - (ay - cy) * (bx - cx)));
}

int refOrient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  mpq_class m[3][3] = {{mpq_class(a.x) - d.x, mpq_class(a.y) - d.y, mpq_class(a.z) - d.z},
                       {mpq_class(b.x) - d.x, mpq_class(b.y) - d.y, mpq_class(b.z) - d.z},
                       {mpq_class(c.x) - d.x, mpq_class(c.y) - d.y, mpq_class(c.z) - d.z}};
  mpq_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                  m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                  m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return sgn(det);
}

// a double with a random exponent in [lo, hi] and a random sign
double wild(Rng& r, int lo, int hi) {
  double m = 1 + r.uniform();
  int e = lo + static_cast<int>(r.below(static_cast<std::uint64_t>(hi - lo + 1)));
  return (r.below(2) ? -1 : 1) * std::ldexp(m, e);
}

// a point of wild coordinates
Vec3 wildPoint(Rng& r, int lo, int hi) {
  return {wild(r, lo, hi), wild(r, lo, hi), wild(r, lo, hi)};
}

// round i's exponent range: ordinary, tiny (subnormal included), huge, or all of them
std::pair<int, int> exponentRange(int i) {
  if (i % 5 == 1) return {-1074, -900};
  if (i % 5 == 2) return {900, 1023};
  if (i % 5 == 3) return {-1074, 1023};
  return {-20, 20};
}

}  // namespace

TEST(Orient2d, SimpleTurns) {
  EXPECT_EQ(orient2d({0, 0}, {1, 0}, {0, 1}), 1);
  EXPECT_EQ(orient2d({0, 0}, {0, 1}, {1, 0}), -1);
  EXPECT_EQ(orient2d({0, 0}, {1, 1}, {2, 2}), 0);
  EXPECT_EQ(orient2d({0.5, 0.5}, {12, 12}, {24, 24}), 0);
}

TEST(Orient2d, NearlyCollinearMatchesRational) {
  // points one ulp off the line y = x at many scales: the filter alone would guess
  Rng r(11);
  for (int i = 0; i < 200000; ++i) {
    double s = std::ldexp(1.0, static_cast<int>(r.below(200)) - 100);
    Vec2 a{s * r.uniform(), 0}, b{s * r.uniform(), 0};
    a.y = a.x;
    b.y = b.x;
    Vec2 c{s * r.uniform(), 0};
    c.y = c.x;
    switch (r.below(3)) {
      case 0: c.y = std::nextafter(c.y, 1e300); break;
      case 1: c.y = std::nextafter(c.y, -1e300); break;
      default: break;
    }
    ASSERT_EQ(orient2d(a, b, c), refOrient2d(a, b, c)) << a.x << ' ' << b.x << ' ' << c.x;
  }
}

TEST(Orient2d, ExtremeMagnitudesMatchRational) {
  // subnormals, huge values and overflow of the products all take the exact path
  Rng r(12);
  const int ranges[][2] = {{-1074, -1000}, {-600, -400}, {-10, 10},
                           {400, 600},     {1000, 1023}, {-1074, 1023}};
  for (auto [lo, hi] : ranges)
    for (int i = 0; i < 20000; ++i) {
      Vec2 a{wild(r, lo, hi), wild(r, lo, hi)}, b{wild(r, lo, hi), wild(r, lo, hi)};
      Vec2 c = r.below(4) == 0 ? Vec2{a.x, b.y} : Vec2{wild(r, lo, hi), wild(r, lo, hi)};
      ASSERT_EQ(orient2d(a, b, c), refOrient2d(a, b, c)) << lo << ' ' << hi;
    }
  const double tiny = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(orient2d({0, 0}, {tiny, tiny}, {2 * tiny, 2 * tiny}), 0);
  EXPECT_EQ(orient2d({0, 0}, {tiny, 0}, {0, tiny}), 1);
  const double big = std::numeric_limits<double>::max();
  EXPECT_EQ(orient2d({-big, -big}, {big, -big}, {0, big}), 1);
  EXPECT_EQ(orient2d({-big, -big}, {big, big}, {0, 0}), 0);
}

TEST(CrossDiff2d, MatchesOrientWhenSharingAPoint) {
  Rng r(13);
  for (int i = 0; i < 10000; ++i) {
    Vec2 a{r.uniform(), r.uniform()}, b{r.uniform(), r.uniform()}, c{r.uniform(), r.uniform()};
    ASSERT_EQ(crossDiff2d(a, b, a, c), orient2d(b, c, a));
  }
}

TEST(Orient3d, MatchesRational) {
  Rng r(14);
  for (int i = 0; i < 100000; ++i) {
    const auto [lo, hi] = exponentRange(i);
    const Vec3 a = wildPoint(r, lo, hi), b = wildPoint(r, lo, hi), c = wildPoint(r, lo, hi);
    Vec3 d = wildPoint(r, lo, hi);
    if (i % 5 == 4) d = {a.x + (b.x - a.x) * 0.5, a.y + (b.y - a.y) * 0.5, a.z + (b.z - a.z) * 0.5};
    ASSERT_EQ(orient3d(a, b, c, d), refOrient3d(a, b, c, d)) << i;
  }
  EXPECT_EQ(orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, 0}), 0);
  EXPECT_EQ(orient3d({0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0.25, 0.25, -1}), 1);
}

// a coordinate from a mixture of scales: zero, a few subnormal steps, tiny, small, ordinary,
// and up to 2^249, where orient3d's filter takes underflow into account (predicates.cpp,
// orient3dUntame) rather than handing every untame difference to the exact stage
double mixed(Rng& r) {
  const double sign = r.below(2) ? -1 : 1;
  switch (r.below(7)) {
    case 0: return 0.0;
    case 1: return sign * std::ldexp(static_cast<double>(1 + r.below(8)), -1074);
    case 2: return wild(r, -1074, -1000);
    case 3: return wild(r, -600, -400);
    case 4: return wild(r, 200, 249);
    default: return wild(r, -20, 20);
  }
}

TEST(Orient3d, SmallDifferencesBesideOrdinaryOnesMatchRational) {
  Rng r(16);
  const int rounds = static_cast<int>(testscale::scaled(200000, 20000));  // fewer under ASan
  for (int i = 0; i < rounds; ++i) {
    const Vec3 a{mixed(r), mixed(r), mixed(r)}, b{mixed(r), mixed(r), mixed(r)},
        c{mixed(r), mixed(r), mixed(r)};
    Vec3 d{mixed(r), mixed(r), mixed(r)};
    // d on a face in the plane z = 0, or one to a few subnormal steps off it
    if (i % 4 == 1) {
      const Vec3 a0{a.x, a.y, 0}, b0{b.x, b.y, 0}, c0{c.x, c.y, 0};
      d.z = i % 8 == 1 ? 0.0 : std::ldexp(static_cast<double>(r.below(5)) - 2, -1074);
      ASSERT_EQ(orient3d(a0, b0, c0, d), refOrient3d(a0, b0, c0, d)) << i;
      continue;
    }
    // d on the line through a and b, rounded: on the plane or a rounding off it
    if (i % 4 == 2) d = {a.x * 0.5 + b.x * 0.5, a.y * 0.5 + b.y * 0.5, a.z * 0.5 + b.z * 0.5};
    ASSERT_EQ(orient3d(a, b, c, d), refOrient3d(a, b, c, d)) << i;
  }
  // a part on its ground plane and a point one subnormal step below it: untame differences,
  // a determinant far from zero, decided without the exact stage
  const unsigned long long before = exactFallbackCount();
  const double step = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(orient3d({0, 0, 0}, {8000, 0, 0}, {0, 8000, 0}, {10, 10, -step}), 1);
  EXPECT_EQ(orient3d({0, 0, 0}, {8000, 0, 0}, {0, 0, 40}, {10, -step, 10}), -1);
  EXPECT_EQ(exactFallbackCount(), before);
  // a triangle of area 2^-1000 and a point a step off its plane: the determinant underflows
  // to zero in doubles and is not zero
  const double t = 0x1p-500;
  EXPECT_EQ(orient3d({0, 0, 0}, {t, 0, 0}, {0, t, 0}, {0, 0, -step}), 1);
  EXPECT_EQ(orient3d({0, 0, 0}, {t, 0, 0}, {0, t, 0}, {0, 0, step}), -1);
  EXPECT_EQ(orient3d({0, 0, 0}, {t, 0, 0}, {0, t, 0}, {t, t, 0}), 0);
}

TEST(Orient2d, SmallDifferencesBesideOrdinaryOnesMatchRational) {
  Rng r(17);
  const int rounds = static_cast<int>(testscale::scaled(200000, 20000));  // fewer under ASan
  for (int i = 0; i < rounds; ++i) {
    const Vec2 a{mixed(r), mixed(r)}, b{mixed(r), mixed(r)};
    Vec2 c{mixed(r), mixed(r)};
    // c on an edge along the x axis, or one to a few subnormal steps off it
    if (i % 3 == 1) {
      const Vec2 a0{a.x, 0}, b0{b.x, 0};
      c.y = i % 6 == 1 ? 0.0 : std::ldexp(static_cast<double>(r.below(5)) - 2, -1074);
      ASSERT_EQ(orient2d(a0, b0, c), refOrient2d(a0, b0, c)) << i;
      continue;
    }
    // c the rounded midpoint of a and b: on the line or a rounding off it
    if (i % 3 == 2) c = {a.x * 0.5 + b.x * 0.5, a.y * 0.5 + b.y * 0.5};
    ASSERT_EQ(orient2d(a, b, c), refOrient2d(a, b, c)) << i;
  }
  // an edge on the x axis and a point one subnormal step above it: decided by the filter
  const unsigned long long before = exactFallbackCount();
  const double step = std::numeric_limits<double>::denorm_min();
  EXPECT_EQ(orient2d({0, 0}, {8000, 0}, {10, step}), 1);
  EXPECT_EQ(orient2d({0, 0}, {8000, 0}, {10, -step}), -1);
  EXPECT_EQ(exactFallbackCount(), before);
  // an edge 2^-500 long and a point a step off it: the cross product underflows to zero
  EXPECT_EQ(orient2d({0, 0}, {0x1p-500, 0}, {0x1p-501, step}), 1);
  EXPECT_EQ(orient2d({0, 0}, {0x1p-500, 0}, {0x1p-501, 0}), 0);
}

TEST(Orient3d, AroundAnAxisMatchesRational) {
  // Orient3dAround(a, b, d)(k) = orient3d(a, b, k, d), the cross product computed once: many
  // k per (a, b, d), at every scale, on the plane through a, b and d and one ulp off it
  Rng r(15);
  for (int i = 0; i < 2000; ++i) {
    const auto [lo, hi] = exponentRange(i);
    const Vec3 a = wildPoint(r, lo, hi), b = wildPoint(r, lo, hi), d = wildPoint(r, lo, hi);
    const detail::Orient3dAround around(a, b, d);
    for (int j = 0; j < 16; ++j) {
      Vec3 k = wildPoint(r, lo, hi);
      if (j % 4 == 1) k = a;
      if (j % 4 == 2) k = {d.x * 0.5 + b.x * 0.5, d.y * 0.5 + b.y * 0.5, d.z * 0.5 + b.z * 0.5};
      if (j % 4 == 3)
        k = {a.x * 0.75 + b.x * 0.25, a.y * 0.75 + b.y * 0.25, a.z * 0.75 + b.z * 0.25};
      if (j % 8 >= 4) k.z = std::nextafter(k.z, r.below(2) ? 1e300 : -1e300);
      ASSERT_TRUE(std::isfinite(k.x) && std::isfinite(k.y) && std::isfinite(k.z));
      ASSERT_EQ(around(k), refOrient3d(a, b, k, d)) << i << ' ' << j;
      ASSERT_EQ(around(k), orient3d(a, b, k, d)) << i << ' ' << j;
    }
  }
  // an axis through the origin and points around it, as a fan's bisection asks
  const detail::Orient3dAround axis({0, 0, 0}, {0, 0, 1}, {1, 0, 0.5});
  EXPECT_EQ(axis({1, 1, 7}), orient3d({0, 0, 0}, {0, 0, 1}, {1, 1, 7}, {1, 0, 0.5}));
  EXPECT_EQ(axis({2, 0, -3}), 0);
  EXPECT_EQ(axis({2, std::nextafter(0.0, 1.0), -3}),
            orient3d({0, 0, 0}, {0, 0, 1}, {2, 4.9e-324, -3}, {1, 0, 0.5}));
}
