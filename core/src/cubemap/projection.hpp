// convexloc (internal) — a face's cone from the centre projected onto a cube face, and the
// cells it meets: the build's geometry, relaxed beyond every rounding so that the lists stay
// conservative (the argument: cubemap/index.hpp).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "convexloc/polyhedron.hpp"
#include "cubemap/build.hpp"

namespace convexloc::cubemap {

inline constexpr double kEps = 0x1p-53;
// how far, in (s, t) units, a query's computed coordinates may stray: far above their error
inline constexpr double kMargin = 0x1p-40;
// extra room that keeps rounding in the build's clipping from losing a face
inline constexpr double kSlack = 0x1p-42;
inline constexpr double kReach = kMargin + kSlack;
// error of a computed edge-plane normal component, per unit of its permanent
inline constexpr double kNormalError = 5.25 * kEps;
// absolute slack for products that underflow in the scaled normals
inline constexpr double kUnderflow = 0x1p-1060;
// relative margin by which all three vertices must miss a cube face to skip it
inline constexpr double kReject = 0x1p-30;

// the cone of face t seen from c, scaled exactly; false when something is not finite
inline bool coneOf(const std::vector<Vec3>& v, const ConvexPolyhedron::Triangle& t, Vec3 c,
                   const PowerOfTwo& scale, Cone& k) {
  for (int i = 0; i < 3; ++i) {
    const Vec3 p = v[t[i]];
    k.d[i][0] = scale(p.x - c.x);
    k.d[i][1] = scale(p.y - c.y);
    k.d[i][2] = scale(p.z - c.z);
  }
  bool ok = true;
  for (int i = 0; i < 3; ++i) {
    const Vec3 p = v[t[i]], q = v[t[(i + 1) % 3]];
    const double* d = k.d[i];
    const double e[3] = {scale(q.x - p.x), scale(q.y - p.y), scale(q.z - p.z)};
    double perm = 0;
    for (int a = 0; a < 3; ++a) {
      const int u = (a + 1) % 3, w = (a + 2) % 3;
      const double l = d[u] * e[w], r = d[w] * e[u];
      k.n[i][a] = l - r;
      perm += std::fabs(l) + std::fabs(r);
      ok &= std::isfinite(k.n[i][a]);
    }
    k.bound[i] = kNormalError * perm + kUnderflow;
    ok &= std::isfinite(perm);
  }
  return ok;
}

// keeps the part of P where a + b s + c t >= 0 (Sutherland-Hodgman)
inline void clip(Poly& P, double a, double b, double c) {
  Poly out;
  for (int i = 0; i < P.n; ++i) {
    const Vec2 p = P.p[i], q = P.p[(i + 1) % P.n];
    const double fp = a + b * p.x + c * p.y, fq = a + b * q.x + c * q.y;
    if (fp >= 0) out.p[out.n++] = p;
    if ((fp >= 0) != (fq >= 0)) {
      const double r = fp / (fp - fq);
      out.p[out.n++] = {p.x + r * (q.x - p.x), p.y + r * (q.y - p.y)};
    }
  }
  P = out;
}

// The polygon P of the face's cone on cube face `face` (see the notes above); false when
// the cone surely misses the face's square.
inline bool onCubeFace(const Cone& k, int face, Poly& P) {
  const int a = face / 2, u = (a + 1) % 3, w = (a + 2) % 3;
  const double sigma = (face & 1) ? -1.0 : 1.0;
  // quick rejection: all three directions strictly on the outer side of one of the
  // pyramid's bounding planes (or behind it), by a relative margin far above rounding
  for (int rule = 0; rule < 5; ++rule) {
    bool all = true;
    for (int i = 0; i < 3 && all; ++i) {
      const double* d = k.d[i];
      const double da = sigma * d[a];
      const double f = rule == 0   ? da
                       : rule == 1 ? da + d[u]
                       : rule == 2 ? da - d[u]
                       : rule == 3 ? da + d[w]
                                   : da - d[w];
      all = f < -kReject * (std::fabs(d[a]) + std::fabs(d[u]) + std::fabs(d[w]));
    }
    if (all) return false;
  }
  const double L = 1 + kReach;
  P.n = 4;
  P.p[0] = {-L, -L};
  P.p[1] = {L, -L};
  P.p[2] = {L, L};
  P.p[3] = {-L, L};
  for (int i = 0; i < 3; ++i) {
    const double alpha = sigma * k.n[i][a], beta = k.n[i][u], gamma = k.n[i][w];
    const double relax = k.bound[i] + kSlack * (std::fabs(beta) + std::fabs(gamma)) +
                         4 * kEps * (std::fabs(alpha) + std::fabs(beta) + std::fabs(gamma));
    clip(P, alpha + relax, beta, gamma);
    if (P.n == 0) return false;
  }
  return true;
}

// The bounding box, in (s, t) of cube face `face`, of face t's projection when all three
// vertices lie strictly in front of that cube face (then the projection is the triangle of
// the projected vertices), grown by far more than the rounding of their coordinates; as a
// polygon (corners 0 and 2 are the low and high ones). False otherwise.
inline bool projectedBox(const std::vector<Vec3>& v, const ConvexPolyhedron::Triangle& t, Vec3 c,
                         int face, Poly& B) {
  const int a = face / 2, u = (a + 1) % 3, w = (a + 2) % 3;
  const double sigma = (face & 1) ? -1.0 : 1.0;
  double lo[2] = {0, 0}, hi[2] = {0, 0}, big = 0;
  for (int i = 0; i < 3; ++i) {
    const Vec3 p = v[t[i]];
    const double d[3] = {p.x - c.x, p.y - c.y, p.z - c.z};
    const double major = sigma * d[a];
    if (!(major > 0)) return false;
    const double st[2] = {d[u] / major, d[w] / major};
    for (int k = 0; k < 2; ++k) {
      lo[k] = i ? std::min(lo[k], st[k]) : st[k];
      hi[k] = i ? std::max(hi[k], st[k]) : st[k];
      big = std::max(big, std::fabs(st[k]));
    }
  }
  if (!(big < 0x1p40)) return false;  // also false for NaN
  const double grow = 0x1p-50 * (1 + big);
  B.n = 4;
  B.p[0] = {lo[0] - grow, lo[1] - grow};
  B.p[1] = {hi[0] + grow, lo[1] - grow};
  B.p[2] = {hi[0] + grow, hi[1] + grow};
  B.p[3] = {lo[0] - grow, hi[1] + grow};
  return true;
}

// floor(x) and ceil(x) as integers, by truncation where |x| < 2^52 (the usual cell index: no
// call to the library's rounding in the rasteriser's inner loop)
inline std::int64_t floorIndex(double x) {
  if (!(std::fabs(x) < 0x1p52)) return static_cast<std::int64_t>(std::floor(x));
  const auto i = static_cast<std::int64_t>(x);
  return i - static_cast<std::int64_t>(static_cast<double>(i) > x);
}
inline std::int64_t ceilIndex(double x) {
  if (!(std::fabs(x) < 0x1p52)) return static_cast<std::int64_t>(std::ceil(x));
  const auto i = static_cast<std::int64_t>(x);
  return i + static_cast<std::int64_t>(static_cast<double>(i) < x);
}

// Narrows [first, last] to the cells, at the level with K = (cells per side) / 2, whose
// range of one coordinate grown by kReach meets [lo, hi] (empty when first > last).
inline void cellRange(double lo, double hi, double K, std::int64_t& first, std::int64_t& last) {
  first = std::max(first, ceilIndex((lo - kReach + 1) * K) - 1);
  last = std::min(last, floorIndex((hi + kReach + 1) * K));
}

// Calls cell(i, j) for every cell at the level with K = (cells per side) / 2, within the
// index window [i0, i1] x [j0, j1], whose square grown by kReach meets P.
template <class F>
inline void rasterise(const Poly& P, double K, std::int64_t i0, std::int64_t i1, std::int64_t j0,
                      std::int64_t j1, F&& cell) {
  double tmin = P.p[0].y, tmax = P.p[0].y;
  for (int k = 1; k < P.n; ++k) {
    tmin = std::min(tmin, P.p[k].y);
    tmax = std::max(tmax, P.p[k].y);
  }
  std::int64_t jlo = j0, jhi = j1;
  cellRange(tmin, tmax, K, jlo, jhi);
  // each edge's dx / dy, once (a product per row instead of a quotient: the same few ulps)
  double slope[8];
  for (int k = 0; k < P.n; ++k) {
    const Vec2 p = P.p[k], q = P.p[(k + 1) % P.n];
    slope[k] = (q.x - p.x) / (q.y - p.y);
  }
  for (std::int64_t j = jlo; j <= jhi; ++j) {
    const double ta = -1 + static_cast<double>(j) / K - kReach;
    const double tb = -1 + static_cast<double>(j + 1) / K + kReach;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (int k = 0; k < P.n; ++k) {
      const Vec2 p = P.p[k], q = P.p[(k + 1) % P.n];
      if (p.y >= ta && p.y <= tb) {
        lo = std::min(lo, p.x);
        hi = std::max(hi, p.x);
      }
      for (double y : {ta, tb})
        if ((p.y < y) != (q.y < y)) {
          // a nearly level edge whose dx / dy overflows: the quotient first, as it is
          const double x = std::isfinite(slope[k]) ? p.x + (y - p.y) * slope[k]
                                                   : p.x + (y - p.y) / (q.y - p.y) * (q.x - p.x);
          lo = std::min(lo, x);
          hi = std::max(hi, x);
        }
    }
    if (lo > hi) continue;
    std::int64_t ilo = i0, ihi = i1;
    cellRange(lo, hi, K, ilo, ihi);
    for (std::int64_t i = ilo; i <= ihi; ++i) cell(i, j);
  }
}

}  // namespace convexloc::cubemap
