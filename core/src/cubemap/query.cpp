// convexloc — the cube map's single-point queries: locate(p) and trace(p).
#include "cubemap/query.hpp"

#include <algorithm>
#include <optional>

#include "cubemap/index.hpp"
#include "detail/radii.hpp"
#include "detail/sinks3d.hpp"

namespace convexloc {

std::optional<Vec3> CubemapLocator::centre() const noexcept {
  if (!centred_) return std::nullopt;
  return centre_;
}

Location CubemapLocator::locate(Vec3 p) const noexcept {
  // Most points: aimed at a cell, down to its leaf and decided by its radii. All in line, no
  // call: a caller's loop of independent points then keeps several cells' memory reads in
  // flight at once. The rest go on from the leaf (its slab, then its faces).
  Aim a;
  detail::NoSink3D sink;
  if (aim(p, a) > 0) {
    int level = 0;
    const Node& nd = nodes_[leafAt(a.deepI, a.deepJ, a.baseCell, level)];
    if (detail::radiiDecide(a.d2, nd.in2, nd.out2))
      return detail::insideOrOutside(a.d2 > static_cast<double>(nd.out2));
    return fromLeaf(p, a.d2, nd, sink);
  }
  return run(p, sink);
}

std::vector<std::uint32_t> CubemapLocator::cellFaces(Vec3 p) const {
  Aim a;
  if (aim(p, a) <= 0) return {};
  int level = 0;
  return leafFaces(nodes_[leafAt(a.deepI, a.deepJ, a.baseCell, level)]);
}

std::vector<std::uint32_t> CubemapLocator::leafFaces(const Node& nd) const {
  const std::uint32_t* e = entries_.data() + nd.first;
  if (cubemap::isSectorLeaf(nd.count)) {
    // the others, and the fan's faces from the first any window of the range holds on
    const SectorRange& r = sectorRanges_[e[0]];
    const Sectors& f = sectors_[r.fan];
    std::uint32_t lo = r.from;
    for (std::uint32_t j = r.from; j <= r.to; ++j)
      lo = std::min(
          lo, j - (j < f.size ? sectorKeys_[f.first + j] >> cubemap::kSectorBackShift : f.back));
    std::vector<std::uint32_t> faces(e + 1, e + cubemap::leafEntries(nd.count));
    faces.insert(faces.end(), sectorFaces_.begin() + f.first + lo,
                 sectorFaces_.begin() + f.first + r.to);
    std::sort(faces.begin(), faces.end());
    return faces;
  }
  if (!cubemap::isZoneLeaf(nd.count)) return {e, e + nd.count};
  const ZoneRange& r = zoneRanges_[e[0]];
  const Zone& z = zones_[r.zone];
  std::vector<std::uint32_t> faces;
  for (std::uint32_t k = 0; k < r.span; ++k)
    faces.push_back(zoneFaces_[z.first + (r.lo + k) % z.size]);
  faces.insert(faces.end(), e + 1, e + (nd.count & ~cubemap::kZoneLeaf));
  std::sort(faces.begin(), faces.end());
  return faces;
}

Trace3D CubemapLocator::trace(Vec3 p, TraceOptions options) const {
  Trace3D t = detail::traced(
      Method3D::Cubemap, centre(), [&](auto& sink) { return run(p, sink); }, options);
  if (t.cubeFace >= 0) {
    t.direction = {p.x - centre_.x, p.y - centre_.y, p.z - centre_.z};
    t.cellsPerSide = resolution_ << t.level;
  }
  return t;
}

}  // namespace convexloc
