// convexloc (internal) — the cube map's query, written once for locate(), trace() and the
// batch: aim at a cell, go down to its leaf, let the radii decide, else test the leaf's faces
// (or walk, in a crowded leaf). Why this is exact: cubemap/index.hpp.
#pragma once

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
  return detail::walkAndTest(
      surface_, neighbours_, centre_, p, *first, 16 + leaf.count / 4, sink,
      [&] { return detail::testList(surface_, first, first + leaf.count, p, sink); });
}

}  // namespace convexloc
