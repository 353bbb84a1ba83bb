// convexloc — the cube map's tables as plain arrays, and a locator loaded from them: every
// size, index, mark and level checked, so that no query reads outside the tables; the lists
// radii and slabs are trusted to be the builder's (see CubemapLocator's load constructor).
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "convexloc/error.hpp"
#include "convexloc/locate3d.hpp"
#include "convexloc/predicates.hpp"
#include "cubemap/build.hpp"
#include "cubemap/index.hpp"

namespace convexloc {
namespace {

// what a sign table stores for orient3d's sign: 1 for +1, 0 for -1
std::uint32_t signBit(int sign) {
  return sign > 0 ? 1u : 0u;
}
int signOf(std::uint32_t bit) {
  return bit ? 1 : -1;
}

// a structural check of the tables being loaded: throws ParseError naming the problem
void require(bool ok, const std::string& problem) {
  if (!ok) throw ParseError("cube map tables: " + problem);
}

// the number of records of `width` in `table` called `name`; its size must be a multiple
template <class T>
std::size_t records(const std::vector<T>& table, std::size_t width, const char* name) {
  require(table.size() % width == 0, std::string(name) + " holds " + std::to_string(table.size()) +
                                         " values, not a multiple of " + std::to_string(width));
  return table.size() / width;
}

// every value of `table` (named `name`) below `bound` (named `what`)
void allBelow(const std::vector<std::uint32_t>& table, std::size_t bound, const char* name,
              const char* what) {
  for (std::size_t k = 0; k < table.size(); ++k)
    require(table[k] < bound, std::string(name) + "[" + std::to_string(k) +
                                  "] = " + std::to_string(table[k]) + " is not below the " +
                                  std::to_string(bound) + " " + what);
}

}  // namespace

CubemapTables CubemapLocator::tables() const {
  CubemapTables t;
  t.resolution = centred_ ? resolution_ : 0;
  t.buildSeconds = buildSeconds_;
  if (!centred_) return t;
  t.centre = centre_;
  for (const Node& nd : nodes_) {
    t.nodes.insert(t.nodes.end(), {nd.first, nd.count});
    t.radii.insert(t.radii.end(), {nd.in2, nd.out2});
  }
  for (const Slab& b : slabs_) t.slabs.insert(t.slabs.end(), {b.n[0], b.n[1], b.n[2], b.lo, b.hi});
  t.entries.assign(entries_.begin(), entries_.end());
  for (const Zone& z : zones_) t.zones.insert(t.zones.end(), {z.first, z.size, signBit(z.sigma)});
  for (const auto& e : zoneEdges_) t.zoneEdges.insert(t.zoneEdges.end(), {e[0], e[1]});
  t.zoneFaces = zoneFaces_;
  for (const ZoneRange& r : zoneRanges_)
    t.zoneRanges.insert(t.zoneRanges.end(), {r.zone, r.lo, r.span});
  for (const Sectors& f : sectors_) {
    t.sectorPoints.insert(t.sectorPoints.end(), {f.axis.x, f.axis.y, f.axis.z, f.reference.x,
                                                 f.reference.y, f.reference.z});
    t.sectors.insert(t.sectors.end(), {signBit(f.sign), f.first, f.size, f.back});
  }
  t.sectorFaces = sectorFaces_;
  t.sectorKeys = sectorKeys_;
  for (const SectorRange& r : sectorRanges_)
    t.sectorRanges.insert(t.sectorRanges.end(), {r.fan, r.from, r.to});
  return t;
}

// === loading

namespace {

// Loads the tables into a locator, checking each as it goes (the order: the grid, the
// zones and fans, then the nodes and their leaves, which index all of them).
class TableLoader {
 public:
  TableLoader(const CubemapTables& t, std::size_t vertices, std::size_t faces)
      : t_(t), vertices_(vertices), faces_(faces) {}

  // the base grid's G and deepest level
  int checkGrid() const {
    require(t_.resolution >= 1 && t_.resolution <= cubemap::kMaxResolution,
            "the resolution " + std::to_string(t_.resolution) + " is not in 1.." +
                std::to_string(cubemap::kMaxResolution));
    return cubemap::depthFor(t_.resolution);
  }

