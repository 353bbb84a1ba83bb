// Hard query points for the 3D locators: vertices, points on edges and faces (exact where
// a double lies there), their ulp neighbours, points along the cube's edge and diagonal
// directions from the cubemap's centre, points on the cubemap's cell borders, and the centre.
#pragma once

#include <cmath>
#include <limits>
#include <optional>
#include <vector>

#include "convexloc/generate2d.hpp"
#include "convexloc/locate3d.hpp"
#include "convexloc/polyhedron.hpp"
#include "reference3d.hpp"

namespace adversarial3d {

using convexloc::Vec3;

// v moved by `steps` ulps (negative: down)
inline double ulps(double v, int steps) {
  const double inf = std::numeric_limits<double>::infinity();
  for (; steps > 0; --steps) v = std::nextafter(v, inf);
  for (; steps < 0; ++steps) v = std::nextafter(v, -inf);
  return v;
}

// p and its neighbours one ulp away along each axis, and along the three diagonals
inline void withNeighbours(std::vector<Vec3>& out, Vec3 p) {
  out.push_back(p);
  for (int s : {-1, 1}) {
    out.push_back({ulps(p.x, s), p.y, p.z});
    out.push_back({p.x, ulps(p.y, s), p.z});
    out.push_back({p.x, p.y, ulps(p.z, s)});
    out.push_back({ulps(p.x, s), ulps(p.y, s), ulps(p.z, s)});
  }
}

// p moved onto the plane of (a, b, c) by a few ulps of one coordinate, when that reaches it
inline Vec3 ontoPlane(Vec3 a, Vec3 b, Vec3 c, Vec3 p) {
  for (int axis = 0; axis < 3; ++axis)
    for (int k = 0; k <= 6; ++k)
      for (int s : {1, -1}) {
        Vec3 q = p;
        double& x = axis == 0 ? q.x : axis == 1 ? q.y : q.z;
        x = ulps(x, s * k);
        if (reftest::orient(a, b, c, q) == 0) return q;
      }
  return p;
}

// vertices, edge and face points of the polyhedron, each with its ulp neighbours; at most
// about `budget` base points
inline std::vector<Vec3> surfacePoints(const convexloc::ConvexPolyhedron& p, std::size_t budget,
                                       convexloc::Rng& rng) {
  std::vector<Vec3> out;
  auto v = p.vertices();
  auto tri = p.triangles();
  const std::size_t step =
      std::max<std::size_t>(1, tri.size() / std::max<std::size_t>(1, budget / 4));
  for (std::size_t i = 0; i < v.size(); i += std::max<std::size_t>(1, v.size() / budget))
    withNeighbours(out, v[i]);
  for (std::size_t t = rng.below(step); t < tri.size(); t += step) {
    const Vec3 a = v[tri[t][0]], b = v[tri[t][1]], c = v[tri[t][2]];
    // the edge's midpoint and a point a third along it
    for (double s : {0.5, 1.0 / 3})
      withNeighbours(out, {a.x + s * (b.x - a.x), a.y + s * (b.y - a.y), a.z + s * (b.z - a.z)});
    // the face's centroid and a random point, moved onto its plane where possible
    const Vec3 m{(a.x + b.x + c.x) / 3, (a.y + b.y + c.y) / 3, (a.z + b.z + c.z) / 3};
    withNeighbours(out, ontoPlane(a, b, c, m));
    double s = rng.uniform(), r = rng.uniform();
    if (s + r > 1) s = 1 - s, r = 1 - r;
    withNeighbours(out, ontoPlane(a, b, c,
                                  {a.x + s * (b.x - a.x) + r * (c.x - a.x),
                                   a.y + s * (b.y - a.y) + r * (c.y - a.y),
                                   a.z + s * (b.z - a.z) + r * (c.z - a.z)}));
  }
  return out;
}

// where the ray from c along w leaves the polyhedron, roughly (floating point)
inline double exitScale(const convexloc::ConvexPolyhedron& p, Vec3 c, Vec3 w) {
  double best = std::numeric_limits<double>::infinity();
  auto v = p.vertices();
  for (const auto& t : p.triangles()) {
    const Vec3 a = v[t[0]], b = v[t[1]], d = v[t[2]];
    const double ux = b.x - a.x, uy = b.y - a.y, uz = b.z - a.z;
    const double vx = d.x - a.x, vy = d.y - a.y, vz = d.z - a.z;
    const double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    const double den = nx * w.x + ny * w.y + nz * w.z;
    if (den <= 0) continue;
    const double num = nx * (a.x - c.x) + ny * (a.y - c.y) + nz * (a.z - c.z);
    best = std::min(best, num / den);
  }
  return best;
}

// points at and around the surface along w from c: the crossing scaled by 1 and a hair
// either side, each with its ulp neighbours
inline void alongRay(std::vector<Vec3>& out, const convexloc::ConvexPolyhedron& p, Vec3 c, Vec3 w) {
  const double lambda = exitScale(p, c, w);
  if (!std::isfinite(lambda)) return;
  for (double f : {0.5, 1.0 - 1e-12, 1.0, 1.0 + 1e-12, 2.0})
    withNeighbours(out, {c.x + f * lambda * w.x, c.y + f * lambda * w.y, c.z + f * lambda * w.z});
}

// points along the 26 cube edge, face and diagonal directions from the cubemap's centre, on
// cell borders of the base grid, and the centre itself, each with its ulp neighbours
inline std::vector<Vec3> cubemapPoints(const convexloc::ConvexPolyhedron& p,
                                       const convexloc::CubemapLocator& cm, convexloc::Rng& rng) {
  std::vector<Vec3> out;
  const std::optional<Vec3> centre = cm.centre();
  if (!centre) return out;
  const Vec3 c = *centre;
  withNeighbours(out, c);
  for (int x = -1; x <= 1; ++x)
    for (int y = -1; y <= 1; ++y)
      for (int z = -1; z <= 1; ++z)
        if (x || y || z) alongRay(out, p, c, {double(x), double(y), double(z)});
  // the feet of the perpendiculars from the centre to sampled face planes: there the face
  // lies nearest the centre, where the cells' inner radii must not reach past it
  auto v = p.vertices();
  auto tri = p.triangles();
  const std::size_t step = std::max<std::size_t>(1, tri.size() / 150);
  for (std::size_t f = 0; f < tri.size(); f += step) {
    using L = long double;
    const Vec3 a = v[tri[f][0]], b = v[tri[f][1]], d = v[tri[f][2]];
    const L ux = L(b.x) - a.x, uy = L(b.y) - a.y, uz = L(b.z) - a.z;
    const L vx = L(d.x) - a.x, vy = L(d.y) - a.y, vz = L(d.z) - a.z;
    const L nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
    const L k = (nx * (L(a.x) - c.x) + ny * (L(a.y) - c.y) + nz * (L(a.z) - c.z)) /
                (nx * nx + ny * ny + nz * nz);
    const Vec3 w{static_cast<double>(k * nx), static_cast<double>(k * ny),
                 static_cast<double>(k * nz)};
    if (std::isfinite(w.x) && std::isfinite(w.y) && std::isfinite(w.z)) alongRay(out, p, c, w);
  }
  // cell borders: s = -1 + i / K exactly, on random cube faces
  const double K = cm.resolution() / 2.0;
  for (int k = 0; k < 60; ++k) {
    const int face = static_cast<int>(rng.below(6));
    const double s = -1 + static_cast<double>(rng.below(cm.resolution() + 1)) / K;
    const double t = rng.below(4) == 0
                         ? -1 + static_cast<double>(rng.below(cm.resolution() + 1)) / K
                         : rng.uniform(-1, 1);
    const int a = face / 2;
    double w[3];
    w[a] = (face & 1) ? -1 : 1;
    w[(a + 1) % 3] = s;
    w[(a + 2) % 3] = t;
    alongRay(out, p, c, {w[0], w[1], w[2]});
  }
  // cell corners, down to the third quadtree level: along these rays the cells' outer radii
  // meet the face planes (a leaf's radii bound only the part of each face its pyramid holds)
  for (int k = 0; k < 60; ++k) {
    const int face = static_cast<int>(rng.below(6));
    const std::uint32_t level = static_cast<std::uint32_t>(rng.below(4));
    const std::uint32_t cells = cm.resolution() << level;
    const double Kl = std::ldexp(K, static_cast<int>(level));
    const int a = face / 2;
    double w[3];
    w[a] = (face & 1) ? -1 : 1;
    w[(a + 1) % 3] = -1 + static_cast<double>(rng.below(cells + 1)) / Kl;
    w[(a + 2) % 3] = -1 + static_cast<double>(rng.below(cells + 1)) / Kl;
    alongRay(out, p, c, {w[0], w[1], w[2]});
  }
  return out;
}

}  // namespace adversarial3d
