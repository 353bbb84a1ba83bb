// convexloc-bench, shapes as CAD programs export them: the cube map on cylinders with
// fan-triangulated caps (N sides, 4N - 4 triangles) beside a geodesic sphere of about as
// many triangles, and the near-boundary classification (vertices, points on edges and faces
// and their ulp neighbours) of a tilted prism over a large lattice polygon beside the same on
// a geodesic sphere; and the CAD family (cad_family.hpp: 64 .. 65536 sides, heights 0.1 to
// 10 radii, turned by odd angles, at the origin or moved to 10^6, rounded to float32, read as
// the hull where rounding folds them) beside a geodesic sphere of as many triangles. Every
// figure is items (points) per second.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <map>
#include <memory>
#include <tuple>
#include <utility>
#include <vector>

#include "cad_family.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/locate3d.hpp"
#include "fixtures.hpp"

using namespace convexloc;
using namespace bench;

namespace {

// the shape of `kind` with about `triangles` triangles, built once
const ConvexPolyhedron& cadShape(PolyhedronKind kind, std::int64_t triangles) {
  static std::map<std::pair<PolyhedronKind, std::int64_t>, std::unique_ptr<ConvexPolyhedron>> cache;
  auto& slot = cache[{kind, triangles}];
  if (!slot)
    slot = std::make_unique<ConvexPolyhedron>(
        generatePolyhedron(kind, static_cast<std::size_t>(triangles), 1));
  return *slot;
}

// one point per call: uniform points in the box (near = false) or near-boundary ones
void locateOn(benchmark::State& state, const ConvexPolyhedron& p, bool near) {
  const CubemapLocator loc(p);
  const std::vector<Vec3> pts = generatePoints3D(p, kLocatePoints, 42, near);
  timeEachPoint(state, pts, [&](Vec3 q) { return loc.locate(q); });
  state.counters["faces"] = static_cast<double>(p.planeCount());
  state.counters["triangles"] = static_cast<double>(p.faceCount());
  const Stats3D s = loc.stats();
  state.counters["build_s"] = s.buildSeconds;
  state.counters["crowded"] = static_cast<double>(s.crowdedCells);
  state.counters["sectors"] = static_cast<double>(s.sectorCells);
}

// range(0) = N sides: the cylinder with fan caps, or the geodesic sphere of 4N - 4 triangles
void cylinder(benchmark::State& state) {
  locateOn(state, cadShape(PolyhedronKind::Cylinder, 4 * state.range(0) - 4), false);
}
void sphereLikeCylinder(benchmark::State& state) {
  locateOn(state, cadShape(PolyhedronKind::Geodesic, 4 * state.range(0) - 4), false);
}

// range(0) = triangles: near-boundary points of the tilted lattice prism or a geodesic sphere
void prismNear(benchmark::State& state) {
  locateOn(state, cadShape(PolyhedronKind::Prism, state.range(0)), true);
}
void sphereNear(benchmark::State& state) {
  locateOn(state, cadShape(PolyhedronKind::Geodesic, state.range(0)), true);
}

// building the cube map on the cylinder of range(0) sides
void buildCylinder(benchmark::State& state) {
  const ConvexPolyhedron& p = cadShape(PolyhedronKind::Cylinder, 4 * state.range(0) - 4);
  for (auto _ : state) benchmark::DoNotOptimize(CubemapLocator(p));
  state.SetItemsProcessed(state.iterations() * static_cast<std::int64_t>(p.faceCount()));
}

// range: sides, height in tenths of a radius, moved (0 or 1)
cadfamily::Part familyPart(const benchmark::State& state) {
  return {static_cast<std::size_t>(state.range(0)), static_cast<double>(state.range(1)) / 10,
          state.range(2) != 0};
}

// the family member, built once, and whether it was read as its hull
const ConvexPolyhedron& familyShape(const cadfamily::Part& part, bool& hull) {
  static std::map<std::tuple<std::size_t, double, bool>,
                  std::pair<std::unique_ptr<ConvexPolyhedron>, bool>>
      cache;
  auto& slot = cache[{part.sides, part.heightRadii, part.moved}];
  if (!slot.first)
    slot.first = std::make_unique<ConvexPolyhedron>(cadfamily::polyhedron(part, &slot.second));
  hull = slot.second;
  return *slot.first;
}

// one member of the family: uniform points, one per call; its build time as a counter
void family(benchmark::State& state) {
  bool hull = false;
  const ConvexPolyhedron& p = familyShape(familyPart(state), hull);
  locateOn(state, p, false);
  state.counters["hull"] = hull ? 1 : 0;
}

// the geodesic sphere of as many triangles as the family member
void familySphere(benchmark::State& state) {
  bool hull = false;
  const ConvexPolyhedron& p = familyShape(familyPart(state), hull);
  locateOn(state, cadShape(PolyhedronKind::Geodesic, static_cast<std::int64_t>(p.faceCount())),
           false);
}

[[maybe_unused]] const bool registered = [] {
  for (std::int64_t sides : {64, 512, 4096, 65536}) {
    benchmark::RegisterBenchmark("Cylinder3D/cubemap", cylinder)->Arg(sides);
    benchmark::RegisterBenchmark("Cylinder3D/geodesic", sphereLikeCylinder)->Arg(sides);
    benchmark::RegisterBenchmark("BuildCylinder3D/cubemap", buildCylinder)->Arg(sides);
  }
  for (std::int64_t sides : {64, 512, 4096, 65536})
    for (std::int64_t tenths : {1, 10, 40, 100})
      for (std::int64_t moved : {0, 1}) {
        benchmark::RegisterBenchmark("CadFamily3D/cubemap", family)->Args({sides, tenths, moved});
        benchmark::RegisterBenchmark("CadFamily3D/geodesic", familySphere)
            ->Args({sides, tenths, moved});
      }
  benchmark::RegisterBenchmark("Near3D/prism", prismNear)->Arg(86172);
  benchmark::RegisterBenchmark("Near3D/geodesic", sphereNear)->Arg(86172);
  return true;
}();

}  // namespace