  std::vector<CubemapLocator::Zone> zones(std::size_t& edges) const {
    edges = records(t_.zoneEdges, 2, "zone_edges");
    require(t_.zoneFaces.size() == edges, "zone_faces holds " +
                                              std::to_string(t_.zoneFaces.size()) + " faces for " +
                                              std::to_string(edges) + " edges");
    allBelow(t_.zoneEdges, vertices_, "zone_edges", "vertices");
    allBelow(t_.zoneFaces, faces_, "zone_faces", "faces");
    std::vector<CubemapLocator::Zone> out(records(t_.zones, 3, "zones"));
    for (std::size_t k = 0; k < out.size(); ++k) {
      const std::uint32_t* z = t_.zones.data() + 3 * k;
      const std::string name = "zone " + std::to_string(k);
      require(z[1] >= 1 && std::uint64_t{z[0]} + z[1] <= edges,
              name + " does not lie within the " + std::to_string(edges) + " zone edges");
      require(z[2] <= 1, name + " has the sign mark " + std::to_string(z[2]) + ", not 0 or 1");
      out[k] = {z[0], z[1], signOf(z[2])};
    }
    return out;
  }

  std::vector<CubemapLocator::ZoneRange> zoneRanges(
      const std::vector<CubemapLocator::Zone>& zones) const {
    std::vector<CubemapLocator::ZoneRange> out(records(t_.zoneRanges, 3, "zone_ranges"));
    for (std::size_t k = 0; k < out.size(); ++k) {
      const std::uint32_t* r = t_.zoneRanges.data() + 3 * k;
      const std::string name = "zone range " + std::to_string(k);
      require(r[0] < zones.size(),
              name + " names zone " + std::to_string(r[0]) + " of " + std::to_string(zones.size()));
      // the bisection reaches places lo .. lo + span - 1, each taken mod the zone's size once
      const std::uint32_t size = zones[r[0]].size;
      require(r[1] < size && r[2] >= 1 && r[2] <= size,
              name + " does not lie within its zone of " + std::to_string(size) + " faces");
      out[k] = {r[0], r[1], r[2]};
    }
    return out;
  }

  std::vector<CubemapLocator::Sectors> sectors() const {
    require(t_.sectorKeys.size() == t_.sectorFaces.size(),
            "sector_keys holds " + std::to_string(t_.sectorKeys.size()) + " keys for " +
                std::to_string(t_.sectorFaces.size()) + " sector faces");
    allBelow(t_.sectorFaces, faces_, "sector_faces", "faces");
    for (std::size_t k = 0; k < t_.sectorKeys.size(); ++k)
      require((t_.sectorKeys[k] & cubemap::kSectorKey) < vertices_,
              "sector_keys[" + std::to_string(k) + "] names a vertex beyond the " +
                  std::to_string(vertices_));
    const std::size_t n = records(t_.sectors, 4, "sectors");
    require(records(t_.sectorPoints, 6, "sector_points") == n,
            "sector_points and sectors describe different numbers of fans");
    std::vector<CubemapLocator::Sectors> out(n);
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t* f = t_.sectors.data() + 4 * k;
      const double* q = t_.sectorPoints.data() + 6 * k;
      const std::string name = "fan " + std::to_string(k);
      for (int i = 0; i < 6; ++i) require(std::isfinite(q[i]), name + " has a non-finite point");
      require(f[0] <= 1, name + " has the sign mark " + std::to_string(f[0]) + ", not 0 or 1");
      require(std::uint64_t{f[1]} + f[2] <= t_.sectorKeys.size(),
              name + " does not lie within the " + std::to_string(t_.sectorKeys.size()) +
                  " sector keys");
      require(f[3] <= f[2], name + " has more back faces than faces");
      // place j's window starts `back` faces before j: never before the fan's first face
      for (std::uint32_t j = 0; j < f[2]; ++j)
        require((t_.sectorKeys[f[1] + j] >> cubemap::kSectorBackShift) <= j,
                name + "'s key " + std::to_string(j) + " reaches before the fan's first face");
      out[k] = {{q[0], q[1], q[2]}, {q[3], q[4], q[5]}, signOf(f[0]), f[1], f[2], f[3]};
    }
    return out;
  }

