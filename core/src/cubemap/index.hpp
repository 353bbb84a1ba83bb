// convexloc (internal) — the cube map's cells: the coordinates and the index every part of
// it shares (build, radii, query, batch), and why the query is exact.
//
// Coordinates. For d = p - c, the major axis a is the first of x, y, z with the largest
// |d_a|; the cube face is 2a (d_a > 0) or 2a + 1 (d_a < 0); with (u, v) = (a + 1, a + 2)
// mod 3, the face coordinates are s = d_u / |d_a| and t = d_v / |d_a| in [-1, 1], computed
// as d_u * (1 / |d_a|): within 2 ulps of the quotient, perhaps 1 + 1 ulp in size (indices are
// clamped to the grid). At level k a face has n_k = G 2^k cells per side; cell (i, j) is
// s in [-1 + i / K_k, -1 + (i + 1) / K_k], t likewise, with K_k = n_k / 2 (levelScale), and
// the index of a coordinate is floor((s + 1) K_k) clamped to n_k - 1. The query computes it
// once at the deepest level D, as floor((s + 1) K_D) with K_D = K_k 2^(D - k); scaling by a
// power of two is exact, so shifting right by D - k gives the index at level k, consistent
// across levels. The computed (s, t) is within a few ulps of the exact direction's, even
// where the computed major axis differs from the exact one (then the exact direction lies
// just past the cube edge, at |s| <= 1 + a few ulps, still in the face's plane).
//
// Build (cubemap/build.cpp). A face (a, b, c') seen from the centre spans the cone
// {w : n_i . w >= 0, i = 0..2} with n_i = (v_i - c) x (v_(i+1) - v_i) (it is positively
// oriented from c). On cube face (a, sigma), with w = (sigma, s, t), each n_i . w >= 0 is a
// half-plane in (s, t). Computed in floating point, n_i has an error we bound (kNormalError
// times its permanent); relaxing each half-plane by that bound, plus kSlack per unit of its
// (s, t) gradient, and clipping the square [-1 - kReach, 1 + kReach]^2 by them gives a
// polygon P that contains a disc of radius about kSlack around every exact point of the
// cone's section. A face is listed in every cell whose square, grown by
// kReach = kMargin + kSlack, meets P (rasterised row by row, P being convex up to rounding
// far below kSlack).
//
// Why the query is exact. Let p != c, and let T be a face through which the ray from c
// through p leaves the polyhedron (one exists: c is strictly inside). The exact direction of
// p - c lies in T's cone, at a point w* of the computed cube face's plane that is within a
// few ulps of the computed (s, t), hence inside the computed cell's square grown by
// kMargin. The disc of radius kSlack around w* then lies in P and in the square grown by
// kReach, so T is listed in that cell. The ray meets T at the surface point y. If p is
// strictly inside, it is strictly inside every face plane: all signs positive, Inside. If p
// is on the surface, p = y lies in T's plane (sign 0) and on the inner side of every plane:
// Boundary. If p is outside, p lies beyond y on the ray, and T's plane, which has c strictly
// inside, separates them: T's sign is negative, Outside. A negative sign for any listed face
// is Outside in any case. So "any negative: Outside; else any zero: Boundary; else Inside"
// over the listed faces is exact. A crowded cell is searched by a walk from one of its
// faces, which ends at such a face T; if the walk runs too long the cell's list is tested. A
// crowded cell over a zone of thin faces is searched by bisection (cubemap/zones.cpp), and
// one whose faces are thin around some axis by bisection around it (cubemap/sectors.cpp).
// The radii that decide most points first are sound by the argument of detail/radii.hpp,
// and the slabs that decide most of the rest by cubemap/slabs.cpp's.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <vector>

#include "convexloc/locate3d.hpp"

