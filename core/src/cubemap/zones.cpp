// convexloc — the cube map's zones: thin faces around one direction searched by bisection.
//
// A zone of a convex polyhedron is a cycle of faces F_0 .. F_(n-1), each holding two edges
// exactly parallel to one direction T, F_k between E_k and E_(k+1): the side of a cylinder
// or a prism, however thin its faces. Cells over it list many faces and no split helps (each
// face spans the whole height), so a crowded leaf over a zone keeps a range of it instead.
//
// Why the bisection is exact. Every plane through the centre c and an edge E_k contains the
// line l = c + lambda T (E_k is exactly parallel to T), so these planes are ordered by their
// angle around l, in zone order (the zone's shadow along T is a convex polygon around l's).
// If every direction of a cell and every edge of its range lie within a quarter turn around
// l, the sign of orient3d(c, E_k, p) for p mapped to the cell changes once along the range,
// so bisection finds the wedge between E_k and E_(k+1) that holds p's direction (on an edge's
// plane either neighbour). The ray from c through p leaves through F_k there, or through a
// face that is not in the zone, or (on the plane of E_k) through E_k itself, which lies in
// both neighbours' planes; the leaf keeps every listed face outside the zone. So testing
// F_k and those faces decides p exactly, by the argument of cubemap/index.hpp. The quarter
// turn is checked in floating point with room far beyond its rounding.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <unordered_map>
#include <vector>

#include "convexloc/predicates.hpp"
#include "cubemap/build.hpp"
#include "cubemap/index.hpp"

namespace convexloc {
namespace cubemap {
namespace {

using Edge = std::array<std::uint32_t, 2>;
constexpr std::uint32_t kNone = 0xffffffffu;
// a face with more corners than this starts or carries no zone (a cap is not a zone face)
constexpr std::size_t kZoneFaceCorners = 8;
// the fewest faces worth a zone
constexpr std::uint32_t kMinZone = 16;

// b - a exactly parallel to d - c (every component of their cross product zero)
bool parallel(const std::vector<Vec3>& v, Edge e, Edge f) {
  const Vec3 a = v[e[0]], b = v[e[1]], c = v[f[0]], d = v[f[1]];
  return crossDiff2d({a.x, a.y}, {b.x, b.y}, {c.x, c.y}, {d.x, d.y}) == 0 &&
         crossDiff2d({a.y, a.z}, {b.y, b.z}, {c.y, c.z}, {d.y, d.z}) == 0 &&
         crossDiff2d({a.z, a.x}, {b.z, b.x}, {c.z, c.x}, {d.z, d.x}) == 0;
}

std::uint64_t key(std::uint32_t a, std::uint32_t b) {
  return (std::uint64_t{a} << 32) | b;
}

// the faces and edges of every zone, found by chaining parallel edges across faces
class ZoneFinder {
 public:
  ZoneFinder(const ConvexPolyhedron& p, Vec3 c)
      : p_(p), v_(p.vertices().begin(), p.vertices().end()), c_(c) {
    for (std::uint32_t f = 0; f < p.planeCount(); ++f) {
      const auto loop = p.planeLoop(f);
      for (std::size_t i = 0; i < loop.size(); ++i)
        left_[key(loop[i], loop[(i + 1) % loop.size()])] = f;
    }
    zoneOf.assign(p.planeCount(), kNone);
    positionOf.assign(p.planeCount(), 0);
  }

  // chains from every face not yet in a zone
  void findAll() {
    std::vector<std::uint8_t> tried(p_.planeCount(), 0);
    for (std::uint32_t f = 0; f < p_.planeCount(); ++f) {
      const auto loop = p_.planeLoop(f);
      if (zoneOf[f] != kNone || tried[f] || loop.size() > kZoneFaceCorners) continue;
      for (std::size_t i = 0; i < loop.size() && zoneOf[f] == kNone; ++i)
        chain(f, {loop[i], loop[(i + 1) % loop.size()]}, tried);
    }
  }

  std::vector<CubemapLocator::Zone> zones;
  std::vector<Edge> edges;
  std::vector<std::uint32_t> faces, zoneOf, positionOf;

 private:
  // the edge of face f parallel to `e` (a loop edge of f), oriented like e; false if none
  bool partner(std::uint32_t f, Edge e, Edge& out) const {
    const auto loop = p_.planeLoop(f);
    if (loop.size() > kZoneFaceCorners) return false;
    for (std::size_t i = 0; i < loop.size(); ++i) {
      const Edge g{loop[i], loop[(i + 1) % loop.size()]};
      if (g == e || !parallel(v_, e, g)) continue;
      out = {g[1], g[0]};  // a convex polygon's parallel edges run opposite ways
      return true;
    }
    return false;
  }

