// The exact stage of the predicates (detail::crossExact, detail::orient3dExact), called
// directly so that the filter decides nothing, against GMP rationals, which share no code
// with it: random, collinear and coplanar by construction (with exact and with inexact
// differences), one ulp off, huge, subnormal, mixed and 2^+-700 inputs. Over the ordinary
// exponent range the stage must allocate nothing: this binary counts every operator new and
// every GMP allocation.
#include <gmpxx.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <limits>
#include <new>
#include <utility>
#include <vector>

#include "convexloc/generate2d.hpp"
#include "convexloc/predicates.hpp"

namespace {
thread_local unsigned long long tAllocations = 0;
}  // namespace

// every allocation of this binary counted, then served by malloc
void* operator new(std::size_t n) {
  ++tAllocations;
  if (void* p = std::malloc(n ? n : 1)) return p;
  throw std::bad_alloc();
}
void operator delete(void* p) noexcept {
  std::free(p);
}
void operator delete(void* p, std::size_t) noexcept {
  std::free(p);
}

using namespace convexloc;

namespace {

// === Counting allocations (operator new above, GMP's through its memory functions)

void* (*gmpAlloc)(std::size_t);
void* (*gmpRealloc)(void*, std::size_t, std::size_t);
void (*gmpFree)(void*, std::size_t);
void* countedAlloc(std::size_t n) {
  ++tAllocations;
  return gmpAlloc(n);
}
void* countedRealloc(void* p, std::size_t from, std::size_t to) {
  ++tAllocations;
  return gmpRealloc(p, from, to);
}

// the allocations made in this thread while it lives
class AllocationCount {
 public:
  AllocationCount() : start_(tAllocations) {
    mp_get_memory_functions(&gmpAlloc, &gmpRealloc, &gmpFree);
    mp_set_memory_functions(countedAlloc, countedRealloc, gmpFree);
  }
  ~AllocationCount() { mp_set_memory_functions(gmpAlloc, gmpRealloc, gmpFree); }
  AllocationCount(const AllocationCount&) = delete;
  AllocationCount& operator=(const AllocationCount&) = delete;
  unsigned long long count() const { return tAllocations - start_; }

