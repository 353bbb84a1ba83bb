// convexloc — the generators' prisms: a cylinder over a regular polygon and a tilted prism
// over a large lattice polygon, triangulated the way CAD programs write them (each side quad
// as two triangles, each cap as a fan of slivers from one corner).
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <numeric>
#include <vector>

#include "detail/prisms.hpp"

namespace convexloc::detail {
namespace {

// the prism over `base` (counter-clockwise in x, y at z = 0) with its top at base + lift:
// side quads as two triangles, caps as fans from corner 0, counter-clockwise from outside
MeshData prismOver(const std::vector<Vec2>& base, Vec3 lift) {
  MeshData mesh;
  const auto n = static_cast<std::uint32_t>(base.size());
  for (const Vec2& p : base) mesh.addVertex({p.x, p.y, 0});
  for (const Vec2& p : base) mesh.addVertex({p.x + lift.x, p.y + lift.y, lift.z});
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t j = (i + 1) % n;
    mesh.addFace({i, j, n + j});
    mesh.addFace({i, n + j, n + i});
  }
  for (std::uint32_t i = 1; i + 1 < n; ++i) {
    mesh.addFace({0, i + 1, i});          // the bottom, seen from below
    mesh.addFace({n, n + i, n + i + 1});  // the top, seen from above
  }
  return mesh;
}

}  // namespace

MeshData cylinderMesh(std::size_t sides) {
  std::vector<Vec2> base(sides);
  for (std::size_t i = 0; i < sides; ++i) {
    const double a = 2 * std::numbers::pi * static_cast<double>(i) / static_cast<double>(sides);
    base[i] = {std::cos(a), std::sin(a)};
  }
  MeshData mesh = prismOver(base, {0, 0, 2});
  for (Vec3& p : mesh.vertices) p.z -= 1;
  return mesh;
}

MeshData latticePrismMesh(std::size_t corners) {
  // the primitive vectors with max(|a|, |b|) <= r number about 2.43 r^2
  const auto r =
      static_cast<std::int64_t>(std::ceil(std::sqrt(static_cast<double>(corners) / 2.43)));
  std::vector<std::pair<double, Vec2>> steps;
  for (std::int64_t a = -r; a <= r; ++a)
    for (std::int64_t b = -r; b <= r; ++b)
      if (std::gcd(a, b) == 1)
        steps.push_back({std::atan2(static_cast<double>(b), static_cast<double>(a)),
                         {static_cast<double>(a), static_cast<double>(b)}});
  // distinct primitive directions differ in angle by far more than atan2's rounding
  std::sort(steps.begin(), steps.end(),
            [](const auto& p, const auto& q) { return p.first < q.first; });
  std::vector<Vec2> base;
  Vec2 at{0, 0};
  double lo = 0, hi = 0;
  for (const auto& s : steps) {
    base.push_back(at);
    at = {at.x + s.second.x, at.y + s.second.y};
    lo = std::min(lo, at.x), hi = std::max(hi, at.x);
  }
  const double width = hi - lo, shift = std::floor((lo + hi) / 2);
  double bottom = 0, top = 0;
  for (const Vec2& p : base) bottom = std::min(bottom, p.y), top = std::max(top, p.y);
  const double middle = std::floor((bottom + top) / 2);
  for (Vec2& p : base) p = {p.x - shift, p.y - middle};
  return prismOver(base, {std::floor(width / 3), std::floor(width / 5), width});
}

}  // namespace convexloc::detail