  // follows the zone from face f across its edge e; keeps it when it closes and is long
  void chain(std::uint32_t f, Edge e, std::vector<std::uint8_t>& tried) {
    std::vector<Edge> es{e};
    std::vector<std::uint32_t> fs;
    std::uint32_t face = f;
    Edge at = e;
    for (;;) {
      Edge next;
      if (!partner(face, at, next)) break;
      fs.push_back(face);
      tried[face] = 1;
      const auto it = left_.find(key(next[0], next[1]));
      if (it == left_.end() || fs.size() > p_.planeCount()) break;
      if (it->second == f) {
        if (next == e) keep(es, fs);
        return;
      }
      if (zoneOf[it->second] != kNone) break;
      es.push_back(next);
      face = it->second;
      at = next;
    }
  }

  // records a closed zone whose edge planes turn one way
  void keep(const std::vector<Edge>& es, const std::vector<std::uint32_t>& fs) {
    const auto n = static_cast<std::uint32_t>(fs.size());
    if (n < kMinZone) return;
    const int sigma = orient3d(c_, v_[es[1][0]], v_[es[1][1]], v_[es[0][0]]);
    for (std::uint32_t k = 0; k < n; ++k) {
      const Edge& e = es[(k + 1) % n];
      if (sigma == 0 || orient3d(c_, v_[e[0]], v_[e[1]], v_[es[k][0]]) != sigma) return;
    }
    const auto z = static_cast<std::uint32_t>(zones.size());
    zones.push_back({static_cast<std::uint32_t>(edges.size()), n, sigma});
    for (std::uint32_t k = 0; k < n; ++k) {
      edges.push_back(es[k]);
      faces.push_back(fs[k]);
      zoneOf[fs[k]] = z;
      positionOf[fs[k]] = k;
    }
  }

