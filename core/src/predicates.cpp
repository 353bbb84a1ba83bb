// convexloc — the exact stage of the predicates: what runs when the floating-point filter of
// predicates.hpp cannot decide.
//
// Three stages, each exact, the first that applies decides:
//  - narrow integers (detail/narrow_integers.hpp): where all coordinates are 61-bit
//    integers times one power of two (at any scale up to 2^+-900), 64-, 128- and 192-bit
//    integer arithmetic;
//  - floating-point expansions over the ordinary exponent range (below);
//  - multiprecision integers beyond it.
// Only the last allocates.
//
// Over the ordinary exponent range the sign comes from floating-point expansions
// (detail/expansion.hpp) on the stack: each difference a - b of the input doubles is taken
// exactly as a two-component expansion (two-diff), and the determinant of those
// differences is multiplied out and summed exactly. Outside that range (DBL_MAX,
// subnormals, 2^700 beside 2^-700) the doubles are scaled to exact integers
// (detail/exact_number.hpp) and the determinant is taken there.
//
// Why the expansions are exact. Let k be the number of factors in each term of the
// determinant (2 in the plane, 3 in space) and suppose every input coordinate is 0 or has
// 2^lo <= |x| <= 2^hi, with (k, lo, hi) = (2, -480, 500) or (3, -300, 330) (the code asks
// for a little less: a normal double of exponent at most hi - 1).
//  1. Grain. A double with |x| >= 2^lo is an integer multiple of g = 2^(lo - 52) (its last
//     bit lies 52 places below its leading one). If the exact result of a sum, difference
//     or product of doubles is a multiple of 2^m, so is its rounded value (rounding keeps a
//     value on its own grid, or on a coarser grid of larger powers of two), and so is the
//     error term two-sum, two-diff or two-product recovers (a difference of two such).
//     The differences are multiples of g; every product formed multiplies one component
//     drawn from each of at most k differences (or from an expansion built of such
//     products), so every value computed is a multiple of g^k: 2^-1064 in the plane and
//     2^-1056 in space, both multiples of 2^-1074, the subnormal grid.
//  2. Magnitude. |a - b| <= 2^(hi+1), and the two components of its expansion sum in
//     magnitude to at most 2^(hi+1) (1 + 2^-53). Each error-free step replaces its operands
//     by results whose magnitudes sum to at most (1 + 2^-53) times theirs, and a few
//     thousand steps run, so every component and partial sum is below
//     (terms) * (2^(hi+1))^k * (1 + 2^-40): 2 * 2^1002 = 2^1003 in the plane and
//     6 * 2^993 < 2^996 in space. No operation overflows, and the operands of a product
//     stay below 2^996, as Veltkamp's split (used where there is no fused multiply-add)
//     needs.
//  3. Hence detail/expansion.hpp's condition holds (multiples of 2^-1074, below 2^1020):
//     each step is exact, the final expansion is nonoverlapping, and its last component
//     has the sign of the determinant.
// The range test costs one pass over the coordinates; the bounds are on the inputs rather
// than the differences, so that the grain argument of 1. holds for the tails too.
#include "convexloc/predicates.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <tuple>

#include "detail/exact_number.hpp"
#include "detail/expansion.hpp"
#include "detail/narrow_integers.hpp"

// GCC's straight-line vectoriser packs the points' coordinates, passed in separate
// registers, into pairs through the stack, and each pair's reload stalls on the two stores
// before it (store forwarding fails): a third of the narrow stage's time. Scalar code here.
#if defined(__GNUC__) && !defined(__clang__)
#define CONVEXLOC_SCALAR [[gnu::optimize("no-tree-slp-vectorize")]]
#else
#define CONVEXLOC_SCALAR
#endif

