// An exact reference for point-in-convex-polyhedron, for tests only. It shares no code with
// core's predicates: a plain double evaluation with a generous error bound as a filter, and
// GMP rationals (mpq_class) whenever that cannot decide. The inner side of each face is
// taken from the exact vertex centroid, not from core's orientation.
#pragma once

#include <gmpxx.h>

#include <cmath>
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

// the same sign, decided in doubles when the value is far from zero
inline int orient(Vec3 a, Vec3 b, Vec3 c, Vec3 d) {
  double m[3][3] = {{a.x - d.x, a.y - d.y, a.z - d.z},
                    {b.x - d.x, b.y - d.y, b.z - d.z},
                    {c.x - d.x, c.y - d.y, c.z - d.z}};
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
    double bound = 1e-12 * perm;  // three orders of magnitude above the true error bound
    if (det > bound) return 1;
    if (-det > bound) return -1;
  }
  return rationalOrient(a, b, c, d);
}

// A polyhedron's faces with their inner sides, decided once against the exact centroid of
// the vertices (strictly inside a convex polyhedron with positive volume).
class Reference {
public:
  explicit Reference(const convexloc::ConvexPolyhedron& p)
      : v_(p.vertices().begin(), p.vertices().end()) {
    mpq_class g[3];
    for (const Vec3& w : v_) {
      g[0] += w.x;
      g[1] += w.y;
      g[2] += w.z;
    }
    for (auto& x : g) x /= static_cast<long>(v_.size());
    for (const auto& t : p.triangles()) {
      faces_.push_back(t);
      inner_.push_back(orientRational(v_[t[0]], v_[t[1]], v_[t[2]], g));
    }
  }

  // the exact class of p
  Location locate(Vec3 p) const {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return Location::Outside;
    bool zero = false;
    for (std::size_t f = 0; f < faces_.size(); ++f) {
      int s = side(f, p);
      if (s < 0) return Location::Outside;
      zero = zero || s == 0;
    }
    return zero ? Location::Boundary : Location::Inside;
  }
  // +1 when p is on the inner side of face f, 0 on its plane, -1 outer
  int side(std::size_t f, Vec3 p) const {
    const auto& t = faces_[f];
    return inner_[f] * orient(v_[t[0]], v_[t[1]], v_[t[2]], p);
  }
  // faces whose centroid sign is not strictly decided (must be none)
  bool sound() const {
    for (int s : inner_)
      if (s == 0) return false;
    return true;
  }

private:
  std::vector<Vec3> v_;
  std::vector<convexloc::ConvexPolyhedron::Triangle> faces_;
  std::vector<int> inner_;
};

}  // namespace reftest