  std::vector<CubemapLocator::SectorRange> sectorRanges(
      const std::vector<CubemapLocator::Sectors>& fans) const {
    std::vector<CubemapLocator::SectorRange> out(records(t_.sectorRanges, 3, "sector_ranges"));
    for (std::size_t k = 0; k < out.size(); ++k) {
      const std::uint32_t* r = t_.sectorRanges.data() + 3 * k;
      const std::string name = "sector range " + std::to_string(k);
      require(r[0] < fans.size(),
              name + " names fan " + std::to_string(r[0]) + " of " + std::to_string(fans.size()));
      require(
          r[1] <= r[2] && r[2] <= fans[r[0]].size,
          name + " does not lie within its fan of " + std::to_string(fans[r[0]].size) + " keys");
      out[k] = {r[0], r[1], r[2]};
    }
    return out;
  }

  // node k's leaf: its entries in range, and a zone or sector leaf's first entry a range
  void checkLeaf(std::size_t k, std::uint32_t first, std::uint32_t count, std::size_t zoneRanges,
                 std::size_t sectorRanges) const {
    const std::string name = "node " + std::to_string(k);
    const bool zone = cubemap::isZoneLeaf(count), sector = cubemap::isSectorLeaf(count);
    require(!(zone && (count & cubemap::kSectorLeaf)), name + " is marked both zone and fan");
    const std::uint32_t n = cubemap::leafEntries(count);
    const bool ranged = zone || sector;
    require(n > 0 || !ranged, name + " is marked zone or fan but names no range");
    if (n == 0) return;  // lists nothing: its first entry is never read
    require(std::uint64_t{first} + n <= t_.entries.size(),
            name + "'s entries run past the " + std::to_string(t_.entries.size()) + " entries");
    const std::uint32_t* e = t_.entries.data() + first;
    if (ranged) {
      const std::size_t bound = zone ? zoneRanges : sectorRanges;
      require(e[0] < bound,
              name + " names range " + std::to_string(e[0]) + " of " + std::to_string(bound));
    }
    for (std::uint32_t i = ranged ? 1 : 0; i < n; ++i)
      require(e[i] < faces_,
              name + " lists face " + std::to_string(e[i]) + " of " + std::to_string(faces_));
  }

  // the nodes: 6 G^2 base cells then blocks of 4 children, each block one node's, the tree
  // no deeper than `deepest`; each leaf checked
  void checkNodes(int deepest, std::size_t zoneRanges, std::size_t sectorRanges) const {
    const std::size_t n = records(t_.nodes, 2, "nodes");
    require(t_.radii.size() == 2 * n, "radii holds " + std::to_string(t_.radii.size()) +
                                          " values for " + std::to_string(n) + " nodes");
    const std::size_t base = 6 * std::size_t{t_.resolution} * t_.resolution;
    require(n >= base && (n - base) % 4 == 0, std::to_string(n) + " nodes are not the " +
                                                  std::to_string(base) +
                                                  " base cells and blocks of 4");
    for (std::size_t k = 0; k < n; ++k) {
      const std::uint32_t first = t_.nodes[2 * k], count = t_.nodes[2 * k + 1];
      const float in2 = t_.radii[2 * k], out2 = t_.radii[2 * k + 1];
      const std::string name = "node " + std::to_string(k);
      if (count == cubemap::kInner) {
        require(first >= base && (first - base) % 4 == 0 && first + std::size_t{4} <= n,
                name + "'s children " + std::to_string(first) + " are not a block of nodes");
        require(std::isnan(in2) && std::isnan(out2), name + " is inner but has radii");
      } else {
        require(in2 >= 0 && out2 >= 0, name + "'s radii are not numbers of at least 0");
        checkLeaf(k, first, count, zoneRanges, sectorRanges);
      }
    }
    checkTree(deepest, base, n);
    checkSlabs(n);
  }

 private:
  // none, or one per node: a finite normal and bounds that are not NaN
  void checkSlabs(std::size_t n) const {
    if (t_.slabs.empty()) return;
    require(t_.slabs.size() == 5 * n, "slabs holds " + std::to_string(t_.slabs.size()) +
                                          " values for " + std::to_string(n) + " nodes");
    for (std::size_t k = 0; k < n; ++k) {
      const float* b = t_.slabs.data() + 5 * k;
      require(std::isfinite(b[0]) && std::isfinite(b[1]) && std::isfinite(b[2]) &&
                  !std::isnan(b[3]) && !std::isnan(b[4]),
              "node " + std::to_string(k) + "'s slab is not numbers");
    }
  }