namespace convexloc {
namespace {

namespace ex = detail::expansion;
namespace narrow = detail::narrow;

thread_local ExactStageCounts tCounts{};

// the exponent range of the proof above (2^lo <= |v| < 2^(hi+1) for each non-zero v), in the
// plane and in space
constexpr int kPlaneLo = -480, kPlaneHi = 499;
constexpr int kSpaceLo = -300, kSpaceHi = 329;

// === The expansion stage

// a difference of two doubles, exactly: at most two components
struct Diff {
  double c[2];
  int n;
};
Diff diff(double a, double b) noexcept {
  Diff d;
  d.n = ex::difference(a, b, d.c);
  return d;
}

// h = x * y - z * w exactly, at most 16 components
int minor(const Diff& x, const Diff& y, const Diff& z, const Diff& w, double* h) noexcept {
  double left[8], right[8], scratch[16];
  const int nl = ex::product(x.c, x.n, y.c, y.n, left, scratch);
  const int nr = ex::product(z.c, z.n, w.c, w.n, right, scratch);
  ex::negate(right, nr);
  return ex::sum(left, nl, right, nr, h);
}

// sign of (p1 - p0) x (q1 - q0), all on the stack (kept out of line: the narrow-integer
// stage before it stays lean)
[[gnu::noinline]] int crossExpansion(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1) noexcept {
  const Diff px = diff(p1.x, p0.x), py = diff(p1.y, p0.y);
  const Diff qx = diff(q1.x, q0.x), qy = diff(q1.y, q0.y);
  double det[16];
  return ex::signOf(det, minor(px, qy, py, qx, det));
}

// h = u * m exactly for a difference u and an expansion m of at most 16 components
int times(const Diff& u, const double* m, int n, double* h) noexcept {
  double scratch[4 * 16 * 2];
  return ex::product(m, n, u.c, u.n, h, scratch);
}

// sign of det[a-d; b-d; c-d], all on the stack (out of line, as above)
[[gnu::noinline]] int orient3dExpansion(Vec3 a, Vec3 b, Vec3 c, Vec3 d) noexcept {
  const Diff ux = diff(a.x, d.x), uy = diff(a.y, d.y), uz = diff(a.z, d.z);
  const Diff vx = diff(b.x, d.x), vy = diff(b.y, d.y), vz = diff(b.z, d.z);
  const Diff wx = diff(c.x, d.x), wy = diff(c.y, d.y), wz = diff(c.z, d.z);
  // expanded along the first row: ux (vy wz - vz wy) + uy (vz wx - vx wz) + uz (vx wy - vy wx)
  double m[16], t1[64], t2[64], t3[64], t12[128], det[192];
  int n = minor(vy, wz, vz, wy, m);
  const int n1 = times(ux, m, n, t1);
  n = minor(vz, wx, vx, wz, m);
  const int n2 = times(uy, m, n, t2);
  n = minor(vx, wy, vy, wx, m);
  const int n3 = times(uz, m, n, t3);
  const int n12 = ex::sum(t1, n1, t2, n2, t12);
  return ex::signOf(det, ex::sum(t12, n12, t3, n3, det));
}

// === The multiprecision stage (extreme exponents)

// The multiprecision stage's integers, one set per thread: each keeps its limbs from call to
// call, so that a thread's calls allocate only while its integers grow (under the sanitizers
// allocation was half of this stage's time), and every operation below writes into one of
// them rather than into a temporary.
template <std::size_t K>
struct Scratch {
  std::array<detail::ExactInt, K> z;
  detail::ExactInt t0, t1, t2, det;
};
template <std::size_t K>
Scratch<K>& scratch() {
  thread_local Scratch<K> s;
  return s;
}

// z[i] = values[i] * 2^-lo, all exact integers, with lo the common lowest set bit
template <std::size_t K>
void integers(const std::array<double, K>& values, std::array<detail::ExactInt, K>& z) {
  const int lo = detail::commonLowestSetBit(values);
  for (std::size_t i = 0; i < K; ++i) detail::setScaledInteger(z[i], values[i], -lo);
}

[[gnu::noinline]] int crossMultiprecision(const std::array<double, 8>& in) {
  Scratch<8>& s = scratch<8>();
  auto& z = s.z;  // p0x p0y p1x p1y q0x q0y q1x q1y
  integers(in, z);
  z[2] -= z[0];
  z[7] -= z[5];
  z[3] -= z[1];
  z[6] -= z[4];
  s.t0 = z[2] * z[7];
  s.t1 = z[3] * z[6];
  s.t0 -= s.t1;
  return s.t0.sign();
}

[[gnu::noinline]] int orient3dMultiprecision(const std::array<double, 12>& in) {
  Scratch<12>& s = scratch<12>();
  auto& z = s.z;  // a b c d, three coordinates each
  integers(in, z);
  for (std::size_t i = 0; i < 9; ++i) z[i] -= z[9 + i % 3];
  // z0 (z4 z8 - z5 z7) + z1 (z5 z6 - z3 z8) + z2 (z3 z7 - z4 z6), one product at a time
  auto term = [&](const detail::ExactInt& f, const detail::ExactInt& p, const detail::ExactInt& q,
                  const detail::ExactInt& r, const detail::ExactInt& w) {
    s.t0 = p * q;
    s.t1 = r * w;
    s.t0 -= s.t1;
    s.t2 = f * s.t0;
    s.det += s.t2;
  };
  s.det = 0u;
  term(z[0], z[4], z[8], z[5], z[7]);
  term(z[1], z[5], z[6], z[3], z[8]);
  term(z[2], z[3], z[7], z[4], z[6]);
  return s.det.sign();
}

// the three stages in order, each counted: narrow integers when the coordinates are close in
// scale, expansions when every exponent lies in [lo, hi], else multiprecision on `values`
template <std::size_t K, class Narrow, class Expansion>
int staged(const std::array<double, K>& values, int lo, int hi, Narrow narrowSign,
           Expansion expansionSign,
           int (*multiprecisionSign)(const std::array<double, K>&)) noexcept {
  const narrow::Magnitudes m =
      std::apply([](auto... v) { return narrow::Magnitudes{v...}; }, values);
  if (const int sign = narrowSign(m); sign != narrow::kDeclined) {
    ++tCounts.narrowIntegers;
    return sign;
  }
  if (m.within(lo, hi)) {
    ++tCounts.expansions;
    return expansionSign();
  }
  ++tCounts.multiprecision;
  return multiprecisionSign(values);
}

}  // namespace

CONVEXLOC_SCALAR int detail::crossExact(Vec2 p0, Vec2 p1, Vec2 q0, Vec2 q1) noexcept {
  return staged(
      std::array<double, 8>{p0.x, p0.y, p1.x, p1.y, q0.x, q0.y, q1.x, q1.y}, kPlaneLo, kPlaneHi,
      [&](const narrow::Magnitudes& m) { return narrow::cross(p0, p1, q0, q1, m); },
      [&] { return crossExpansion(p0, p1, q0, q1); }, crossMultiprecision);
}

CONVEXLOC_SCALAR int detail::orient3dExact(Vec3 a, Vec3 b, Vec3 c, Vec3 d) noexcept {
  return staged(
      std::array<double, 12>{a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z}, kSpaceLo,
      kSpaceHi, [&](const narrow::Magnitudes& m) { return narrow::orient3d(a, b, c, d, m); },
      [&] { return orient3dExpansion(a, b, c, d); }, orient3dMultiprecision);
}

// The filter once more where a difference is untame only by being small (or zero beside
// small ones). With every difference at most 2^250 nothing overflows, and a product that
// underflows errs by at most 2^-1075 in absolute terms (a sum or difference of doubles is
// exact where it underflows). Such an error in one of a 2x2 minor's two products is multiplied
// by the third row's difference (|adz|, |bdz| or |cdz|) and then rounded twice, so beyond
// Shewchuk's kO3dBound * permanent (the relative errors, with the permanent computed from the
// same products) |error| <= (2 (|adz| + |bdz| + |cdz|) + 3) 2^-1075 (1 + 2^-50), which
// (|adz| + |bdz| + |cdz| + 2) 2^-1072 covers fourfold. A point one subnormal step off a face
// in the plane z = 0 (a part standing on its ground plane) has untame differences and
// determinants far from zero: decided here, not by the multiprecision stage.
int detail::orient3dUntame(Vec3 a, Vec3 b, Vec3 c, Vec3 d, const Orient3dTerms& t) noexcept {
  if (!t.tame) {
    const double adz = std::fabs(a.z - d.z), bdz = std::fabs(b.z - d.z), cdz = std::fabs(c.z - d.z);
    const double hi = std::max({std::fabs(a.x - d.x), std::fabs(a.y - d.y), adz,
                                std::fabs(b.x - d.x), std::fabs(b.y - d.y), bdz,
                                std::fabs(c.x - d.x), std::fabs(c.y - d.y), cdz});
    if (hi <= 0x1p250) {
      const double bound = kO3dBound * t.permanent + (adz + bdz + cdz + 2) * 0x1p-1072;
      if (t.det > bound) return 1;
      if (-t.det > bound) return -1;
    }
  }
  return orient3dExact(a, b, c, d);
}

unsigned long long exactFallbackCount() noexcept {
  return tCounts.narrowIntegers + tCounts.expansions + tCounts.multiprecision;
}

ExactStageCounts exactStageCounts() noexcept {
  return tCounts;
}

}  // namespace convexloc