namespace convexloc::cubemap {

// the inner-node mark in Node::count
inline constexpr std::uint32_t kInner = 0xffffffffu;
// A leaf over a zone (cubemap/zones.cpp): Node::count is kZoneLeaf | (1 + others); its first
// entry indexes zoneRanges_, the others follow. Never kInner: others stay below 2^31 - 1.
inline constexpr std::uint32_t kZoneLeaf = 0x80000000u;

// A leaf over a fan of thin faces sorted around an axis (cubemap/sectors.cpp): Node::count
// is kSectorLeaf | (1 + others); its first entry indexes sectorRanges_, the others follow.
// A fan's key entry: a corner's index (below 2^27) and the window's faces before the key's
// place (5 bits). No leaf lists 2^30 faces (a polyhedron has at most 2^27).
inline constexpr std::uint32_t kSectorLeaf = 0x40000000u;
inline constexpr int kSectorBackShift = 27;
inline constexpr std::uint32_t kSectorKey = (1u << kSectorBackShift) - 1, kSectorBack = 31;

// whether a leaf's count marks a zone leaf
inline bool isZoneLeaf(std::uint32_t count) {
  return count != kInner && (count & kZoneLeaf);
}

// whether a leaf's count marks a sector leaf
inline bool isSectorLeaf(std::uint32_t count) {
  return count != kInner && !(count & kZoneLeaf) && (count & kSectorLeaf);
}

// the entries a leaf's count stands for
inline std::uint32_t leafEntries(std::uint32_t count) {
  return count & ~(kZoneLeaf | kSectorLeaf);
}

// K = (cells per side) / 2 at `level` over base resolution g: cell i spans
// [-1 + i / K, -1 + (i + 1) / K]
inline double levelScale(std::uint32_t g, int level) {
  return std::ldexp(g / 2.0, level);
}

// the node index of base cell (i, j) of cube face `face`, for base resolution g: faces one
// after the other, each row by row
[[gnu::always_inline]] inline std::uint64_t baseCellIndex(std::uint64_t face, std::uint64_t i,
                                                          std::uint64_t j, std::uint32_t g) {
  return (face * g + j) * g + i;
}

// a base cell's place: cube face, column, row
struct BaseCell {
  int face = 0;
  std::uint32_t i = 0, j = 0;
};

// the inverse of baseCellIndex
inline BaseCell baseCellAt(std::size_t index, std::uint32_t g) {
  const std::size_t perFace = static_cast<std::size_t>(g) * g;
  const auto rest = static_cast<std::uint32_t>(index % perFace);
  return {static_cast<int>(index / perFace), rest % g, rest / g};
}

// the direction (on the cube of half-size 1 around the centre) of point (s, t) of a face
inline Vec3 cubeDirection(int face, double s, double t) {
  const int a = face / 2;
  double w[3];
  w[a] = (face & 1) ? -1.0 : 1.0;
  w[(a + 1) % 3] = s;
  w[(a + 2) % 3] = t;
  return {w[0], w[1], w[2]};
}

// The cube face of direction d (finite) and its face coordinates (s, t), as the file's head
// sets out: the major axis a (x before y before z on ties, without a branch: random
// directions would mispredict one), the face 2a or 2a + 1 by its sign, and (s, t) =
// (d_u, d_v) / |d_a| as one division and two products; -1 when d = 0.
[[gnu::always_inline]] inline int faceCoordinates(const double d[3], double& s,
                                                  double& t) noexcept {
  const double ax = std::fabs(d[0]), ay = std::fabs(d[1]), az = std::fabs(d[2]);
  constexpr int kU[3] = {1, 2, 0}, kV[3] = {2, 0, 1};
  const int xWins = static_cast<int>(ax >= ay) & static_cast<int>(ax >= az);
  const int axis = (1 - xWins) * (1 + static_cast<int>(!(ay >= az)));  // arithmetic, no jump
  const double major = d[axis], du = d[kU[axis]], dv = d[kV[axis]];
  if (major == 0) return -1;
  // within 2 ulps of the quotients; below 2^-1023 the reciprocal overflows, and the
  // quotients are taken as they are
  const double m = std::fabs(major), inv = 1.0 / m;
  if (inv <= std::numeric_limits<double>::max()) {
    s = du * inv;
    t = dv * inv;
  } else {
    s = du / m;
    t = dv / m;
  }
  return 2 * axis + (major < 0 ? 1 : 0);
}

// the base cell (baseCellIndex) of direction w on a grid of g cells per cube-face side; -1
// when w is zero or not finite
inline std::int64_t directionCell(Vec3 w, std::uint32_t g) noexcept {
  const double d[3] = {w.x, w.y, w.z};
  if (!(std::fabs(w.x) + std::fabs(w.y) + std::fabs(w.z) < std::numeric_limits<double>::infinity()))
    return -1;
  double s = 0, t = 0;
  const int face = faceCoordinates(d, s, t);
  if (face < 0) return -1;
  const double half = 0.5 * g;
  auto slot = [&](double c) {
    return std::min<std::uint64_t>(g - 1, static_cast<std::uint64_t>((c + 1) * half));
  };
  return static_cast<std::int64_t>(
      baseCellIndex(static_cast<std::uint64_t>(face), slot(s), slot(t), g));
}

// the direction through the middle of base cell `index` (the inverse of directionCell)
inline Vec3 cellDirection(std::size_t index, std::uint32_t g) {
  const BaseCell c = baseCellAt(index, g);
  return cubeDirection(c.face, (2.0 * c.i + 1) / g - 1, (2.0 * c.j + 1) / g - 1);
}

}  // namespace convexloc::cubemap

