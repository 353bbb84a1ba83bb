// An exact reference for point-in-convex-polyhedron, for tests only. It shares no code with
// core's predicates: a plain double evaluation with a generous error bound as a filter, and
// GMP rationals (mpq_class) whenever that cannot decide. The inner side of each face is
// decided against a point strictly inside, not taken from core's orientation.
#pragma once

#include <gmpxx.h>

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

// exact sign of det[a - d; b - d; c - d] in rationals
inline int rationalOrient(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  const mpq_class g[3] = {d.x, d.y, d.z};
  return orientRational(a, b, c, g);
}

// a difference whose triple products stay normal doubles: zero, or in [1e-90, 1e90]
inline bool tameDiff(double v) {
  double a = std::fabs(v);
  return a == 0.0 || (a >= 1e-90 && a <= 1e90);
}

// The same sign, decided in doubles when the value is far from zero. Rows are taken
// relative to a (det[a - d; b - d; c - d] = det[a - d; b - a; c - a]) so that small faces
// seen from afar stay well conditioned.
inline int orient(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  double m[3][3] = {{a.x - d.x, a.y - d.y, a.z - d.z},
                    {b.x - a.x, b.y - a.y, b.z - a.z},
                    {c.x - a.x, c.y - a.y, c.z - a.z}};
  bool tame = true;
  for (auto& row : m)
    for (double x : row) tame = tame && tameDiff(x);
  if (tame) {
    double t0 = m[1][1] * m[2][2], t1 = m[1][2] * m[2][1];
    double t2 = m[1][0] * m[2][2], t3 = m[1][2] * m[2][0];
    double t4 = m[1][0] * m[2][1], t5 = m[1][1] * m[2][0];
    double det = m[0][0] * (t0 - t1) - m[0][1] * (t2 - t3) + m[0][2] * (t4 - t5);
    double perm = std::fabs(m[0][0]) * (std::fabs(t0) + std::fabs(t1)) +
                  std::fabs(m[0][1]) * (std::fabs(t2) + std::fabs(t3)) +
                  std::fabs(m[0][2]) * (std::fabs(t4) + std::fabs(t5));
    double bound = 1e-13 * perm;  // about a hundred times the true error bound
    if (det > bound) return 1;
    if (-det > bound) return -1;
  }
  return rationalOrient(a, b, c, d);
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
        const auto& r = planes_[plane];
        if (inner_[plane] == inner[f] && orient(v_[r[0]], v_[r[1]], v_[r[2]], a) == 0 &&
            orient(v_[r[0]], v_[r[1]], v_[r[2]], b) == 0 &&
            orient(v_[r[0]], v_[r[1]], v_[r[2]], c) == 0) {
          joined = true;
          break;
        }
      }
      if (joined) continue;
      buckets[key].push_back(planes_.size());
      planes_.push_back(t);
      inner_.push_back(inner[f]);
    }
  }

  // the exact class of p
  Location locate(Vec3 p) const {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return Location::Outside;
    bool zero = false;
    for (std::size_t f = 0; f < planes_.size(); ++f) {
      int s = side(f, p);
      if (s < 0) return Location::Outside;
      zero = zero || s == 0;
    }
    return zero ? Location::Boundary : Location::Inside;
  }
  // +1 when p is on the inner side of plane f, 0 on it, -1 outer
  int side(std::size_t f, Vec3 p) const {
    const auto& t = planes_[f];
    return inner_[f] * orient(v_[t[0]], v_[t[1]], v_[t[2]], p);
  }
  // every plane's inner side is strictly decided
  bool sound() const {
    for (int s : inner_)
      if (s == 0) return false;
    return true;
  }
  // the number of distinct face planes
  std::size_t planes() const { return planes_.size(); }

 private:
  std::vector<Vec3> v_;
  std::vector<convexloc::ConvexPolyhedron::Triangle> planes_;  // one face per distinct plane
  std::vector<int> inner_;
};

}  // namespace reftest