  const ConvexPolyhedron& p_;
  std::vector<Vec3> v_;
  Vec3 c_;
  std::unordered_map<std::uint64_t, std::uint32_t> left_;  // half-edge -> face on its left
};

// the angle of direction d around the axis `axis` (unit), in the frame (e1, e2); NaN when d
// lies within a thousandth of the axis
double angleAround(const double (&d)[3], const double (&axis)[3], const double (&e1)[3],
                   const double (&e2)[3]) {
  const double along = d[0] * axis[0] + d[1] * axis[1] + d[2] * axis[2];
  const double q[3] = {d[0] - along * axis[0], d[1] - along * axis[1], d[2] - along * axis[2]};
  const double len = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  const double x = q[0] * e1[0] + q[1] * e1[1] + q[2] * e1[2];
  const double y = q[0] * e2[0] + q[1] * e2[1] + q[2] * e2[2];
  if (!(std::hypot(x, y) >= 1e-3 * len)) return std::nan("");
  return std::atan2(y, x);
}

}  // namespace
}  // namespace cubemap

using namespace cubemap;

bool CubemapBuilder::zoneFits(const ZoneRange& r, int cf, int level, std::uint64_t i,
                              std::uint64_t j) const {
  // every direction of the widened cell and the range's end edges within a quarter turn
  const CubemapLocator& L = locator_;
  const CubemapLocator::Zone& z = L.zones_[r.zone];
  const std::vector<Vec3>& v = L.surface_.vertices;
  const auto& e0 = L.zoneEdges_[z.first];
  double axis[3] = {v[e0[1]].x - v[e0[0]].x, v[e0[1]].y - v[e0[0]].y, v[e0[1]].z - v[e0[0]].z};
  const double n = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
  for (double& a : axis) a /= n;
  const int m = std::fabs(axis[0]) < 0.5 ? 0 : (std::fabs(axis[1]) < 0.5 ? 1 : 2);
  double e1[3] = {0, 0, 0}, e2[3];
  e1[m] = 1;
  const double dot = axis[m];
  for (int k = 0; k < 3; ++k) e1[k] -= dot * axis[k];
  const double l1 = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
  for (double& a : e1) a /= l1;
  e2[0] = axis[1] * e1[2] - axis[2] * e1[1];
  e2[1] = axis[2] * e1[0] - axis[0] * e1[2];
  e2[2] = axis[0] * e1[1] - axis[1] * e1[0];
  std::vector<double> angles;
  const double K = levelScale(L.resolution_, level), widen = 0x1p-30;
  for (int q = 0; q < 4; ++q) {
    const double s =
        -1 + static_cast<double>(i + (q == 1 || q == 2)) / K + (q == 1 || q == 2 ? widen : -widen);
    const double t = -1 + static_cast<double>(j + (q >= 2)) / K + (q >= 2 ? widen : -widen);
    const Vec3 d = cubeDirection(cf, s, t);
    angles.push_back(angleAround({d.x, d.y, d.z}, axis, e1, e2));
  }
  for (std::uint32_t k : {1u, r.span - 1}) {
    const Vec3 a = v[L.zoneEdges_[z.first + (r.lo + k) % z.size][0]];
    angles.push_back(
        angleAround({a.x - L.centre_.x, a.y - L.centre_.y, a.z - L.centre_.z}, axis, e1, e2));
  }
  double lo = 0, hi = 0;
  for (double a : angles) {
    if (std::isnan(a)) return false;
    const double rel = std::remainder(a - angles[0], 2 * std::numbers::pi);
    lo = std::min(lo, rel), hi = std::max(hi, rel);
  }
  return hi - lo < std::numbers::pi / 2;
}

std::uint32_t CubemapBuilder::entryCount(std::uint32_t count) {
  return leafEntries(count);
}

void CubemapBuilder::findZones() {
  CubemapLocator& L = locator_;
  ZoneFinder finder(polyhedron_, L.centre_);
  finder.findAll();
  L.zones_ = std::move(finder.zones);
  L.zoneEdges_ = std::move(finder.edges);
  L.zoneFaces_ = std::move(finder.faces);
  zoneOf_ = std::move(finder.zoneOf);
  positionOf_ = std::move(finder.positionOf);
}

void CubemapBuilder::encodeZones() {
  CubemapLocator& L = locator_;
  if (L.zones_.empty()) return;
  Table<std::uint32_t> entries;
  entries.reserve(L.entries_.size());
  std::vector<std::uint32_t> others;
  L.forEachLeaf([&](std::uint32_t node, int cf, int level, std::uint64_t i, std::uint64_t j) {
    Node& nd = L.nodes_[node];
    const std::uint32_t* list = L.entries_.data() + nd.first;
    const auto first = static_cast<std::uint32_t>(entries.size());
    ZoneRange r;
    if (!isZoneLeaf(nd.count) && !isSectorLeaf(nd.count) && nd.count > kCrowdedCell3D &&
        rangeOf(list, nd.count, zoneOf_, positionOf_, r, others) &&
        others.size() <= kCrowdedCell3D && zoneFits(r, cf, level, i, j)) {
      entries.push_back(static_cast<std::uint32_t>(L.zoneRanges_.size()));
      L.zoneRanges_.push_back(r);
      entries.insert(entries.end(), others.begin(), others.end());
      nd = {first, kZoneLeaf | static_cast<std::uint32_t>(1 + others.size()), nd.in2, nd.out2};
      return;
    }
    entries.insert(entries.end(), list, list + entryCount(nd.count));
    nd.first = first;
  });
  L.entries_.swap(entries);
  L.entries_.shrink_to_fit();
  L.zoneRanges_.shrink_to_fit();
}

bool CubemapBuilder::rangeOf(const std::uint32_t* list, std::uint32_t count,
                             const std::vector<std::uint32_t>& zoneOf,
                             const std::vector<std::uint32_t>& positionOf, ZoneRange& r,
                             std::vector<std::uint32_t>& others) const {
  // the zone most of the list lies in, and the shortest cyclic range holding its faces
  std::unordered_map<std::uint32_t, std::uint32_t> votes;
  std::uint32_t best = kNone, most = 0;
  for (const std::uint32_t* f = list; f != list + count; ++f)
    if (zoneOf[*f] != kNone && ++votes[zoneOf[*f]] > most)
      most = votes[zoneOf[*f]], best = zoneOf[*f];
  if (best == kNone || most <= kCrowdedCell3D) return false;
  std::vector<std::uint32_t> at;
  others.clear();
  for (const std::uint32_t* f = list; f != list + count; ++f)
    (zoneOf[*f] == best ? at.push_back(positionOf[*f]) : others.push_back(*f));
  std::sort(at.begin(), at.end());
  const std::uint32_t n = locator_.zones_[best].size;
  std::uint32_t gap = n - at.back() + at.front(), start = at.front();
  for (std::size_t k = 0; k + 1 < at.size(); ++k)
    if (at[k + 1] - at[k] > gap) gap = at[k + 1] - at[k], start = at[k + 1];
  r = {best, start, n - gap + 1};
  return true;
}

}  // namespace convexloc
