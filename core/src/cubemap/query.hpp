// convexloc (internal) — the cube map's query, written once for locate(), trace() and the
// batch: aim at a cell, go down to its leaf, let the radii decide, else its slab, else test
// the leaf's faces (or walk, in a crowded leaf). Why this is exact: cubemap/index.hpp.
#pragma once

#include <algorithm>
#include <cstdint>
#include <type_traits>

#include "convexloc/locate3d.hpp"
#include "convexloc/predicates.hpp"
#include "cubemap/index.hpp"
#include "detail/plane_tests3d.hpp"
#include "detail/radii.hpp"
#include "detail/sinks3d.hpp"
#include "detail/walk_step.hpp"

namespace convexloc {

template <class Sink>
Location CubemapLocator::run(Vec3 p, Sink& sink) const noexcept {
  Aim a;
  const int aimed = aim(p, a);
  if (aimed == 0) {
    sink.atCentre();  // strictly inside
    return Location::Inside;
  }
  if (aimed < 0) {
    if (!detail::isFinite(p)) {
      sink.nonFinite();
      return Location::Outside;
    }
    sink.fallback();  // no centre, or the direction overflows
    return detail::testAll(surface_, p, sink);
  }
  int level = 0;
  const std::uint32_t node = leafAt(a.deepI, a.deepJ, a.baseCell, level);
  const int up = deepestLevel_ - level;
  sink.cell(a.face, level, a.deepI >> up, a.deepJ >> up, a.s, a.t);
  return fromLeaf(p, a.d2, nodes_[node], sink);
}

template <class Sink>
Location CubemapLocator::fromLeaf(Vec3 p, double d2, const Node& leaf, Sink& sink) const noexcept {
  if (sink.radii()) {  // always, but in a trace asked without the radius filter
    const bool decided = detail::radiiDecide(d2, leaf.in2, leaf.out2);
    sink.radius(d2, leaf.in2, leaf.out2, decided);
    if (decided) return detail::insideOrOutside(d2 > static_cast<double>(leaf.out2));
    // d2 <= out2 bounds the slab's rounding (cubemap/slabs.cpp)
    if (!slabs_.empty() && d2 <= static_cast<double>(leaf.out2)) {
      const Slab& b = slabs_[static_cast<std::size_t>(&leaf - nodes_.data())];
      const double v = static_cast<double>(b.n[0]) * (p.x - centre_.x) +
                       static_cast<double>(b.n[1]) * (p.y - centre_.y) +
                       static_cast<double>(b.n[2]) * (p.z - centre_.z);
      const bool beyond = v > static_cast<double>(b.hi);
      const bool bySlab = beyond | (v < static_cast<double>(b.lo));
      sink.slab(bySlab);
      if (bySlab) return detail::insideOrOutside(beyond);
    }
  }
  if constexpr (std::is_same_v<Sink, detail::NoSink3D>) {
    // Untraced, a leaf that is not crowded: every face's filter, then the answer without a
    // branch on it (inside and outside come at random). A face surely beyond p's side
    // decides Outside, all faces surely on the inner side Inside; the exact tests below
    // only where neither holds.
    if (leaf.count - 1 < kCrowdedCell3D) {
      const std::uint32_t* e = entries_.data() + leaf.first;
      const std::vector<Vec3>& v = surface_.vertices;
      bool beyond = false, allSure = true;
      for (std::uint32_t k = 0; k < leaf.count; ++k) {
        const ConvexPolyhedron::Triangle& t = surface_.faces[e[k]];
        const auto s = detail::orient3dTerms(v[t[0]], v[t[1]], v[t[2]], p);
        const bool sure = detail::orient3dSure(s);
        beyond |= sure & (s.det < 0);
        allSure &= sure;
      }
      if (beyond | allSure) return detail::insideOrOutside(beyond);
    }
  }
  const std::uint32_t* first = entries_.data() + leaf.first;
  if (leaf.count == 0) {
    sink.fallback();  // cannot happen (every direction leaves through some face); be safe
    return detail::testAll(surface_, p, sink);
  }
  if (leaf.count <= kCrowdedCell3D)
    return detail::testList(surface_, first, first + leaf.count, p, sink);
  sink.crowded();
  if (cubemap::isZoneLeaf(leaf.count)) return fromZone(p, leaf, sink);
  if (cubemap::isSectorLeaf(leaf.count)) return fromSectors(p, leaf, sink);
  return detail::walkAndTest(
      surface_, mesh_, centre_, p, mesh_.triangle(*first), 16 + leaf.count / 4, sink,
      [&] { return detail::testList(surface_, first, first + leaf.count, p, sink); });
}

template <class Sink>
Location CubemapLocator::fromZone(Vec3 p, const Node& leaf, Sink& sink) const noexcept {
  // the first k in [1, span) with p strictly before edge lo + k: p's direction then lies in
  // the wedge of face lo + k - 1 (the last face when there is none); see cubemap/zones.cpp
  const std::uint32_t* e = entries_.data() + leaf.first;
  const std::uint32_t others = (leaf.count & ~cubemap::kZoneLeaf) - 1;
  const ZoneRange& r = zoneRanges_[e[0]];
  const Zone& z = zones_[r.zone];
  const std::vector<Vec3>& v = surface_.vertices;
  auto at = [&](std::uint32_t k) {
    const std::uint32_t m = r.lo + k;
    return z.first + (m >= z.size ? m - z.size : m);
  };
  std::uint32_t lo = 1, hi = r.span;
  while (lo < hi) {
    const std::uint32_t mid = lo + (hi - lo) / 2;
    const std::array<std::uint32_t, 2>& edge = zoneEdges_[at(mid)];
    const int s = orient3d(centre_, v[edge[0]], v[edge[1]], p);
    sink.zone(at(mid) - z.first, edge[0], edge[1], s);
    if (s == z.sigma)
      hi = mid;
    else
      lo = mid + 1;
  }
  const std::uint32_t face = zoneFaces_[at(lo - 1)];
  const int s = detail::planeSign(surface_, face, p);
  sink.face(face, s);
  if (s < 0) return Location::Outside;
  const Location rest = detail::testList(surface_, e + 1, e + 1 + others, p, sink);
  return rest == Location::Inside && s == 0 ? Location::Boundary : rest;
}

template <class Sink>
Location CubemapLocator::fromSectors(Vec3 p, const Node& leaf, Sink& sink) const noexcept {
  // past the plane through the axis and the reference: the ray leaves through one of the
  // others; else p's place j among the leaf's keys, the faces of j's window (the back faces
  // before it) and the others (see cubemap/sectors.cpp)
  const std::uint32_t* e = entries_.data() + leaf.first;
  const SectorRange& r = sectorRanges_[e[0]];
  const Sectors& f = sectors_[r.fan];
  const std::uint32_t* others = e + 1;
  const std::uint32_t count = cubemap::leafEntries(leaf.count) - 1;
  const std::uint32_t* keys = sectorKeys_.data() + f.first;
  const std::uint32_t* faces = sectorFaces_.data() + f.first;
  const std::vector<Vec3>& v = surface_.vertices;
  std::uint32_t from = 0, to = 0;  // the window
  if (orient3d(centre_, f.axis, f.reference, p) == f.sign) {
    std::uint32_t lo = r.from, hi = r.to;
    const detail::Orient3dAround around(centre_, f.axis, p);  // orient3d(c, axis, ., p)
    while (lo < hi) {
      const std::uint32_t mid = lo + (hi - lo) / 2;
      const std::uint32_t key = keys[mid] & cubemap::kSectorKey;
      const int s = around(v[key]);
      sink.sector(mid, key, s);
      if (s == f.sign)
        lo = mid + 1;
      else
        hi = mid;
    }
    from = lo - (lo < f.size ? keys[lo] >> cubemap::kSectorBackShift : f.back), to = lo;
  } else if (count == 0) {
    sink.fallback();  // cannot happen (the ray leaves through a listed face); be safe
    return detail::testAll(surface_, p, sink);
  }
  if constexpr (std::is_same_v<Sink, detail::NoSink3D>) {
    // untraced: every face's filter without a branch on it, as for a plain leaf
    bool beyond = false, allSure = true;
    auto filter = [&](const std::uint32_t* first, const std::uint32_t* last) {
      for (const std::uint32_t* k = first; k != last; ++k) {
        const ConvexPolyhedron::Triangle& t = surface_.faces[*k];
        const auto terms = detail::orient3dTerms(v[t[0]], v[t[1]], v[t[2]], p);
        const bool sure = detail::orient3dSure(terms);
        beyond |= sure & (terms.det < 0);
        allSure &= sure;
      }
    };
    filter(faces + from, faces + to);
    filter(others, others + count);
    if (beyond | allSure) return detail::insideOrOutside(beyond);
  }
  const Location near = detail::testList(surface_, faces + from, faces + to, p, sink);
  if (near == Location::Outside) return near;
  const Location rest = detail::testList(surface_, others, others + count, p, sink);
  return rest == Location::Inside ? near : rest;
}

}  // namespace convexloc
