// convexloc — the cube map's build: the base grid and the quadtree of crowded cells, flat.
//
// Each face's cone from the centre is projected onto the cube faces it meets as a polygon
// relaxed beyond every rounding (see cubemap/index.hpp), and rasterised onto the cells with
// the query's own cell index. The base grid (6 G^2 cells) is coarsened until it fits the
// memory budget; then crowded cells are split into 4, the most crowded first (where a walk
// or a bisection costs most), while the budget allows; a cell that no split helps (many
// faces meeting at one vertex) stays crowded and is searched by a walk. Nodes and entries
// are stored flat (CSR), so memory is O(F) whatever the faces' sizes.
#include "cubemap/build.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <limits>
#include <string>

#include "convexloc/error.hpp"
#include "convexloc/timing.hpp"
#include "cubemap/index.hpp"
#include "cubemap/projection.hpp"

namespace convexloc {
namespace cubemap {
namespace {

// the most cells per side at any level: 2^31
constexpr int kMaxSideBits = 31;
// The default G is at least this: where the faces are few, each cell's radii then bound
// only the part of a face the cell sees, and a thinner shell is left to the face tests; the
// grid still fits the constant part of the memory budget.
constexpr std::uint32_t kSmallestDefault = 16;
// no face yet, in a cell's "last face listed"
constexpr std::uint32_t kUnlisted = 0xffffffffu;
// the part of the memory budget that does not grow with the faces
constexpr std::size_t kFixedBudget = 32 * 1024;

}  // namespace

int depthFor(std::uint32_t g) {
  const int bits = static_cast<int>(std::bit_width(g - 1));
  return std::min(kMaxLevel, kMaxSideBits - bits);
}

double cubeExtent(std::span<const Vec3> vertices, Vec3 c) {
  double extent = 0;
  for (const Vec3& p : vertices)
    extent = std::max({extent, std::fabs(p.x - c.x), std::fabs(p.y - c.y), std::fabs(p.z - c.z)});
  return extent;
}

}  // namespace cubemap

using namespace cubemap;

namespace {

// the box (s0, s1, t0, t1) as a polygon
Poly boxPoly(const std::array<double, 4>& b) {
  Poly B;
  B.n = 4;
  B.p[0] = {b[0], b[2]}, B.p[1] = {b[1], b[2]}, B.p[2] = {b[1], b[3]}, B.p[3] = {b[0], b[3]};
  return B;
}

// up to this many triangles, a base grid that does not fit is tried again three quarters as
// fine (a halving would often give up twice the cell width the budget allows); beyond, half
// as fine, as each try rasterises every face
constexpr std::size_t kFineSteps = std::size_t{1} << 16;

// the next coarser base grid to try after g, on a surface of `triangles`: at least 1 less
std::uint32_t coarser(std::uint32_t g, std::size_t triangles) {
  const std::uint32_t next = triangles <= kFineSteps ? g * 3 / 4 : g / 2;
  return std::max<std::uint32_t>(1, std::min(g - 1, next));
}

}  // namespace

CubemapLocator::CubemapLocator(const ConvexPolyhedron& polyhedron, std::uint32_t resolution) {
  const auto t0 = Clock::now();
  CubemapBuilder(*this, polyhedron, resolution).build();
  buildSeconds_ = secondsSince(t0);
}

// === base grid

CubemapBuilder::CubemapBuilder(CubemapLocator& locator, const ConvexPolyhedron& polyhedron,
                               std::uint32_t resolution)
    : locator_(locator), polyhedron_(polyhedron) {
  if (resolution > kMaxResolution)
    throw UsageError("cubemap: the resolution is at most " + std::to_string(kMaxResolution));
  locator_.surface_ = detail::SurfaceCopy(polyhedron);
  locator_.mesh_ = detail::WalkMesh(polyhedron);
  locator_.resolution_ =
      resolution ? resolution
                 : defaultResolution(locator_.surface_.faces.size(), locator_.surface_.triangles);
  centre_ = polyhedron.centre();
}

std::uint32_t CubemapBuilder::defaultResolution(std::size_t faces, std::size_t triangles) {
  // From the plane faces; where they are made of many more triangles (a CAD shape's caps and
  // side quads), up to kZoneResolution from the triangles: a zone's thin faces take one entry
  // per cell, and on a coarser grid a cell's shell between its radii is thick.
  constexpr std::uint32_t kZoneResolution = 64;
  return std::max(defaultResolution(faces),
                  std::min(defaultResolution(triangles), kZoneResolution));
}

std::uint32_t CubemapBuilder::defaultResolution(std::size_t faces) {
  // about 4 faces per base cell up to G = 160, so that few cells are crowded and refined and
  // a batch meets few inner nodes; beyond, about 8, which keeps the build of millions of
  // faces fast
  const double perCell8 = std::sqrt(static_cast<double>(faces) / 8),
               perCell4 = std::min(std::sqrt(static_cast<double>(faces) / 4), 160.0);
  return static_cast<std::uint32_t>(std::clamp<double>(std::round(std::max(perCell8, perCell4)),
                                                       kSmallestDefault, kMaxResolution));
}

void CubemapBuilder::build() {
  CubemapLocator& L = locator_;
  if (!aimFromCentre()) {
    L.resolution_ = 0;  // no cells: every query tests all faces
    return;
  }
  findZones();
  findFans();
  if (!buildBaseGrid()) {
    L.resolution_ = 0;  // no cells: every query tests all faces
    return;
  }
  L.centred_ = true;
  L.deepScale_ = std::ldexp(static_cast<double>(L.resolution_), L.deepestLevel_ - 1);
  refineCrowdedCells();
  compactEntries();
  L.nodes_.shrink_to_fit();
  encodeZones();  // crowded leaves the refinement made over a zone
  encodeSectors();
  L.nodes_.shrink_to_fit();
  L.entries_.shrink_to_fit();
  L.sectorRanges_.shrink_to_fit();
  setLeafRadii();
}

bool CubemapBuilder::aimFromCentre() {
  CubemapLocator& L = locator_;
  double extent = 0;
  if (centre_) extent = cubeExtent(L.surface_.vertices, L.centre_ = *centre_);
  // no centre (a polyhedron thinner than the double grid), or one so vast that its
  // directions overflow
  if (!centre_ || !std::isfinite(extent) || !(extent > 0)) return false;
  L.cubeHalfSize_ = extent;
  scale_ = PowerOfTwo(-std::ilogb(extent));  // extent scaled into [1, 2)
  return true;
}

std::size_t CubemapBuilder::memoryBudget() const {
  // 120 bytes per triangle in all, plus kFixedBudget (so that small polyhedra, the ones a
  // lecturer draws, still get a grid worth showing, and fast radii)
  const CubemapLocator& L = locator_;
  const std::size_t fixed = sizeof(CubemapLocator) + L.surface_.bytes() + L.mesh_.bytes();
  const std::size_t total = 120 * L.surface_.triangles + kFixedBudget;
  return total > fixed ? total - fixed : 0;
}

template <class Visit>
bool CubemapBuilder::forEachProjection(Visit&& visit) const {
  const std::vector<Vec3>& v = locator_.surface_.vertices;
  const auto& triangles = polyhedron_.triangles();
  Cone k;
  Poly P;
  const auto faces = static_cast<std::uint32_t>(polyhedron_.planeCount());
  for (std::uint32_t f = 0; f < faces; ++f)
    for (std::uint32_t t : polyhedron_.planeTriangles(f)) {
      if (!coneOf(v, triangles[t], locator_.centre_, scale_, k)) return false;
      for (int cf = 0; cf < 6; ++cf)
        if (onCubeFace(k, cf, P)) visit(f, cf, P);
    }
  return true;
}

bool CubemapBuilder::buildBaseGrid() {
  budget_ = memoryBudget();
  std::vector<std::uint32_t> counts;
  for (;;) {
    if (!fitBaseGrid(counts)) return false;  // a direction overflowed
    fillBaseCells(counts);
    encodeZones();
    encodeSectors();
    // the fit assumed every crowded cell over a zone would become a range of it
    CubemapLocator& L = locator_;
    if (L.resolution_ == 1 || liveBytes() <= budget_) return true;
    L.resolution_ = coarser(L.resolution_, L.surface_.triangles);
    L.zoneRanges_.clear();
    L.sectorRanges_.clear();
  }
}

std::size_t CubemapBuilder::liveBytes() const {
  const CubemapLocator& L = locator_;
  return L.nodes_.size() * kNodeBytes + L.entries_.size() * sizeof(std::uint32_t) +
         L.zoneRanges_.size() * sizeof(ZoneRange) +
         L.sectorRanges_.size() * sizeof(CubemapLocator::SectorRange);
}

bool CubemapBuilder::fitBaseGrid(std::vector<std::uint32_t>& counts) {
  std::uint32_t& g = locator_.resolution_;
  while (g > 1 && 6 * static_cast<std::size_t>(g) * g * kNodeBytes > budget_) g /= 2;
  for (;;) {
    locator_.deepestLevel_ = depthFor(g);
    const std::size_t cells = 6 * static_cast<std::size_t>(g) * g;
    counts.assign(cells + 1, 0);
    const double K = levelScale(g, 0);
    const std::int64_t last = g - 1;
    std::vector<std::uint32_t> lastFace(cells, kUnlisted);  // each face once per cell
    const bool grouped = !zoneOf_.empty() || !fanOf_.empty();
    // each cell's faces in zones and in fans
    std::vector<std::uint32_t> inZones(grouped ? cells : 0, 0), inFans(grouped ? cells : 0, 0);
    const bool ok = forEachProjection([&](std::uint32_t f, int cf, const Poly& P) {
      rasterise(P, K, 0, last, 0, last, [&](std::int64_t i, std::int64_t j) {
        const std::size_t c = baseCellIndex(cf, i, j, g);
        if (lastFace[c] == f) return;
        lastFace[c] = f;
        ++counts[c];
        if (grouped) {
          inZones[c] += !zoneOf_.empty() && zoneOf_[f] != kUnlisted;
          inFans[c] += !fanOf_.empty() && fanOf_[f] != kUnlisted;
        }
      });
    });
    if (!ok) return false;
    // a crowded cell over a zone or a fan with few other faces keeps a range of it: one entry
    // and the range for its faces there (as encodeZones and encodeSectors at best make it;
    // encodeSectors takes a fan of kFanLeaf faces at least)
    std::size_t bytes = cells * kNodeBytes;
    for (std::size_t c = 0; c < cells; ++c) {
      const std::uint32_t zones = inZones.empty() ? 0 : inZones[c],
                          fans = inFans.empty() ? 0 : inFans[c], z = zones + fans;
      const bool ranged =
          z > kCrowdedCell3D && counts[c] - z <= kCrowdedCell3D && (fans == 0 || fans >= kFanLeaf);
      const std::size_t range = fans ? sizeof(CubemapLocator::SectorRange) : sizeof(ZoneRange);
      bytes += ranged ? (counts[c] - z + 1) * sizeof(std::uint32_t) + range
                      : counts[c] * sizeof(std::uint32_t);
    }
    if (g == 1 || bytes <= budget_) return true;
    g = coarser(g, locator_.surface_.triangles);
  }
}

void CubemapBuilder::fillBaseCells(const std::vector<std::uint32_t>& counts) {
  CubemapLocator& L = locator_;
  const std::uint32_t g = L.resolution_;
  const std::size_t baseCells = 6 * static_cast<std::size_t>(g) * g;
  L.nodes_.resize(baseCells);
  std::uint32_t at = 0;
  for (std::size_t c = 0; c < baseCells; ++c) {
    L.nodes_[c] = {at, counts[c]};
    at += counts[c];
  }
  L.entries_.resize(at);
  std::vector<std::uint32_t> cursor(baseCells);
  for (std::size_t c = 0; c < baseCells; ++c) cursor[c] = L.nodes_[c].first;
  const double K = levelScale(g, 0);
  const std::int64_t last = g - 1;
  std::vector<std::uint32_t> lastFace(baseCells, kUnlisted);  // each face once per cell
  forEachProjection([&](std::uint32_t f, int cf, const Poly& P) {
    rasterise(P, K, 0, last, 0, last, [&](std::int64_t i, std::int64_t j) {
      const std::size_t c = baseCellIndex(cf, i, j, g);
      if (lastFace[c] == f) return;
      lastFace[c] = f;
      L.entries_[cursor[c]++] = f;
    });
  });
}

// === quadtree

void CubemapBuilder::refineCrowdedCells() {
  CubemapLocator& L = locator_;
  queueCrowdedBaseCells();
  live_ = liveBytes();
  liveEntries_ = L.entries_.size();
  while (!queue_.empty()) {
    std::pop_heap(queue_.begin(), queue_.end(), morePressing);
    const Pending q = queue_.back();
    queue_.pop_back();
    if (q.level >= L.deepestLevel_) continue;
    const Node parent = L.nodes_[q.node];
    const std::span<const std::uint32_t> faces = parentFaces(parent);
    sortFaces(q, faces);
    const int levels = chainLevels(q);
    const std::size_t added = listChildren(q, levels);
    if (levels == 1 && splitIsFutile(faces.size(), added)) continue;
    const std::uint32_t stored = leafEntries(parent.count);
    const std::size_t grown = live_ + 4 * kNodeBytes * levels + added * sizeof(std::uint32_t) -
                              stored * sizeof(std::uint32_t);
    if (grown > budget_ || L.entries_.size() + added > std::numeric_limits<std::uint32_t>::max())
      break;
    commitChildren(q, levels);
    live_ = grown;
    liveEntries_ = liveEntries_ + added - stored;
    if (L.entries_.size() > 2 * liveEntries_ + (1u << 20)) compactEntries();
  }
}

void CubemapBuilder::queueCrowdedBaseCells() {
  const CubemapLocator& L = locator_;
  for (std::size_t c = 0; c < L.nodes_.size(); ++c)
    if (const std::uint32_t n = L.nodes_[c].count;
        (n > kCrowdedCell3D && !isZoneLeaf(n) && !isSectorLeaf(n)) ||
        (isSectorLeaf(n) && leafEntries(n) > 1)) {
      const BaseCell base = baseCellAt(c, L.resolution_);
      queue(
          {static_cast<std::uint32_t>(c), base.i, base.j, static_cast<std::uint8_t>(base.face), 0});
    }
}

std::span<const std::uint32_t> CubemapBuilder::parentFaces(const Node& nd) {
  if (!isSectorLeaf(nd.count)) return {locator_.entries_.data() + nd.first, nd.count};
  fanLeafFaces(nd, expanded_);
  return expanded_;
}

void CubemapBuilder::queue(Pending q) {
  q.faces = static_cast<std::uint32_t>(parentFaces(locator_.nodes_[q.node]).size());
  q.order = queued_++;
  queue_.push_back(q);
  std::push_heap(queue_.begin(), queue_.end(), morePressing);
}

void CubemapBuilder::sortFaces(const Pending& q, std::span<const std::uint32_t> faces) {
  // a small face in front of the cube face goes by its box (a superset of its projection,
  // so still conservative); others by their polygon
  const CubemapLocator& L = locator_;
  const std::vector<Vec3>& v = L.surface_.vertices;
  const double K1 = levelScale(L.resolution_, q.level + 1);
  small_.clear(), large_.clear(), smallBoxes_.clear(), largePolys_.clear();
  std::array<double, 4>& all = smallBounds_;
  all = {HUGE_VAL, -HUGE_VAL, HUGE_VAL, -HUGE_VAL};
  Cone k;
  Poly P, B;
  const auto& triangles = polyhedron_.triangles();
  for (const std::uint32_t f : faces) {
    for (std::uint32_t tri : polyhedron_.planeTriangles(f)) {
      const ConvexPolyhedron::Triangle& t = triangles[tri];
      if (projectedBox(v, t, L.centre_, q.face, B) && B.p[2].x - B.p[0].x <= 1 / K1 &&
          B.p[2].y - B.p[0].y <= 1 / K1) {
        small_.push_back(f);
        smallBoxes_.push_back({B.p[0].x, B.p[2].x, B.p[0].y, B.p[2].y});
        all = {std::min(all[0], B.p[0].x), std::max(all[1], B.p[2].x), std::min(all[2], B.p[0].y),
               std::max(all[3], B.p[2].y)};
      } else if (coneOf(v, t, L.centre_, scale_, k) && onCubeFace(k, q.face, P)) {
        large_.push_back(f);
        largePolys_.push_back(P);
      }
    }
  }
}

void CubemapBuilder::smallFacesCells(double K, std::int64_t& i0, std::int64_t& i1, std::int64_t& j0,
                                     std::int64_t& j1) const {
  cellRange(smallBounds_[0], smallBounds_[1], K, i0, i1);
  cellRange(smallBounds_[2], smallBounds_[3], K, j0, j1);
}

int CubemapBuilder::chainLevels(const Pending& q) const {
  // while all the small faces stay in one cell, descend several levels at once; only the
  // large faces are placed in the cells beside the chain
  const CubemapLocator& L = locator_;
  int deepest = q.level;
  if (small_.size() > kCrowdedCell3D) {
    for (int level = q.level + 1; level <= L.deepestLevel_; ++level) {
      const std::int64_t n = static_cast<std::int64_t>(L.resolution_) << level;
      std::int64_t i0 = 0, i1 = n - 1, j0 = 0, j1 = n - 1;
      smallFacesCells(levelScale(L.resolution_, level), i0, i1, j0, j1);
      if (i0 != i1 || j0 != j1) break;
      deepest = level;
    }
  }
  return deepest >= q.level + 2 ? deepest - q.level : 1;
}

std::size_t CubemapBuilder::listChildren(const Pending& q, int levels) {
  std::size_t added = 0;
  std::int64_t ci = q.i, cj = q.j;  // the chain's cell at the level above
  for (int l = 0; l < levels; ++l) {
    const double K = levelScale(locator_.resolution_, q.level + 1 + l);
    const std::int64_t i0 = 2 * ci, j0 = 2 * cj;
    std::vector<std::uint32_t>(&lists)[4] = lists_[l];
    for (auto& list : lists) list.clear();
    auto placer = [&](std::uint32_t f) {
      return
          [&, f](std::int64_t i, std::int64_t j) { lists[(j - j0) * 2 + (i - i0)].push_back(f); };
    };
    for (std::size_t m = 0; m < large_.size(); ++m)
      rasterise(largePolys_[m], K, i0, i0 + 1, j0, j0 + 1, placer(large_[m]));
    if (l + 1 == levels) {
      for (std::size_t m = 0; m < small_.size(); ++m)
        rasterise(boxPoly(smallBoxes_[m]), K, i0, i0 + 1, j0, j0 + 1, placer(small_[m]));
    } else {
      // the chain's cell at this level: the one cell every small box meets
      std::int64_t i1 = i0 + 1, j1 = j0 + 1, ii = i0, jj = j0;
      smallFacesCells(K, ii, i1, jj, j1);
      ci = ii, cj = jj;
      lists[(cj - j0) * 2 + (ci - i0)].clear();  // an inner node: its faces go deeper
    }
    for (auto& list : lists) {
      // a face whose triangles meet the cell is listed once
      std::sort(list.begin(), list.end());
      list.erase(std::unique(list.begin(), list.end()), list.end());
      added += list.size();
    }
  }
  return added;
}

bool CubemapBuilder::splitIsFutile(std::size_t parent, std::size_t added) const {
  // an ordinary split: stop where a child keeps every face while the others share many (a
  // vertex all of them meet, which no split separates; a walk searches it instead)
  std::size_t most = 0;
  for (const auto& list : lists_[0]) most = std::max(most, list.size());
  return most == parent && added - most > parent / 2;
}

void CubemapBuilder::commitChildren(const Pending& q, int levels) {
  // an inner chain cell gets its children at the next level
  std::uint32_t node = q.node;
  std::int64_t ci = q.i, cj = q.j;
  for (int l = 0; l < levels; ++l) {
    const int level = q.level + 1 + l;
    const std::uint32_t first = addChildren(node, 2 * ci, 2 * cj, q.face, level, lists_[l]);
    if (l + 1 == levels) break;
    std::int64_t i1 = 2 * ci + 1, j1 = 2 * cj + 1, ii = 2 * ci, jj = 2 * cj;
    smallFacesCells(levelScale(locator_.resolution_, level), ii, i1, jj, j1);
    node = first + static_cast<std::uint32_t>((jj - 2 * cj) * 2 + (ii - 2 * ci));
    ci = ii, cj = jj;
  }
}

std::uint32_t CubemapBuilder::addChildren(std::uint32_t node, std::int64_t i0, std::int64_t j0,
                                          std::uint8_t face, int level,
                                          std::vector<std::uint32_t> (&lists)[4]) {
  CubemapLocator& L = locator_;
  const auto first = static_cast<std::uint32_t>(L.nodes_.size());
  for (int c = 0; c < 4; ++c) {
    L.nodes_.push_back({static_cast<std::uint32_t>(L.entries_.size()),
                        static_cast<std::uint32_t>(lists[c].size())});
    L.entries_.insert(L.entries_.end(), lists[c].begin(), lists[c].end());
    if (lists[c].size() > kCrowdedCell3D)
      queue({first + static_cast<std::uint32_t>(c), static_cast<std::uint32_t>(i0 + (c & 1)),
             static_cast<std::uint32_t>(j0 + (c >> 1)), face, static_cast<std::uint8_t>(level)});
  }
  L.nodes_[node] = {first, kInner};
  return first;
}

void CubemapBuilder::compactEntries() {
  CubemapLocator& L = locator_;
  Table<std::uint32_t> kept;
  kept.reserve(liveEntries_);
  for (Node& nd : L.nodes_) {
    if (nd.count == kInner) continue;
    const auto first = static_cast<std::uint32_t>(kept.size());
    kept.insert(kept.end(), L.entries_.begin() + nd.first,
                L.entries_.begin() + nd.first + entryCount(nd.count));
    nd.first = first;
  }
  L.entries_.swap(kept);
}

}  // namespace convexloc
