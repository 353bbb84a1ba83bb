// An exact reference for point-in-convex-polyhedron, for tests only. It shares no code with
// core's predicates: a plain double evaluation with a generous error bound as a filter, and
// GMP integers (every double is an integer times a power of two) whenever that cannot
// decide. The inner side of each face is decided against a point strictly inside, not taken
// from core's orientation.
#pragma once

#include <gmpxx.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <vector>

#include "convexloc/geometry.hpp"
#include "convexloc/polyhedron.hpp"

namespace reftest {

using convexloc::Location;
using convexloc::Vec3;

// exact sign of det[a - g; b - g; c - g] for a rational g
inline int orientRational(Vec3 a, Vec3 b, Vec3 c, const mpq_class (&g)[3]) {
  mpq_class m[3][3];
  const Vec3 abc[3] = {a, b, c};
  for (int r = 0; r < 3; ++r) {
    m[r][0] = mpq_class(abc[r].x) - g[0];
    m[r][1] = mpq_class(abc[r].y) - g[1];
    m[r][2] = mpq_class(abc[r].z) - g[2];
  }
  mpq_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                  m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                  m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return mpq_sgn(det.get_mpq_t());
}

// the lowest exponent of a last bit among the non-zero values: all are integers times 2^lo
inline int lowestBit(const double* v, int count) {
  int lo = 0;
  bool any = false;
  for (int i = 0; i < count; ++i) {
    if (v[i] == 0.0) continue;
    int e = 0;
    std::frexp(v[i], &e);
    lo = any ? std::min(lo, e - 53) : e - 53;
    any = true;
  }
  return lo;
}

// v * 2^-lo as an exact integer, for an exponent lo at or below v's last bit
inline mpz_class integerAt(double v, int lo) {
  if (v == 0.0) return 0;
  int e = 0;
  const double m = std::frexp(v, &e);  // |m| in [0.5, 1): m * 2^53 is an integer
  mpz_class z(std::ldexp(m, 53));
  mpz_mul_2exp(z.get_mpz_t(), z.get_mpz_t(), static_cast<mp_bitcnt_t>(e - 53 - lo));
  return z;
}

// exact sign of det[a - d; b - d; c - d], of the coordinates scaled to integers
inline int rationalOrient(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const double in[12] = {a.x, a.y, a.z, b.x, b.y, b.z, c.x, c.y, c.z, d.x, d.y, d.z};
  const int lo = lowestBit(in, 12);
  mpz_class z[12];
  for (int i = 0; i < 12; ++i) z[i] = integerAt(in[i], lo);
  mpz_class m[3][3];
  for (int r = 0; r < 3; ++r)
    for (int k = 0; k < 3; ++k) m[r][k] = z[3 * r + k] - z[9 + k];
  const mpz_class det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                        m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                        m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return sgn(det);
}

// The sign of det[a - d; b - d; c - d] for a fixed a, b, c and any d, decided in doubles when
// the value is far from zero. Rows are taken relative to a (det[a - d; b - a; c - a]) so that
// small faces seen from afar stay well conditioned; the rows b - a and c - a and their 2 x 2
// minors are the same for every d, so they are computed once.
// The error bound: each rounding is relative (at most 2^-53) but for a product that
// underflows, which adds an absolute error below 2^-1074; such errors in the minors are
// multiplied by |a - d|. So |error| <= 1e-13 * permanent + (|a - d|_1 + 1) * 2^-1060, with a
// wide margin; where anything overflows, the permanent is not finite and the integers decide.
class OrientFilter {
 public:
  OrientFilter(Vec3 a, Vec3 b, Vec3 c) : a_(a), b_(b), c_(c) {
    const double m[2][3] = {{b.x - a.x, b.y - a.y, b.z - a.z}, {c.x - a.x, c.y - a.y, c.z - a.z}};
    const double t[6] = {m[0][1] * m[1][2], m[0][2] * m[1][1], m[0][0] * m[1][2],
                         m[0][2] * m[1][0], m[0][0] * m[1][1], m[0][1] * m[1][0]};
    for (int k = 0; k < 3; ++k) {
      minor_[k] = t[2 * k] - t[2 * k + 1];
      magnitude_[k] = std::fabs(t[2 * k]) + std::fabs(t[2 * k + 1]);
    }
  }
  // the exact sign for d
  int sign(Vec3 d) const {
    const double u[3] = {a_.x - d.x, a_.y - d.y, a_.z - d.z};
    const double det = u[0] * minor_[0] - u[1] * minor_[1] + u[2] * minor_[2];
    const double perm = std::fabs(u[0]) * magnitude_[0] + std::fabs(u[1]) * magnitude_[1] +
                        std::fabs(u[2]) * magnitude_[2];
    if (std::isfinite(perm) && std::isfinite(det)) {
      const double reach = std::fabs(u[0]) + std::fabs(u[1]) + std::fabs(u[2]) + 1;
      const double bound = 1e-13 * perm + reach * 0x1p-1060;
      if (det > bound) return 1;
      if (-det > bound) return -1;
    }
    return rationalOrient(a_, b_, c_, d);
  }

