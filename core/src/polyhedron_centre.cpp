// convexloc — the global checks of a polyhedron: a point strictly inside, and the winding.
//
// Locally convex is convex only if the surface wraps around once. Seen from a point c
// strictly inside every face plane, each triangle is a positively oriented spherical
// triangle and neighbours lie on opposite sides of their common edge, so the central
// projection is a branched covering of the sphere; its degree, the total solid angle over
// 4 pi, is 1 exactly when the surface is the boundary of the convex solid.
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include "convexloc/error.hpp"
#include "convexloc/predicates.hpp"
#include "detail/exact_number.hpp"
#include "detail/polyhedron_build.hpp"

namespace convexloc::detail {
namespace {

// the solid angle of triangle a, b, c seen from the origin (Van Oosterom and Strackee)
double solidAngle(Vec3 a, Vec3 b, Vec3 c) {
  auto dot = [](Vec3 u, Vec3 v) { return u.x * v.x + u.y * v.y + u.z * v.z; };
  auto len = [&](Vec3 u) { return std::sqrt(dot(u, u)); };
  double det =
      a.x * (b.y * c.z - b.z * c.y) - a.y * (b.x * c.z - b.z * c.x) + a.z * (b.x * c.y - b.y * c.x);
  double la = len(a), lb = len(b), lc = len(c);
  double den = la * lb * lc + dot(a, b) * lc + dot(a, c) * lb + dot(b, c) * la;
  return 2.0 * std::atan2(det, den);
}

// exact sign of det[p - g; q - g; r - g] for a rational g
int rationalOrient(Vec3 p, Vec3 q, Vec3 r, const ExactRational (&g)[3]) {
  const ExactRational m[3][3] = {
      {exactRational(p.x) - g[0], exactRational(p.y) - g[1], exactRational(p.z) - g[2]},
      {exactRational(q.x) - g[0], exactRational(q.y) - g[1], exactRational(q.z) - g[2]},
      {exactRational(r.x) - g[0], exactRational(r.y) - g[1], exactRational(r.z) - g[2]}};
  const ExactRational det = m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
                            m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
                            m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  return det.sign();
}

// the double next to v in direction dir (-1, 0 or +1)
double nudge(double v, int dir) {
  if (dir == 0) return v;
  return std::nextafter(v, dir > 0 ? HUGE_VAL : -HUGE_VAL);
}

// the points that may be strictly inside: the volume centroid, the vertex average, the
// tetrahedron's centroid, and the doubles around the first of them (for polyhedra a few
// ulps thick)
std::vector<Vec3> centreCandidates(const std::vector<Vec3>& v,
                                   const std::vector<ConvexPolyhedron::Triangle>& tri,
                                   const std::uint32_t (&tetra)[4]) {
  const Vec3 o = v[0];
  long double vol = 0, cx = 0, cy = 0, cz = 0, ax = 0, ay = 0, az = 0;
  for (const ConvexPolyhedron::Triangle& t : tri) {
    long double p[3][3];
    const long double d = sixVolume(o, v[t[0]], v[t[1]], v[t[2]], p);
    vol += d;
    cx += d * (p[0][0] + p[1][0] + p[2][0]);
    cy += d * (p[0][1] + p[1][1] + p[2][1]);
    cz += d * (p[0][2] + p[1][2] + p[2][2]);
  }
  for (const Vec3& w : v) {
    ax += (static_cast<long double>(w.x) - o.x) / v.size();
    ay += (static_cast<long double>(w.y) - o.y) / v.size();
    az += (static_cast<long double>(w.z) - o.z) / v.size();
  }
  auto at = [&](long double x, long double y, long double z) {
    return Vec3{static_cast<double>(o.x + x), static_cast<double>(o.y + y),
                static_cast<double>(o.z + z)};
  };
  std::vector<Vec3> candidates;
  if (vol != 0) candidates.push_back(at(cx / (4 * vol), cy / (4 * vol), cz / (4 * vol)));
  candidates.push_back(at(ax, ay, az));
  long double tx = 0, ty = 0, tz = 0;
  for (std::uint32_t k : tetra) {
    tx += (static_cast<long double>(v[k].x) - o.x) / 4;
    ty += (static_cast<long double>(v[k].y) - o.y) / 4;
    tz += (static_cast<long double>(v[k].z) - o.z) / 4;
  }
  candidates.push_back(at(tx, ty, tz));
  const Vec3 first = candidates.front();
  for (int dx = -1; dx <= 1; ++dx)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dz = -1; dz <= 1; ++dz)
        if (dx || dy || dz)
          candidates.push_back({nudge(first.x, dx), nudge(first.y, dy), nudge(first.z, dz)});
  return candidates;
}

// The directions from the exact point g to the vertices, each coordinate axis and then each
// direction scaled exactly by a power of two before it is rounded (toward zero): no
// coordinate that is not zero becomes zero or infinite, however thin the solid is along an
// axis (a box one subnormal step thick beside one as wide as the doubles reach) or however
// far apart its vertices lie. Only a coordinate below 2^-1074 of its direction's largest one
// is lost, which no solid angle notices.
std::vector<Vec3> exactDirections(const std::vector<Vec3>& v, const ExactRational (&g)[3]) {
  constexpr long kNone = std::numeric_limits<long>::min();
  std::vector<std::array<ExactRational, 3>> d(v.size());
  long axis[3] = {kNone, kNone, kNone};
  for (std::size_t i = 0; i < v.size(); ++i) {
    d[i] = {exactRational(v[i].x) - g[0], exactRational(v[i].y) - g[1],
            exactRational(v[i].z) - g[2]};
    for (int a = 0; a < 3; ++a)
      if (d[i][a].sign() != 0) axis[a] = std::max(axis[a], binaryExponent(d[i][a]));
  }
  std::vector<Vec3> rel(v.size());
  for (std::size_t i = 0; i < v.size(); ++i) {
    long top = kNone;
    for (int a = 0; a < 3; ++a)
      if (d[i][a].sign() != 0) {
        d[i][a] = timesPowerOfTwo(d[i][a], -axis[a]);
        top = std::max(top, binaryExponent(d[i][a]));
      }
    if (top == kNone) continue;  // the vertex is g: no direction (not a vertex of a solid)
    auto round = [&](int a) {
      return toDouble(timesPowerOfTwo(d[i][a], -top), Rounding::TowardZero);
    };
    rel[i] = {round(0), round(1), round(2)};
  }
  return rel;
}

// Scales each axis by its own power of two, bringing the largest |coordinate| into [1, 2). A
// positive scaling of the axes does not change the winding number, and it makes a needle or
// slab far thinner along one axis than along another well shaped: at one common scale its
// thin directions are lost in rounding, and triangles that see 0 turn get half a turn each.
// False where a coordinate that is not zero came out below the normal doubles (2^-1022 of its
// axis's extent or less), its bits cut or gone.
bool scaleAxes(std::vector<Vec3>& rel) {
  Vec3 extent{};
  for (const Vec3& r : rel)
    extent = {std::max(extent.x, std::fabs(r.x)), std::max(extent.y, std::fabs(r.y)),
              std::max(extent.z, std::fabs(r.z))};
  auto shiftFor = [](double e) {
    return e > 0 ? -std::ilogb(e) : 0;
  };  // 2^shift may not be a double
  const int sx = shiftFor(extent.x), sy = shiftFor(extent.y), sz = shiftFor(extent.z);
  bool whole = true;
  auto scaled = [&whole](double c, int shift) {
    const double out = std::ldexp(c, shift);
    whole &= c == 0 || std::fabs(out) >= std::numeric_limits<double>::min();
    return out;
  };
  for (Vec3& r : rel) r = {scaled(r.x, sx), scaled(r.y, sy), scaled(r.z, sz)};
  return whole;
}

}  // namespace

