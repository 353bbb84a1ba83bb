// convexloc — the cube map's fans: thin faces sorted by angle around an axis fitted at build
// time, which a crowded leaf searches by bisection.
//
// Where no split helps and no zone fits (the sides of a cylinder turned and rounded to
// float32, so that no two edges are exactly parallel, or of a hull's output), the thin faces
// still lie around some line through the centre c. The build fits that line's direction T
// (the planes through c and each thin face's longest edge nearly contain it), cuts the turn
// around it into arcs, and for each fixes two points q and r in doubles: the axis L is the
// line through c and q, exactly, and the plane through c, q and r bounds the open half-space
// H = {x : orient3d(c, q, r, x) = sigma} around the arc. A fan is the arc's thin faces that
// lie in H (checked exactly), sorted; a crowded leaf over a fan keeps the range of places
// its faces need and its other faces.
//
// Why the search is exact. Around L, write theta(x) for the angle of a point x not on L. For
// a and b in H, orient3d(c, q, a, b) has the sign of sin(theta(b) - theta(a)) times a
// positive factor (the triple product (q - c) . ((a - c) x (b - c)) sees only the parts of
// a - c and b - c across L), and H is an open half-turn, so orient3d(c, q, a, b) = sigma iff
// theta(a) < theta(b): an exact comparison of angles, the points of H ordered by it. Every
// face of a fan has all its corners in H (checked exactly), so the whole face lies in H, and
// as {x in H : theta(x) <= t} is convex (a half-space cut by H), the angles of its points
// fill exactly [theta(first), theta(last)], its first and last corners by angle. The fan's
// faces F_0 .. F_(n-1) are sorted by their first corners k_i, the keys; a query p != c counts
// j = #{i : theta(k_i) < theta(p)} by bisection (the predicate is monotone along the order).
// Let y be where the ray from c through p leaves the polyhedron. If p is not in H, neither
// is y (y - c is a positive multiple of p - c, and orient3d(c, q, r, .) is linear in it),
// nor any face through y of the fan: a face the leaf lists through y (cubemap/index.hpp)
// is one of its others, which are always tested. If p is in H: the directions of p - c
// turned slightly back around L still lie in the leaf's square grown by kMargin (p's exact
// direction lies inside it with room far above the query's rounding), so every face their
// rays leave through is listed in the leaf; their exit points tend to y (the boundary of a
// convex body moves continuously seen from an inner point), so some listed face T holds y
// and exit points of angles below theta(p). If T is not in the fan it is tested as one of
// the others; if T = F_i, then theta(k_i) < theta(p) <= theta(last_i), so i < j and
// theta(last_i) > theta(k_(j-1)): M_i = #{k : theta(k_k) < theta(last_i)} >= j. The window
// of place j is F_(j - back_j) .. F_(j - 1), back_j the largest j - i over the faces with
// i < j <= M_i: it holds T. Testing it and the others decides p exactly, by cubemap/index.hpp's
// argument for T (further faces of the polyhedron never change that answer). A leaf searches
// only the places [from, to] its listed fan faces can be needed at (F_i at i + 1 .. M_i):
// bisection over keys from .. to - 1 gives j clamped to [from, to], which is j itself
// whenever a listed fan face can be T; else T is one of the others. A face whose angles span
// too many keys stays out of the fan; a leaf with many faces outside its fan keeps its walk.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "convexloc/predicates.hpp"
#include "cubemap/build.hpp"
#include "cubemap/index.hpp"

