// convexloc-bench, shapes as CAD programs export them: the cube map on cylinders with
// fan-triangulated caps (N sides, 4N - 4 triangles) beside a geodesic sphere of about as
// many triangles, and the near-boundary classification (vertices, points on edges and faces
// and their ulp neighbours) of a tilted prism over a large lattice polygon beside the same on
// a geodesic sphere. Every figure is items (points) per second.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <map>
#include <memory>
#include <utility>
#include <vector>

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

[[maybe_unused]] const bool registered = [] {
  for (std::int64_t sides : {64, 512, 4096, 65536}) {
    benchmark::RegisterBenchmark("Cylinder3D/cubemap", cylinder)->Arg(sides);
    benchmark::RegisterBenchmark("Cylinder3D/geodesic", sphereLikeCylinder)->Arg(sides);
    benchmark::RegisterBenchmark("BuildCylinder3D/cubemap", buildCylinder)->Arg(sides);
  }
  benchmark::RegisterBenchmark("Near3D/prism", prismNear)->Arg(86172);
  benchmark::RegisterBenchmark("Near3D/geodesic", sphereNear)->Arg(86172);
  return true;
}();

}  // namespace