 private:
  unsigned long long start_;
};

// === The reference: GMP rationals

int sgn(const mpq_class& v) {
  return mpq_sgn(v.get_mpq_t());
}
mpq_class minus(double a, double b) {
  return mpq_class(a) - mpq_class(b);
}
int refCross(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1) {
  return sgn(
      mpq_class(minus(p1.x, p0.x) * minus(q1.y, q0.y) - minus(p1.y, p0.y) * minus(q1.x, q0.x)));
}
int refOrient3d(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const mpq_class u[3] = {minus(a.x, d.x), minus(a.y, d.y), minus(a.z, d.z)};
  const mpq_class v[3] = {minus(b.x, d.x), minus(b.y, d.y), minus(b.z, d.z)};
  const mpq_class w[3] = {minus(c.x, d.x), minus(c.y, d.y), minus(c.z, d.z)};
  return sgn(mpq_class(u[0] * (v[1] * w[2] - v[2] * w[1]) + u[1] * (v[2] * w[0] - v[0] * w[2]) +
                       u[2] * (v[0] * w[1] - v[1] * w[0])));
}

// === Inputs

struct Cross {
  Vec2 p0, p1, q0, q1;
};
struct Orient {
  Vec3 a, b, c, d;
};

// a double with a random 53-bit mantissa, an exponent in [lo, hi] and a random sign
double wild(Rng& r, int lo, int hi) {
  const double m = 1 + r.uniform();
  const int e = lo + static_cast<int>(r.below(static_cast<std::uint64_t>(hi - lo + 1)));
  return (r.below(2) ? -1 : 1) * std::ldexp(m, e);
}
// a random integer in [-n, n]
double integer(Rng& r, std::uint64_t n) {
  return static_cast<double>(r.below(2 * n + 1)) - static_cast<double>(n);
}
// the double next to v, up or down at random
double ulpOff(Rng& r, double v) {
  return std::nextafter(v, r.below(2) ? HUGE_VAL : -HUGE_VAL);
}

// four points on a line of lattice points, times 2^s: the differences are exact
Cross latticeLine(Rng& r, int s) {
  const Vec2 o{integer(r, 1 << 30), integer(r, 1 << 30)}, d{integer(r, 1024), integer(r, 1024)};
  auto at = [&](double t) {
    return Vec2{std::ldexp(o.x + t * d.x, s), std::ldexp(o.y + t * d.y, s)};
  };
  return {at(integer(r, 1024)), at(integer(r, 1024)), at(integer(r, 1024)), at(integer(r, 1024))};
}
// four points on y = k x (k = 1, -1, 2 or 1/2) with full mantissas: the differences have tails
Cross diagonalLine(Rng& r, int lo, int hi) {
  const double k[] = {1, -1, 2, 0.5};
  const double slope = k[r.below(4)];
  auto at = [&]() {
    const double x = wild(r, lo, hi);
    return Vec2{x, slope * x};
  };
  return {at(), at(), at(), at()};
}
// four points of a lattice plane, times 2^s: the differences are exact
Orient latticePlane(Rng& r, int s) {
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
Orient columnPlane(Rng& r, int lo, int hi) {
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
Cross scaled(Cross c, int s) {
  auto f = [s](Vec2 p) { return Vec2{std::ldexp(p.x, s), std::ldexp(p.y, s)}; };
  return {f(c.p0), f(c.p1), f(c.q0), f(c.q1)};
}
Orient scaled(Orient o, int s) {
  auto f = [s](Vec3 p) { return Vec3{std::ldexp(p.x, s), std::ldexp(p.y, s), std::ldexp(p.z, s)}; };
  return {f(o.a), f(o.b), f(o.c), f(o.d)};
}

// === Checks

// every case against the reference; returns how many needed multiprecision integers
template <class Case, class Exact, class Ref>
unsigned long long expectAllMatch(const std::vector<Case>& cases, Exact exact, Ref ref) {
  const unsigned long long before = multiprecisionFallbackCount();
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const int got = exact(cases[i]), want = ref(cases[i]);
    if (got != want) {
      ADD_FAILURE() << "case " << i << ": exact stage " << got << ", rational " << want;
      break;
    }
  }
  return multiprecisionFallbackCount() - before;
}
int crossStage(const Cross& c) {
  return detail::crossExact(c.p0, c.p1, c.q0, c.q1);
}
int crossRef(const Cross& c) {
  return refCross(c.p0, c.p1, c.q0, c.q1);
}
int orientStage(const Orient& o) {
  return detail::orient3dExact(o.a, o.b, o.c, o.d);
}
int orientRef(const Orient& o) {
  return refOrient3d(o.a, o.b, o.c, o.d);
}

// n cases from a generator
template <class Make>
auto make(int n, Make f) {
  std::vector<decltype(f())> out;
  for (int i = 0; i < n; ++i) out.push_back(f());
  return out;
}

constexpr int kCases = 20000;

}  // namespace

TEST(ExactStage, CrossInOrdinaryRangeUsesExpansions) {
  Rng r(101);
  const auto random = make(kCases, [&] {
    return Cross{{wild(r, -40, 40), wild(r, -40, 40)},
                 {wild(r, -40, 40), wild(r, -40, 40)},
                 {wild(r, -40, 40), wild(r, -40, 40)},
                 {wild(r, -40, 40), wild(r, -40, 40)}};
  });
  const auto lattice =
      make(kCases, [&] { return latticeLine(r, static_cast<int>(r.below(121)) - 60); });
  const auto diagonal = make(kCases, [&] { return diagonalLine(r, -60, 60); });
  const auto offLattice = make(kCases, [&] {
    Cross c = latticeLine(r, static_cast<int>(r.below(41)) - 20);
    c.q1.y = ulpOff(r, c.q1.y);
    return c;
  });
  const auto offDiagonal = make(kCases, [&] {
    Cross c = diagonalLine(r, -30, 30);
    c.q1.x = ulpOff(r, c.q1.x);
    return c;
  });
  const auto mixed = make(kCases, [&] {
    return Cross{{wild(r, -480, 499), wild(r, -480, 499)},
                 {wild(r, -480, 499), 0},
                 {0, wild(r, -480, 499)},
                 {wild(r, -480, 499), wild(r, -480, 499)}};
  });
  for (const auto* cases : {&random, &lattice, &diagonal, &offLattice, &offDiagonal, &mixed})
    EXPECT_EQ(expectAllMatch(*cases, crossStage, crossRef), 0u);
}

TEST(ExactStage, CrossAtExtremeExponentsUsesMultiprecision) {
  Rng r(102);
  const double big = std::numeric_limits<double>::max(),
               tiny = std::numeric_limits<double>::denorm_min();
  const auto huge = make(kCases, [&] {
    return Cross{{wild(r, 990, 1023), wild(r, 990, 1023)},
                 {big, -big},
                 {-big, wild(r, 990, 1023)},
                 {wild(r, 990, 1023), big}};
  });
  const auto subnormal = make(kCases, [&] {
    return Cross{{wild(r, -1074, -1023), tiny},
                 {wild(r, -1074, -1023), wild(r, -1074, -1023)},
                 {wild(r, -1074, -1023), wild(r, -1074, -1023)},
                 {-tiny, wild(r, -1074, -1023)}};
  });
  const auto mixed = make(kCases, [&] {
    return Cross{{wild(r, -1074, 1023), wild(r, -1074, 1023)},
                 {wild(r, -1074, 1023), tiny},
                 {big, wild(r, -1074, 1023)},
                 {wild(r, -1074, 1023), wild(r, -1074, 1023)}};
  });
  const auto far = make(kCases, [&] {
    const int s = r.below(2) ? 700 : -700;
    Cross c = r.below(2) ? scaled(latticeLine(r, 0), s) : scaled(diagonalLine(r, -20, 20), s);
    if (r.below(2)) c.q1.y = ulpOff(r, c.q1.y);
    return c;
  });
  for (const auto* cases : {&huge, &subnormal, &mixed, &far})
    EXPECT_EQ(expectAllMatch(*cases, crossStage, crossRef), cases->size());
}

TEST(ExactStage, Orient3dInOrdinaryRangeUsesExpansions) {
  Rng r(103);
  auto point = [&](int lo, int hi) {
    return Vec3{wild(r, lo, hi), wild(r, lo, hi), wild(r, lo, hi)};
  };
  const auto random = make(kCases, [&] {
    return Orient{point(-40, 40), point(-40, 40), point(-40, 40), point(-40, 40)};
  });
  const auto lattice =
      make(kCases, [&] { return latticePlane(r, static_cast<int>(r.below(121)) - 60); });
  const auto column = make(kCases, [&] { return columnPlane(r, -60, 60); });
  const auto offLattice = make(kCases, [&] {
    Orient o = latticePlane(r, static_cast<int>(r.below(41)) - 20);
    o.d.z = ulpOff(r, o.d.z);
    return o;
  });
  const auto offColumn = make(kCases, [&] {
    Orient o = columnPlane(r, -30, 30);
    o.d.x = ulpOff(r, o.d.x);
    return o;
  });
  const auto mixed = make(kCases, [&] {
    return Orient{point(-300, 329), point(-300, 329), point(-300, 329), point(-300, 329)};
  });
  const auto rim = make(kCases, [&] {
    // the edges of the range: 2^330 and 2^-300 and their neighbours inside it
    const double edge[] = {0x1p330, -0x1p330, std::nextafter(0x1p330, 0), 0x1p-300, -0x1p-300, 0};
    auto pick = [&] { return edge[r.below(6)]; };
    return Orient{{pick(), pick(), pick()},
                  {pick(), pick(), pick()},
                  {pick(), pick(), pick()},
                  {pick(), pick(), pick()}};
  });
  for (const auto* cases : {&random, &lattice, &column, &offLattice, &offColumn, &mixed, &rim})
    EXPECT_EQ(expectAllMatch(*cases, orientStage, orientRef), 0u);
}

TEST(ExactStage, Orient3dAtExtremeExponentsUsesMultiprecision) {
  Rng r(104);
  const double big = std::numeric_limits<double>::max(),
               tiny = std::numeric_limits<double>::denorm_min();
  auto point = [&](int lo, int hi) {
    return Vec3{wild(r, lo, hi), wild(r, lo, hi), wild(r, lo, hi)};
  };
  const auto huge = make(kCases, [&] {
    return Orient{
        point(990, 1023), {big, -big, big}, point(995, 1023), scaled(latticePlane(r, 0), 960).d};
  });
  const auto subnormal = make(kCases, [&] {
    Orient o =
        r.below(2)
            ? latticePlane(r, -1074)
            : Orient{
                  point(-1074, -1023), point(-1074, -1023), {tiny, 0, -tiny}, point(-1074, -1023)};
    if (r.below(2)) o.d.y = ulpOff(r, o.d.y);
    return o;
  });
  const auto mixed = make(kCases, [&] {
    return Orient{point(-1074, 1023), point(-1074, 1023), {big, tiny, 0}, point(-1074, 1023)};
  });
  const auto far = make(kCases, [&] {
    const int s = r.below(2) ? 700 : -700;
    Orient o = r.below(2) ? scaled(latticePlane(r, 0), s) : scaled(columnPlane(r, -20, 20), s);
    if (r.below(2)) o.d.x = ulpOff(r, o.d.x);
    return o;
  });
  const auto outside = make(kCases, [&] {
    // just beyond the range: 2^330 and 2^-300 one ulp out
    const double edge[] = {std::nextafter(0x1p330, HUGE_VAL), std::nextafter(0x1p-300, 0), 1, -1};
    auto pick = [&] { return edge[r.below(4)]; };
    return Orient{{edge[r.below(2)], pick(), pick()},
                  {pick(), pick(), pick()},
                  {pick(), pick(), pick()},
                  {pick(), pick(), pick()}};
  });
  for (const auto* cases : {&huge, &subnormal, &mixed, &far, &outside})
    EXPECT_EQ(expectAllMatch(*cases, orientStage, orientRef), cases->size());
}

TEST(ExactStage, OrdinaryRangeAllocatesNothing) {
  // exactly coplanar and collinear cases, which only the exact stage can decide
  Rng r(105);
  const auto planes =
      make(2000, [&] { return r.below(2) ? latticePlane(r, -10) : columnPlane(r, -20, 20); });
  const auto lines =
      make(2000, [&] { return r.below(2) ? latticeLine(r, -10) : diagonalLine(r, -20, 20); });
  const unsigned long long exact0 = exactFallbackCount(), multi0 = multiprecisionFallbackCount();
  int nonZero = 0;
  unsigned long long allocations = 0;
  {
    const AllocationCount count;
    for (const Orient& o : planes) nonZero += orient3d(o.a, o.b, o.c, o.d) != 0;
    for (const Cross& c : lines) nonZero += crossDiff2d(c.p0, c.p1, c.q0, c.q1) != 0;
    allocations = count.count();
  }
  EXPECT_EQ(nonZero, 0);
  EXPECT_EQ(allocations, 0u);
  EXPECT_EQ(multiprecisionFallbackCount(), multi0);
  // the filter decides none of the lattice cases with a non-zero permanent; all of them and
  // most of the rest reach the exact stage
  EXPECT_GT(exactFallbackCount() - exact0, planes.size() + lines.size() / 2);
}

TEST(ExactStage, ExtremeExponentsAllocateAndTheCountSeesIt) {
  // the counter is live: 2^700 and 2^-700 in one call take the multiprecision path, whose
  // integers of some 1400 bits allocate with either backend
  Rng r(106);
  Orient o = scaled(latticePlane(r, 0), 700);
  o.d.z = 0x1p-700;
  const unsigned long long multi0 = multiprecisionFallbackCount();
  unsigned long long allocations = 0;
  int sign = 0;
  {
    const AllocationCount count;
    sign = orient3d(o.a, o.b, o.c, o.d);
    allocations = count.count();
  }
  EXPECT_EQ(sign, refOrient3d(o.a, o.b, o.c, o.d));
  EXPECT_GT(allocations, 0u);
  EXPECT_EQ(multiprecisionFallbackCount(), multi0 + 1);
}