namespace convexloc {
namespace cubemap {
namespace {

constexpr std::uint32_t kNoFan = 0xffffffffu;
// the largest window a key entry holds (cubemap/index.hpp)
constexpr std::uint32_t kMaxBack = kSectorBack;
static_assert(kMaxPolyhedronVertices <= std::size_t{1} << kSectorBackShift);
// the fewest faces worth a fan
constexpr std::size_t kMinFan = 16;
// the arcs the turn around the axis is cut into (each fan's faces lie within a sixth of a
// turn of its middle, well inside its half-turn)
constexpr int kArcs = 6;
// a face is thin where its longest edge is over 2 kThin times its mean width (its area over
// that edge)
constexpr double kThin = 4;
// a plane nearly holds a direction when the cosine between them is below this
constexpr double kHolds = 0.02;

double dot(const double (&a)[3], const double (&b)[3]) {
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void cross(const double (&a)[3], const double (&b)[3], double (&out)[3]) {
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

// scales a to unit length; false when it is zero or not finite
bool normalise(double (&a)[3]) {
  const double n = std::sqrt(dot(a, a));
  if (!(n > 0) || !std::isfinite(n)) return false;
  for (double& x : a) x /= n;
  return true;
}

// whether the face with corners `loop` is thin; then m is the unit normal of the plane
// through c and its longest edge, and mid its corners' mean less c
bool thinFace(std::span<const std::uint32_t> loop, const std::vector<Vec3>& v, Vec3 c,
              double (&m)[3], double (&mid)[3]) {
  double longest = 0, area[3] = {0, 0, 0};
  const Vec3 o = v[loop[0]];
  mid[0] = mid[1] = mid[2] = 0;
  for (std::size_t i = 0; i < loop.size(); ++i) {
    const Vec3 a = v[loop[i]], b = v[loop[(i + 1) % loop.size()]];
    const double e[3] = {b.x - a.x, b.y - a.y, b.z - a.z};
    const double d[3] = {a.x - c.x, a.y - c.y, a.z - c.z};
    const double pa[3] = {a.x - o.x, a.y - o.y, a.z - o.z},
                 pb[3] = {b.x - o.x, b.y - o.y, b.z - o.z};
    double n[3];
    cross(pa, pb, n);
    for (int k = 0; k < 3; ++k) area[k] += n[k], mid[k] += d[k] / static_cast<double>(loop.size());
    if (dot(e, e) > longest) longest = dot(e, e), cross(d, e, m);
  }
  const double twiceArea = std::sqrt(dot(area, area));
  return kThin * twiceArea < longest && normalise(m);
}

// the smallest eigenvector of the symmetric positive semi-definite M (power iteration on
// trace - M), from `t`; false when it vanishes
bool leastDirection(const double (&M)[3][3], double (&t)[3]) {
  const double trace = M[0][0] + M[1][1] + M[2][2];
  for (int it = 0; it < 60; ++it) {
    double next[3];
    for (int i = 0; i < 3; ++i)
      next[i] = trace * t[i] - (M[i][0] * t[0] + M[i][1] * t[1] + M[i][2] * t[2]);
    std::copy(next, next + 3, t);
    if (!normalise(t)) return false;
  }
  return true;
}

// the faces whose planes nearly hold direction t
std::size_t holding(const std::vector<std::array<double, 3>>& normals, const double (&t)[3]) {
  std::size_t n = 0;
  for (const auto& m : normals) n += std::fabs(m[0] * t[0] + m[1] * t[1] + m[2] * t[2]) < kHolds;
  return n;
}

// The axis most of the planes through c and the thin faces' long edges nearly hold (unit
// normals in `normals`): the best of a few pairs' common lines, then the least direction of
// the planes that hold it. False when none is found.
bool fitAxis(const std::vector<std::array<double, 3>>& normals, double (&t)[3]) {
  std::size_t best = 0;
  std::uint64_t seed = 0x9e3779b97f4a7c15u;
  for (int trial = 0; trial < 24; ++trial) {
    seed = seed * 6364136223846793005u + 1442695040888963407u;
    const auto& a = normals[(seed >> 33) % normals.size()];
    const auto& b = normals[(seed >> 13) % normals.size()];
    double d[3];
    cross({a[0], a[1], a[2]}, {b[0], b[1], b[2]}, d);
    if (!normalise(d)) continue;
    const std::size_t n = holding(normals, d);
    if (n > best) best = n, std::copy(d, d + 3, t);
  }
  if (best < kMinFan) return false;
  double M[3][3] = {};
  for (const auto& m : normals)
    if (std::fabs(m[0] * t[0] + m[1] * t[1] + m[2] * t[2]) < kHolds)
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) M[i][j] += m[i] * m[j];
  return leastDirection(M, t);
}

// one face of a fan: its plane face, first and last corners by angle
struct Sorted {
  std::uint32_t face, first, last;
};

}  // namespace
}  // namespace cubemap

using namespace cubemap;

void CubemapBuilder::findFans() {
  CubemapLocator& L = locator_;
  const std::vector<Vec3>& v = L.surface_.vertices;
  const Vec3 c = L.centre_;
  const std::uint32_t planes = polyhedron_.planeCount();
  fanOf_.assign(planes, kNoFan), fanFrom_.assign(planes, 0), fanTo_.assign(planes, 0);
  // the thin faces outside the zones, and the axis least across their long edges' planes
  std::vector<std::uint32_t> thin;
  std::vector<std::array<double, 3>> normals, mids;
  for (std::uint32_t f = 0; f < planes; ++f) {
    double m[3] = {}, mid[3] = {};
    if (zoneOf_[f] != kNoFan /* a zone's (the same mark) */ ||
        !thinFace(polyhedron_.planeLoop(f), v, c, m, mid))
      continue;
    thin.push_back(f);
    normals.push_back({m[0], m[1], m[2]});
    mids.push_back({mid[0], mid[1], mid[2]});
  }
  double t[3];
  if (thin.size() < kMinFan || !fitAxis(normals, t)) return;
  // a frame across the axis, and the arcs
  double e1[3] = {0, 0, 0}, e2[3];
  e1[std::fabs(t[0]) < 0.5 ? 0 : (std::fabs(t[1]) < 0.5 ? 1 : 2)] = 1;
  const double along = dot(e1, t);
  for (int k = 0; k < 3; ++k) e1[k] -= along * t[k];
  normalise(e1);
  cross(t, e1, e2);
  const double size = L.cubeHalfSize_;
  const Vec3 q{c.x + size * t[0], c.y + size * t[1], c.z + size * t[2]};
  std::vector<std::vector<std::uint32_t>> arcs(kArcs);
  for (std::size_t k = 0; k < thin.size(); ++k) {
    const double d[3] = {mids[k][0], mids[k][1], mids[k][2]};
    const double angle = std::atan2(dot(d, e2), dot(d, e1));
    const int arc =
        static_cast<int>(std::floor((angle + std::numbers::pi) / (2 * std::numbers::pi) * kArcs));
    arcs[std::clamp(arc, 0, kArcs - 1)].push_back(thin[k]);
  }
  for (int a = 0; a < kArcs; ++a) {
    const double middle = -std::numbers::pi + (a + 0.5) * 2 * std::numbers::pi / kArcs;
    double u[3], w[3];
    for (int k = 0; k < 3; ++k) u[k] = std::cos(middle) * e1[k] + std::sin(middle) * e2[k];
    cross(t, u, w);
    const Vec3 r{c.x + size * w[0], c.y + size * w[1], c.z + size * w[2]};
    const int sigma =
        orient3d(c, q, r, Vec3{c.x + size * u[0], c.y + size * u[1], c.z + size * u[2]});
    if (sigma == 0) continue;
    std::vector<std::uint32_t> inside;
    for (std::uint32_t f : arcs[a]) {
      bool in = true;
      for (std::uint32_t corner : polyhedron_.planeLoop(f))
        in = in && orient3d(c, q, r, v[corner]) == sigma;
      if (in) inside.push_back(f);
    }
    addFan(inside, q, r, sigma);
  }
  L.sectors_.shrink_to_fit();
  L.sectorFaces_.shrink_to_fit();
  L.sectorKeys_.shrink_to_fit();
}

void CubemapBuilder::addFan(std::vector<std::uint32_t>& faces, Vec3 q, Vec3 r, int sigma) {
  CubemapLocator& L = locator_;
  const std::vector<Vec3>& v = L.surface_.vertices;
  const Vec3 c = L.centre_;
  auto before = [&](std::uint32_t a, std::uint32_t b) {
    return orient3d(c, q, v[a], v[b]) == sigma;
  };
  std::vector<Sorted> sorted;
  for (std::uint32_t f : faces) {
    const auto loop = polyhedron_.planeLoop(f);
    std::uint32_t lo = loop[0], hi = loop[0];
    for (std::uint32_t corner : loop) {
      if (before(corner, lo)) lo = corner;
      if (before(hi, corner)) hi = corner;
    }
    sorted.push_back({f, lo, hi});
  }
  std::sort(sorted.begin(), sorted.end(),
            [&](const Sorted& a, const Sorted& b) { return before(a.first, b.first); });
  // each place's window; faces whose angles span too many keys leave the fan (the others'
  // spans then only shrink, so a second pass finds none)
  std::vector<std::uint32_t> back, to;
  for (int pass = 0; pass < 2; ++pass) {
    const auto n = static_cast<std::uint32_t>(sorted.size());
    back.assign(n + 1, 0), to.assign(n, 0);
    std::vector<Sorted> kept;
    for (std::uint32_t i = 0; i < n; ++i) {
      // M: the keys before the last corner (at least i + 1: the first corner comes before it)
      const auto M = static_cast<std::uint32_t>(
          std::partition_point(sorted.begin(), sorted.end(),
                               [&](const Sorted& s) { return before(s.first, sorted[i].last); }) -
          sorted.begin());
      if (M > i + kMaxBack) continue;
      kept.push_back(sorted[i]);
      for (std::uint32_t j = i + 1; j <= M; ++j) back[j] = std::max(back[j], j - i);
      to[i] = std::max(i + 1, M);
    }
    if (kept.size() == n) break;
    if (pass == 1) return;  // cannot happen (see above); be safe
    sorted.swap(kept);
  }
  const auto n = static_cast<std::uint32_t>(sorted.size());
  if (n < kMinFan) return;
  const auto fan = static_cast<std::uint32_t>(L.sectors_.size());
  const auto first = static_cast<std::uint32_t>(L.sectorFaces_.size());
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t f = sorted[i].face;
    L.sectorFaces_.push_back(f);
    L.sectorKeys_.push_back(sorted[i].first | back[i] << kSectorBackShift);
    fanOf_[f] = fan, fanFrom_[f] = i + 1, fanTo_[f] = to[i];
  }
  L.sectors_.push_back({q, r, sigma, first, n, back[n]});
}

void CubemapBuilder::fanLeafFaces(const Node& nd, std::vector<std::uint32_t>& faces) const {
  // the others, and the fan faces some place of the range needs (F_i at i + 1 .. M_i): every
  // face the leaf listed, and a few beside
  const CubemapLocator& L = locator_;
  const std::uint32_t* e = L.entries_.data() + nd.first;
  const CubemapLocator::SectorRange& r = L.sectorRanges_[e[0]];
  const CubemapLocator::Sectors& f = L.sectors_[r.fan];
  faces.assign(e + 1, e + leafEntries(nd.count));
  std::uint32_t lo = r.from;
  for (std::uint32_t j = r.from; j <= r.to; ++j)
    lo = std::min(lo, j - (j < f.size ? L.sectorKeys_[f.first + j] >> kSectorBackShift : f.back));
  for (std::uint32_t i = lo; i < r.to; ++i) {
    const std::uint32_t face = L.sectorFaces_[f.first + i];
    if (fanTo_[face] >= r.from) faces.push_back(face);
  }
}

void CubemapBuilder::encodeSectors() {
  CubemapLocator& L = locator_;
  if (L.sectors_.empty()) return;
  Table<std::uint32_t> entries;
  entries.reserve(L.entries_.size());
  std::vector<std::uint32_t> others;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> votes;  // (fan, faces)
  for (Node& nd : L.nodes_) {
    if (nd.count == kInner) continue;
    const std::uint32_t* list = L.entries_.data() + nd.first;
    const auto first = static_cast<std::uint32_t>(entries.size());
    const std::uint32_t count = leafEntries(nd.count);
    if (!isZoneLeaf(nd.count) && !isSectorLeaf(nd.count) && count > kCrowdedCell3D) {
      // the fan most of the list lies in
      votes.clear();
      for (const std::uint32_t* f = list; f != list + count; ++f) {
        if (fanOf_[*f] == kNoFan) continue;
        auto it = std::find_if(votes.begin(), votes.end(),
                               [&](auto& x) { return x.first == fanOf_[*f]; });
        if (it == votes.end())
          votes.push_back({fanOf_[*f], 1});
        else
          ++it->second;
      }
      const auto best = std::max_element(votes.begin(), votes.end(),
                                         [](auto& a, auto& b) { return a.second < b.second; });
      if (best != votes.end() && best->second >= kFanLeaf &&
          count - best->second <= kCrowdedCell3D) {
        CubemapLocator::SectorRange range{best->first, 0xffffffffu, 0};
        others.clear();
        for (const std::uint32_t* f = list; f != list + count; ++f)
          if (fanOf_[*f] == best->first) {
            range.from = std::min(range.from, fanFrom_[*f]);
            range.to = std::max(range.to, fanTo_[*f]);
          } else {
            others.push_back(*f);
          }
        entries.push_back(static_cast<std::uint32_t>(L.sectorRanges_.size()));
        L.sectorRanges_.push_back(range);
        entries.insert(entries.end(), others.begin(), others.end());
        nd.first = first;
        nd.count = kSectorLeaf | static_cast<std::uint32_t>(1 + others.size());
        continue;
      }
    }
    entries.insert(entries.end(), list, list + count);
    nd.first = first;
  }
  L.entries_.swap(entries);
  L.entries_.shrink_to_fit();
}

}  // namespace convexloc
