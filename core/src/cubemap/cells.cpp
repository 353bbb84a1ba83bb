// convexloc — the cube map's introspection: its leaves as drawable cells, and its statistics.
#include <algorithm>
#include <cmath>

#include "convexloc/locate3d.hpp"
#include "cubemap/index.hpp"
#include "detail/plane_tests3d.hpp"

namespace convexloc {

Stats3D CubemapLocator::stats() const {
  Stats3D s = detail::baseStats(surface_,
                                sizeof(*this) + mesh_.bytes() + detail::bytesOf(zones_) +
                                    detail::bytesOf(zoneEdges_) + detail::bytesOf(zoneFaces_) +
                                    detail::bytesOf(zoneRanges_) + detail::bytesOf(sectors_) +
                                    detail::bytesOf(sectorFaces_) + detail::bytesOf(sectorKeys_) +
                                    detail::bytesOf(sectorRanges_) + detail::bytesOf(nodes_) +
                                    detail::bytesOf(slabs_) + detail::bytesOf(entries_),
                                buildSeconds_);
  s.centred = centred_;
  s.resolution = centred_ ? resolution_ : 0;
  s.nodes = nodes_.size();
  s.histogram.assign(kCrowdedCell3D + 2, 0);
  if (!centred_) return s;
  for (const Node& nd : nodes_) {
    if (nd.count == cubemap::kInner) continue;
    const bool special = cubemap::isZoneLeaf(nd.count) || cubemap::isSectorLeaf(nd.count);
    const std::size_t count = special ? leafFaces(nd).size() : nd.count;
    ++s.cells;
    s.entries += count;
    s.maxPerCell = std::max(s.maxPerCell, count);
    if (count > kCrowdedCell3D) ++s.crowdedCells;
    s.zoneCells += cubemap::isZoneLeaf(nd.count);
    s.sectorCells += cubemap::isSectorLeaf(nd.count);
    ++s.histogram[std::min<std::size_t>(count, s.histogram.size() - 1)];
  }
  s.meanPerCell = s.cells ? static_cast<double>(s.entries) / static_cast<double>(s.cells) : 0.0;
  forEachLeaf([&](std::uint32_t, int, int level, std::uint32_t, std::uint32_t) {
    s.maxLevel = std::max(s.maxLevel, level);
  });
  return s;
}

std::vector<Cell3D> CubemapLocator::cells() const {
  std::vector<Cell3D> out;
  if (!centred_) return out;
  forEachLeaf([&](std::uint32_t node, int cf, int level, std::uint32_t i, std::uint32_t j) {
    const Node nd = nodes_[node];
    Cell3D cell;
    cell.index = static_cast<std::uint32_t>(out.size());
    cell.cubeFace = cf;
    cell.level = level;
    cell.i = i;
    cell.j = j;
    const double K = cubemap::levelScale(resolution_, level);
    cell.s0 = -1 + i / K;
    cell.s1 = -1 + (i + 1) / K;
    cell.t0 = -1 + j / K;
    cell.t1 = -1 + (j + 1) / K;
    cell.apex = centre_;
    const double st[4][2] = {
        {cell.s0, cell.t0}, {cell.s1, cell.t0}, {cell.s1, cell.t1}, {cell.s0, cell.t1}};
    for (int q = 0; q < 4; ++q) {
      const Vec3 d = cubemap::cubeDirection(cf, st[q][0], st[q][1]);
      cell.corners[q] = {centre_.x + cubeHalfSize_ * d.x, centre_.y + cubeHalfSize_ * d.y,
                         centre_.z + cubeHalfSize_ * d.z};
    }
    cell.faces = leafFaces(nd);
    out.push_back(std::move(cell));
  });
  return out;
}

}  // namespace convexloc