void PolyhedronBuilder::findCentre() {
  const std::vector<Vec3>& v = out_.vertices_;
  const std::vector<Triangle>& tri = out_.triangles_;
  auto insideAll = [&](Vec3 c, std::uint32_t& hint) {
    if (!std::isfinite(c.x) || !std::isfinite(c.y) || !std::isfinite(c.z)) return false;
    if (orient3d(v[tri[hint][0]], v[tri[hint][1]], v[tri[hint][2]], c) <= 0) return false;
    for (std::uint32_t t = 0; t < tri.size(); ++t)
      if (orient3d(v[tri[t][0]], v[tri[t][1]], v[tri[t][2]], c) <= 0) {
        hint = t;
        return false;
      }
    return true;
  };
  std::uint32_t hint = 0;
  for (Vec3 c : centreCandidates(v, tri, tetra_))
    if (insideAll(c, hint)) {
      out_.centre_ = c;
      return;
    }
}

std::vector<Vec3> PolyhedronBuilder::directionsFromInside() const {
  const std::vector<Vec3>& v = out_.vertices_;
  std::vector<Vec3> rel(v.size());
  ExactRational g[3];  // the exact centre when there is no double one
  if (out_.centre_) {
    const Vec3 c = *out_.centre_;
    for (std::size_t i = 0; i < v.size(); ++i) rel[i] = {v[i].x - c.x, v[i].y - c.y, v[i].z - c.z};
  } else {
    // no double point works: decide with the exact centroid g of the tetrahedron found above,
    // strictly inside the solid if it is convex. A face with g on its outer side or in its
    // plane has one of the four vertices strictly outside: the surface is not convex.
    for (std::uint32_t k : tetra_) {
      g[0] += exactRational(v[k].x) / 4;
      g[1] += exactRational(v[k].y) / 4;
      g[2] += exactRational(v[k].z) / 4;
    }
    for (std::uint32_t t = 0; t < out_.triangles_.size(); ++t) {
      const Vec3 p = v[out_.triangles_[t][0]], q = v[out_.triangles_[t][1]],
                 r = v[out_.triangles_[t][2]];
      if (rationalOrient(p, q, r, g) > 0) continue;
      std::uint32_t out = tetra_[0];
      for (std::uint32_t k : tetra_)
        if (orient3d(p, q, r, v[k]) < 0) out = k;
      throw GeometryError(
          "not convex: " + vertexName(out) + " lies outside the plane of " + faceName(t),
          triangleLine(t));
    }
    return exactDirections(v, g);
  }
  // Differences of doubles are exact where they are subnormal and otherwise rounded to 53
  // bits, never to zero. Where one overflows, or where scaling its axis cuts a coordinate, the
  // exact way is taken.
  const bool overflow = std::any_of(rel.begin(), rel.end(), [](const Vec3& r) {
    return !std::isfinite(r.x) || !std::isfinite(r.y) || !std::isfinite(r.z);
  });
  if (overflow || !scaleAxes(rel)) {
    const Vec3 c = *out_.centre_;
    g[0] = exactRational(c.x);
    g[1] = exactRational(c.y);
    g[2] = exactRational(c.z);
    return exactDirections(v, g);
  }
  // a solid angle depends on its three directions only: each scaled exactly (a power of two)
  // to a largest coordinate in [1, 2), so that no length or product in it overflows or
  // underflows however far the vertices lie
  for (Vec3& r : rel) {
    const double m = std::max({std::fabs(r.x), std::fabs(r.y), std::fabs(r.z)});
    if (!(m > 0)) continue;
    const int e = -std::ilogb(m);
    r = {std::ldexp(r.x, e), std::ldexp(r.y, e), std::ldexp(r.z, e)};
  }
  return rel;
}