  // every block is the children of one node only, at most `deepest` levels down
  void checkTree(int deepest, std::size_t base, std::size_t n) const {
    std::vector<bool> claimed((n - base) / 4, false);
    std::vector<std::pair<std::uint32_t, int>> stack;
    for (std::size_t c = 0; c < base; ++c) {
      stack.push_back({static_cast<std::uint32_t>(c), 0});
      while (!stack.empty()) {
        const auto [node, level] = stack.back();
        stack.pop_back();
        if (t_.nodes[2 * node + 1] != cubemap::kInner) continue;
        const std::uint32_t first = t_.nodes[2 * node];
        require(level < deepest, "node " + std::to_string(node) + " is split below the " +
                                     std::to_string(deepest) + " levels of its grid");
        require(!claimed[(first - base) / 4],
                "node " + std::to_string(node) + "'s children belong to another node too");
        claimed[(first - base) / 4] = true;
        for (std::uint32_t k = 0; k < 4; ++k) stack.push_back({first + k, level + 1});
      }
    }
  }

  const CubemapTables& t_;
  std::size_t vertices_, faces_;
};

// the cube's half-size around c, which must be finite and strictly inside every face plane
// (exact predicates), with directions from it that do not overflow
double checkCentre(const detail::SurfaceCopy& surface, Vec3 c) {
  require(std::isfinite(c.x) && std::isfinite(c.y) && std::isfinite(c.z),
          "the centre is not finite");
  const std::vector<Vec3>& v = surface.vertices;
  for (const ConvexPolyhedron::Triangle& f : surface.faces)
    require(orient3d(v[f[0]], v[f[1]], v[f[2]], c) > 0, "the centre is not strictly inside");
  const double extent = cubemap::cubeExtent(v, c);
  require(std::isfinite(extent) && extent > 0,
          "the polyhedron's directions from the centre overflow");
  return extent;
}

}  // namespace

CubemapLocator::CubemapLocator(const ConvexPolyhedron& polyhedron, const CubemapTables& t)
    : surface_(polyhedron), mesh_(polyhedron), buildSeconds_(t.buildSeconds), loaded_(true) {
  require(t.version == CubemapTables::kVersion, "version " + std::to_string(t.version) +
                                                    ", where this convexloc reads version " +
                                                    std::to_string(CubemapTables::kVersion));
  if (t.resolution == 0) {  // no cells: every query tests all faces
    require(t.nodes.empty() && t.radii.empty() && t.entries.empty() && t.zones.empty() &&
                t.zoneEdges.empty() && t.zoneFaces.empty() && t.zoneRanges.empty() &&
                t.sectors.empty() && t.sectorPoints.empty() && t.sectorFaces.empty() &&
                t.sectorKeys.empty() && t.sectorRanges.empty() && t.slabs.empty(),
            "the resolution is 0 (no cells), yet there are tables");
    resolution_ = 0;
    return;
  }
  const TableLoader load(t, surface_.vertices.size(), surface_.faces.size());
  deepestLevel_ = load.checkGrid();
  const Vec3 c = t.centre;
  cubeHalfSize_ = checkCentre(surface_, c);
  std::size_t edges = 0;
  zones_ = load.zones(edges);
  zoneRanges_ = load.zoneRanges(zones_);
  sectors_ = load.sectors();
  sectorRanges_ = load.sectorRanges(sectors_);
  load.checkNodes(deepestLevel_, zoneRanges_.size(), sectorRanges_.size());
  for (std::size_t k = 0; k < edges; ++k)
    zoneEdges_.push_back({t.zoneEdges[2 * k], t.zoneEdges[2 * k + 1]});
  zoneFaces_ = t.zoneFaces;
  sectorFaces_ = t.sectorFaces;
  sectorKeys_ = t.sectorKeys;
  nodes_.resize(t.nodes.size() / 2);
  for (std::size_t k = 0; k < nodes_.size(); ++k)
    nodes_[k] = {t.nodes[2 * k], t.nodes[2 * k + 1], t.radii[2 * k], t.radii[2 * k + 1]};
  entries_.assign(t.entries.begin(), t.entries.end());
  slabs_.resize(t.slabs.size() / 5);
  for (std::size_t k = 0; k < slabs_.size(); ++k) {
    const float* b = t.slabs.data() + 5 * k;
    slabs_[k] = {{b[0], b[1], b[2]}, b[3], b[4]};
  }
  centre_ = c;
  resolution_ = t.resolution;
  deepScale_ = std::ldexp(static_cast<double>(resolution_), deepestLevel_ - 1);
  centred_ = true;
}

}  // namespace convexloc
