// convexloc — the cube map's slabs: for each leaf a direction n and two bounds on n . (y - c)
// over the points y where the cell's rays may leave, which decide most points the radii leave
// open over a flat part of the surface.
//
// The radii bound |y - c|, which over a face seen at a slant varies by about the cell's width
// times the slant: on a cylinder's sides or caps a thick shell, and the points in it go on to
// the face tests. Measured along the normal n of the face the cell looks at, the same points
// vary only by how much the cell's faces turn: a slab far thinner than that shell.
//
// Why the slab is exact. Let p be mapped to the leaf, not the centre, and left open by its
// radii with d2 <= out2 (the query checks both). Its exact direction lies in the cell's square
// widened by 2^-30 (far beyond the query's rounding), and the ray from c through p leaves the
// polyhedron at a point y of a listed face (cubemap/index.hpp) inside that widened pyramid:
// p - c = mu (y - c) with mu > 0, and p is inside iff mu < 1 (c strictly inside, the body
// convex), outside iff mu > 1. The build bounds n . (y - c) by [lo, hi] over every listed
// face's part inside the pyramid. That part lies in the face, over which the linear
// n . (y - c) is extreme at a corner; where those spread, also in the quadrilateral of the
// four corner rays' hits on its plane when all four meet it ahead (hits bounded as
// intervals), else in the face clipped by a pyramid widened by 2^-24 (see clipRange); the
// face's range is the overlap of what it lies in. All with a slack above the rounding. The stored
// bounds are lo' <= lo - m and hi' >= max(hi, 0) + m, floats rounded outward, with m = 2^-44
// sqrt(out2) + 2^-1000 above the error of the query's v = n . (p - c) in doubles (four roundings of
// terms summing to at most |n| |p - c| <= (1 + 2^-23) sqrt(out2 (1 + 2^-50)), and underflow). With
// V = n . (p - c) = mu n . (y - c) exactly: if v > hi', then V > max(hi, 0) >= 0 and V > n . (y -
// c); V > 0 makes n . (y - c) > 0, so mu > 1: Outside. If v < lo' and lo' > 0, then n . (y - c) >=
// lo > 0 and V < n . (y - c), so mu < 1: Inside. A bound below that is not positive disables the
// inner test (lo' = -inf); a leaf without a sure bound (or with too many faces to bound at build)
// gets no slab (lo' = -inf, hi' = +inf).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "cubemap/build.hpp"
#include "cubemap/index.hpp"
#include "detail/radii.hpp"