void PolyhedronBuilder::checkWindsOnce() const {
  // every face has the inside point strictly on its inner side, so each solid angle is
  // positive and the sum is 4 pi times the degree, up to rounding far below the gap between
  // 4 pi and 8 pi
  const std::vector<Vec3> rel = directionsFromInside();
  double total = 0;
  for (const Triangle& t : out_.triangles_) total += solidAngle(rel[t[0]], rel[t[1]], rel[t[2]]);
  const double turns = total / (4 * std::numbers::pi);
  if (!(turns < 1.5))
    throw GeometryError("not convex: the surface winds " + std::to_string(std::lround(turns)) +
                        " times around its inside" +
                        (out_.centre_ ? " point " + show(*out_.centre_) : std::string()));
}

void PolyhedronBuilder::findBounds() {
  const std::vector<Vec3>& v = out_.vertices_;
  Box3& box = out_.bounds_;
  box = {v[0], v[0]};
  for (const Vec3& w : v) {
    box.lo = {std::min(box.lo.x, w.x), std::min(box.lo.y, w.y), std::min(box.lo.z, w.z)};
    box.hi = {std::max(box.hi.x, w.x), std::max(box.hi.y, w.y), std::max(box.hi.z, w.z)};
  }
}

}  // namespace convexloc::detail