 private:
  Vec3 a_, b_, c_;
  double minor_[3] = {0, 0, 0};      // of the rows b - a, c - a, cofactor signs left out
  double magnitude_[3] = {0, 0, 0};  // the sums of the minors' products' magnitudes
};

// the exact sign of det[a - d; b - d; c - d]
inline int orient(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  return OrientFilter(a, b, c).sign(d);
}

// A polyhedron's face planes with their inner sides. Faces in exactly the same plane (checked
// exactly) are tested once: the inner side of each is decided against a point strictly
// inside, and the answer for a point is the same for all of them.
class Reference {
 public:
  explicit Reference(const convexloc::ConvexPolyhedron& p)
      : v_(p.vertices().begin(), p.vertices().end()) {
    std::vector<convexloc::ConvexPolyhedron::Triangle> faces(p.triangles().begin(),
                                                             p.triangles().end());
    // a double point near the vertex average: if every face sees it strictly on one and the
    // same side, it lies in the intersection of those open halfspaces, which is non-empty
    // only when they are the inner ones, so that side is the inner side of every face
    long double sx = 0, sy = 0, sz = 0;
    for (const Vec3& w : v_) {
      sx += w.x;
      sy += w.y;
      sz += w.z;
    }
    const long double n = static_cast<long double>(v_.size());
    const Vec3 g{static_cast<double>(sx / n), static_cast<double>(sy / n),
                 static_cast<double>(sz / n)};
    std::vector<int> inner;
    bool agree = true;
    for (const auto& t : faces) {
      inner.push_back(orient(v_[t[0]], v_[t[1]], v_[t[2]], g));
      agree = agree && inner.back() != 0 && inner.back() == inner.front();
    }
    if (!agree) {
      // else the exact vertex centroid, strictly inside any convex polyhedron
      mpq_class q[3];
      for (const Vec3& w : v_) {
        q[0] += w.x;
        q[1] += w.y;
        q[2] += w.z;
      }
      for (auto& x : q) x /= static_cast<long>(v_.size());
      for (std::size_t f = 0; f < faces.size(); ++f)
        inner[f] = orientRational(v_[faces[f][0]], v_[faces[f][1]], v_[faces[f][2]], q);
    }
    // group coplanar faces: bucket by a rounded plane, then compare exactly
    std::map<std::array<long long, 4>, std::vector<std::size_t>> buckets;
    for (std::size_t f = 0; f < faces.size(); ++f) {
      const auto& t = faces[f];
      const Vec3 a = v_[t[0]], b = v_[t[1]], c = v_[t[2]];
      double nv[3] = {(b.y - a.y) * (c.z - a.z) - (b.z - a.z) * (c.y - a.y),
                      (b.z - a.z) * (c.x - a.x) - (b.x - a.x) * (c.z - a.z),
                      (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)};
      const double len = std::sqrt(nv[0] * nv[0] + nv[1] * nv[1] + nv[2] * nv[2]);
      std::array<long long, 4> key{0, 0, 0, 0};
      if (len > 0 && std::isfinite(len)) {
        for (int k = 0; k < 3; ++k) key[k] = std::llround(nv[k] / len * 1e6);
        key[3] = std::llround((nv[0] * a.x + nv[1] * a.y + nv[2] * a.z) / len * 1e6);
      }
      bool joined = false;
      for (std::size_t plane : buckets[key]) {
        const OrientFilter& r = filters_[plane];
        if (inner_[plane] == inner[f] && r.sign(a) == 0 && r.sign(b) == 0 && r.sign(c) == 0) {
          joined = true;
          break;
        }
      }
      if (joined) continue;
      buckets[key].push_back(filters_.size());
      filters_.emplace_back(a, b, c);
      inner_.push_back(inner[f]);
    }
  }

  // the exact class of p
  Location locate(Vec3 p) const {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return Location::Outside;
    bool zero = false;
    for (std::size_t f = 0; f < filters_.size(); ++f) {
      int s = side(f, p);
      if (s < 0) return Location::Outside;
      zero = zero || s == 0;
    }
    return zero ? Location::Boundary : Location::Inside;
  }
  // +1 when p is on the inner side of plane f, 0 on it, -1 outer
  int side(std::size_t f, Vec3 p) const { return inner_[f] * filters_[f].sign(p); }
  // every plane's inner side is strictly decided
  bool sound() const {
    for (int s : inner_)
      if (s == 0) return false;
    return true;
  }
  // the number of distinct face planes
  std::size_t planes() const { return filters_.size(); }

 private:
  std::vector<Vec3> v_;
  std::vector<OrientFilter> filters_;  // one face per distinct plane: its sign for a point
  std::vector<int> inner_;
};

}  // namespace reftest