namespace convexloc {
namespace cubemap {
namespace {

using Long = long double;
constexpr Long kEps = std::numeric_limits<Long>::epsilon();  // 2^-63
// a leaf listing more faces than this gets no slab (the bound would cost too much to build)
constexpr std::size_t kSlabFaces = 1024;
// a face with more corners is bounded by its plane's hits only (else the leaf gets no slab)
constexpr std::size_t kSlabCorners = 32;
// the faces (spread over its list) among which a leaf's slab normal is chosen
constexpr std::size_t kNormalCandidates = 24;

// the four corner directions of cell (i, j) at `level` of cube face `cf`, widened by 2^-30,
// and their lengths
struct Corners {
  Long d[4][3];
  Long len[4];
};

Corners cornersOf(std::uint32_t g, int cf, int level, std::uint64_t i, std::uint64_t j,
                  Long widen = 0x1p-30L) {
  Corners k;
  const int a = cf / 2, u = (a + 1) % 3, w = (a + 2) % 3;
  const Long K = std::ldexp(static_cast<Long>(g) / 2, level);
  const Long s0 = Long(i) / K - 1 - widen, s1 = Long(i + 1) / K - 1 + widen;
  const Long t0 = Long(j) / K - 1 - widen, t1 = Long(j + 1) / K - 1 + widen;
  const Long st[4][2] = {{s0, t0}, {s1, t0}, {s1, t1}, {s0, t1}};
  for (int c = 0; c < 4; ++c) {
    k.d[c][a] = (cf & 1) ? -1 : 1;
    k.d[c][u] = st[c][0];
    k.d[c][w] = st[c][1];
    k.len[c] = std::sqrt(1 + st[c][0] * st[c][0] + st[c][1] * st[c][1]);
  }
  return k;
}

// [lo, hi] of n . (y - c) over plane face f's part inside the pyramid: from the corner rays'
// hits on its plane when all four meet it ahead, well conditioned; else false
bool pyramidRange(const Corners& k, const Long (&n)[3], Vec3 va, Vec3 vb, Vec3 vd, Vec3 c, Long& lo,
                  Long& hi) {
  const Long u[3] = {Long(vb.x) - va.x, Long(vb.y) - va.y, Long(vb.z) - va.z};
  const Long v[3] = {Long(vd.x) - va.x, Long(vd.y) - va.y, Long(vd.z) - va.z};
  const Long w[3] = {Long(c.x) - va.x, Long(c.y) - va.y, Long(c.z) - va.z};
  const Long m[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
                     u[0] * v[1] - u[1] * v[0]};
  const Long pm[3] = {std::fabs(u[1] * v[2]) + std::fabs(u[2] * v[1]),
                      std::fabs(u[2] * v[0]) + std::fabs(u[0] * v[2]),
                      std::fabs(u[0] * v[1]) + std::fabs(u[1] * v[0])};
  // m (the outward normal) within 4 eps of its permanent, N = m . (a - c) within 8
  const Long mErr[3] = {4 * kEps * pm[0], 4 * kEps * pm[1], 4 * kEps * pm[2]};
  const Long N = -(m[0] * w[0] + m[1] * w[1] + m[2] * w[2]);
  const Long NErr =
      8 * kEps * (pm[0] * std::fabs(w[0]) + pm[1] * std::fabs(w[1]) + pm[2] * std::fabs(w[2]));
  const Long mLen = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
  if (!(N - NErr > 0) || !(mErr[0] + mErr[1] + mErr[2] <= 0x1p-40L * mLen)) return false;
  const Long nLen = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  lo = std::numeric_limits<Long>::infinity(), hi = -lo;
  for (int q = 0; q < 4; ++q) {
    const Long* d = k.d[q];
    const Long D = m[0] * d[0] + m[1] * d[1] + m[2] * d[2];
    const Long DErr = (mErr[0] + 2 * kEps * std::fabs(m[0])) * std::fabs(d[0]) +
                      (mErr[1] + 2 * kEps * std::fabs(m[1])) * std::fabs(d[1]) +
                      (mErr[2] + 2 * kEps * std::fabs(m[2])) * std::fabs(d[2]);
    if (!(D - DErr > 0x1p-20L * mLen * k.len[q])) return false;  // nearly along the plane
    // the hit is lambda d with lambda in [lambdaLo, lambdaHi]; n . d within 4 eps of its size
    const Long lambdaLo = (N - NErr) / (D + DErr), lambdaHi = (N + NErr) / (D - DErr);
    const Long nd = n[0] * d[0] + n[1] * d[1] + n[2] * d[2];
    const Long slack = 0x1p-40L * lambdaHi * nLen * k.len[q];  // every long double rounding here
    lo = std::min(lo, std::min(lambdaLo * nd, lambdaHi * nd) - slack);
    hi = std::max(hi, std::max(lambdaLo * nd, lambdaHi * nd) + slack);
  }
  return true;
}

using Point = std::array<Long, 3>;

Long dot(const Long (&a)[3], const Point& b) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

// [lo, hi] of n . (y - c) over plane face f's part inside the pyramid `wider` (widened by
// 2^-24, so far beyond the 2^-30 one that rounding in the clip cannot cut into it): its
// corners (less c) clipped by the four planes through c and two neighbouring corner rays. A
// clipped corner lies on its edge (t in [0, 1]), where the plane's value is within rounding
// of 0: what the rounding drops lies outside the 2^-30 pyramid. False when nothing is left.
bool clipRange(const Corners& wider, const Long (&n)[3], std::span<const std::uint32_t> loop,
               const std::vector<Vec3>& vertices, Vec3 c, std::vector<Point>& poly,
               std::vector<Point>& next, Long& lo, Long& hi) {
  poly.clear();
  for (std::uint32_t corner : loop) {
    const Vec3 y = vertices[corner];
    poly.push_back({Long(y.x) - c.x, Long(y.y) - c.y, Long(y.z) - c.z});
  }
  Long middle[3] = {0, 0, 0};
  for (const auto& d : wider.d)
    for (int m = 0; m < 3; ++m) middle[m] += d[m];
  for (int q = 0; q < 4 && !poly.empty(); ++q) {
    const Long* a = wider.d[q];
    const Long* b = wider.d[(q + 1) % 4];
    Long h[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
    if (h[0] * middle[0] + h[1] * middle[1] + h[2] * middle[2] < 0)
      for (Long& x : h) x = -x;
    next.clear();
    for (std::size_t e = 0; e < poly.size(); ++e) {
      const Point& p = poly[e];
      const Point& r = poly[(e + 1) % poly.size()];
      const Long sp = dot(h, p), sr = dot(h, r);
      if (sp >= 0) next.push_back(p);
      if ((sp >= 0) != (sr >= 0)) {
        const Long t = std::clamp(sp / (sp - sr), Long(0), Long(1));
        next.push_back(
            {p[0] + t * (r[0] - p[0]), p[1] + t * (r[1] - p[1]), p[2] + t * (r[2] - p[2])});
      }
    }
    poly.swap(next);
  }
  if (poly.empty()) return false;
  const Long nLen = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  lo = std::numeric_limits<Long>::infinity(), hi = -lo;
  for (const Point& p : poly) {
    const Long slack = 0x1p-40L * nLen * (std::fabs(p[0]) + std::fabs(p[1]) + std::fabs(p[2]));
    lo = std::min(lo, dot(n, p) - slack), hi = std::max(hi, dot(n, p) + slack);
  }
  return true;
}

// [lo, hi] of n . (y - c) over plane face f's corners (so over the whole face), in doubles
// with a slack far above their rounding (n's components at most 1 + 2^-23); false when a
// value overflows
bool cornerRange(const std::vector<Vec3>& vertices, std::span<const std::uint32_t> loop,
                 const float (&n)[3], Vec3 c, double& lo, double& hi) {
  double low = HUGE_VAL, high = -HUGE_VAL;
  for (std::uint32_t corner : loop) {
    const Vec3 y = vertices[corner];
    const double d[3] = {y.x - c.x, y.y - c.y, y.z - c.z};
    const double value = static_cast<double>(n[0]) * d[0] + static_cast<double>(n[1]) * d[1] +
                         static_cast<double>(n[2]) * d[2];
    const double slack = 0x1p-40 * (std::fabs(d[0]) + std::fabs(d[1]) + std::fabs(d[2]));
    if (!std::isfinite(value + slack)) return false;
    low = std::min(low, value - slack), high = std::max(high, value + slack);
  }
  lo = low, hi = high;
  return true;
}

}  // namespace
}  // namespace cubemap

using namespace cubemap;

void CubemapBuilder::setLeafSlab(std::uint32_t node, int cf, int level, std::uint64_t i,
                                 std::uint64_t j, std::span<const std::uint32_t> faces) {
  CubemapLocator& L = locator_;
  const std::vector<Vec3>& v = L.surface_.vertices;
  const Vec3 c = L.centre_;
  const double out2 = static_cast<double>(L.nodes_[node].out2);
  if (faces.empty() || faces.size() > kSlabFaces || !std::isfinite(out2)) return;
  float n32[3];
  if (!slabNormal(faces, cf, level, i, j, n32)) return;
  const Long n[3] = {n32[0], n32[1], n32[2]};
  const Corners k = cornersOf(L.resolution_, cf, level, i, j),
                wider = cornersOf(L.resolution_, cf, level, i, j, 0x1p-24L);
  std::vector<Point> poly, next;
  Long lo = std::numeric_limits<Long>::infinity(), hi = -lo;
  double low = HUGE_VAL, high = -HUGE_VAL;  // over the faces whose corners do not spread
  for (std::uint32_t f : faces) {
    // the face's corners; where they spread (a face large or slanted across n), its part in
    // the pyramid too: each range holds the values of that part, so their overlap does
    Long plo, phi;
    const ConvexPolyhedron::Triangle& t = L.surface_.faces[f];
    const auto loop = polyhedron_.planeLoop(f);
    if (loop.size() > kSlabCorners) {  // a cap of many corners: its plane's hits, else none
      if (!pyramidRange(k, n, v[t[0]], v[t[1]], v[t[2]], c, plo, phi)) return;
      lo = std::min(lo, plo), hi = std::max(hi, phi);
      continue;
    }
    double clo, chi;
    if (!cornerRange(v, loop, n32, c, clo, chi)) return;
    if (chi - clo <= 0x1p-8 * std::fabs(chi) && clo > 0) {  // most faces: in doubles
      low = std::min(low, clo), high = std::max(high, chi);
      continue;
    }
    Long flo = clo, fhi = chi;
    if (pyramidRange(k, n, v[t[0]], v[t[1]], v[t[2]], c, plo, phi) ||
        clipRange(wider, n, loop, v, c, poly, next, plo, phi)) {
      const bool overlap = std::max(flo, plo) <= std::min(fhi, phi);
      flo = overlap ? std::max(flo, plo) : plo;
      fhi = overlap ? std::min(fhi, phi) : phi;
    }
    lo = std::min(lo, flo), hi = std::max(hi, fhi);
  }
  lo = std::min(lo, Long(low)), hi = std::max(hi, Long(high));
  // the query's rounding (d2 <= out2 when the slab runs), then outward to floats
  const Long margin = 0x1p-44L * std::sqrt(static_cast<Long>(out2)) + 0x1p-1000L;
  const double below = static_cast<double>(lo - margin),
               above = static_cast<double>(std::max(hi, Long(0)) + margin);
  CubemapLocator::Slab& s = L.slabs_[node];
  std::copy(n32, n32 + 3, s.n);
  const float lo32 = detail::floatBelow(std::nextafter(below, -HUGE_VAL));
  s.lo = lo32 > 0 ? lo32 : -std::numeric_limits<float>::infinity();
  s.hi = detail::floatAbove(std::nextafter(above, HUGE_VAL));
}

bool CubemapBuilder::slabNormal(std::span<const std::uint32_t> faces, int cf, int level,
                                std::uint64_t i, std::uint64_t j, float (&n)[3]) const {
  // the unit outward normal of the face the ray through the cell's middle leaves by (the
  // nearest plane it meets ahead), rounded to floats; any direction would be sound
  const CubemapLocator& L = locator_;
  const std::vector<Vec3>& v = L.surface_.vertices;
  const Vec3 c = L.centre_;
  const double K = levelScale(L.resolution_, level);
  const Vec3 d = cubeDirection(cf, (static_cast<double>(i) + 0.5) / K - 1,
                               (static_cast<double>(j) + 0.5) / K - 1);
  double best = HUGE_VAL, m[3] = {0, 0, 0};
  const std::size_t step = 1 + faces.size() / kNormalCandidates;
  for (std::size_t at = 0; at < faces.size(); at += step) {
    const ConvexPolyhedron::Triangle& t = L.surface_.faces[faces[at]];
    const Vec3 a = v[t[0]], b = v[t[1]], e = v[t[2]];
    const double u[3] = {b.x - a.x, b.y - a.y, b.z - a.z}, w[3] = {e.x - a.x, e.y - a.y, e.z - a.z};
    const double o[3] = {u[1] * w[2] - u[2] * w[1], u[2] * w[0] - u[0] * w[2],
                         u[0] * w[1] - u[1] * w[0]};
    const double D = o[0] * d.x + o[1] * d.y + o[2] * d.z;
    const double N = o[0] * (a.x - c.x) + o[1] * (a.y - c.y) + o[2] * (a.z - c.z);
    if (!(D > 0) || !(N > 0) || !(N / D < best)) continue;
    best = N / D;
    std::copy(o, o + 3, m);
  }
  const double len = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
  if (!(len > 0) || !std::isfinite(len)) return false;
  for (int k = 0; k < 3; ++k) n[k] = static_cast<float>(m[k] / len);
  return true;
}

}  // namespace convexloc