namespace convexloc {

inline int CubemapLocator::aim(Vec3 p, Aim& a) const noexcept {
  if (!centred_) return -1;
  const double d[3] = {p.x - centre_.x, p.y - centre_.y, p.z - centre_.z};
  const double ax = std::fabs(d[0]), ay = std::fabs(d[1]), az = std::fabs(d[2]);
  // one test for the usual point; a sum that overflows (or is NaN) looks closer: p not
  // finite, or the direction overflows
  if (!(ax + ay + az <= std::numeric_limits<double>::max()) &&
      !(ax <= std::numeric_limits<double>::max() && ay <= std::numeric_limits<double>::max() &&
        az <= std::numeric_limits<double>::max()))
    return -1;
  const int face = cubemap::faceCoordinates(d, a.s, a.t);
  if (face < 0) return 0;  // d = 0: p is the centre
  a.face = face;
  a.d2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
  const std::uint64_t last = (static_cast<std::uint64_t>(resolution_) << deepestLevel_) - 1;
  // (s + 1) * deepScale_ lies in [0, 2^31]: the signed conversion is exact and needs no branch
  a.deepI =
      std::min(static_cast<std::uint64_t>(static_cast<std::int64_t>((a.s + 1) * deepScale_)), last);
  a.deepJ =
      std::min(static_cast<std::uint64_t>(static_cast<std::int64_t>((a.t + 1) * deepScale_)), last);
  a.baseCell = static_cast<std::uint32_t>(
      cubemap::baseCellIndex(static_cast<std::uint64_t>(a.face), a.deepI >> deepestLevel_,
                             a.deepJ >> deepestLevel_, resolution_));
  return 1;
}

inline std::uint32_t CubemapLocator::leafAt(std::uint64_t deepI, std::uint64_t deepJ,
                                            std::uint32_t node, int& level) const noexcept {
  while (nodes_[node].count == cubemap::kInner) {
    ++level;
    const int shift = deepestLevel_ - level;
    node = nodes_[node].first +
           static_cast<std::uint32_t>(((deepJ >> shift) & 1) * 2 + ((deepI >> shift) & 1));
  }
  return node;
}

template <class Visit>
void CubemapLocator::forEachLeaf(Visit&& visit) const {
  struct Item {
    std::uint32_t node, i, j;
    int level;
  };
  std::vector<Item> stack;
  const std::size_t baseCells = 6 * static_cast<std::size_t>(resolution_) * resolution_;
  for (std::size_t c = 0; c < baseCells; ++c) {
    const cubemap::BaseCell base = cubemap::baseCellAt(c, resolution_);
    stack.push_back({static_cast<std::uint32_t>(c), base.i, base.j, 0});
    while (!stack.empty()) {
      const Item it = stack.back();
      stack.pop_back();
      const Node nd = nodes_[it.node];
      if (nd.count == cubemap::kInner) {
        for (std::uint32_t k = 4; k-- > 0;)
          stack.push_back({nd.first + k, 2 * it.i + (k & 1), 2 * it.j + (k >> 1), it.level + 1});
        continue;
      }
      visit(it.node, base.face, it.level, it.i, it.j);
    }
  }
}

}  // namespace convexloc
