// convexloc-bench peers: GEOS prepared contains and CGAL, timed in the same run as
// convexloc on the same shapes and points (built with -DCONVEXLOC_BENCH_PEERS=ON; Debian
// libgeos-dev and libcgal-dev). Families: Locate2D/geos, Locate2D/cgal (bounded_side_2,
// O(N)), Locate3D/cgal (Side_of_triangle_mesh over its AABB tree), Build2D/geos and
// Build3D/cgal. Boundary points count as outside for GEOS's contains, as the peers define it.
#include <benchmark/benchmark.h>
#include <geos_c.h>

#include <CGAL/AABB_face_graph_triangle_primitive.h>
#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2_algorithms.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "fixtures.hpp"

using namespace bench;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;
using Mesh = CGAL::Surface_mesh<K::Point_3>;

// a GEOS polygon, prepared (its edges indexed for point-in-polygon queries)
class GeosPrepared {
 public:
  explicit GeosPrepared(const ConvexPolygon& polygon) : ctx_(GEOS_init_r()) {
    const auto v = polygon.vertices();
    GEOSCoordSequence* seq = GEOSCoordSeq_create_r(ctx_, static_cast<unsigned>(v.size() + 1), 2);
    for (std::size_t i = 0; i <= v.size(); ++i) {
      const Vec2 p = v[i % v.size()];
      GEOSCoordSeq_setXY_r(ctx_, seq, static_cast<unsigned>(i), p.x, p.y);
    }
    poly_ = GEOSGeom_createPolygon_r(ctx_, GEOSGeom_createLinearRing_r(ctx_, seq), nullptr, 0);
    prepared_ = GEOSPrepare_r(ctx_, poly_);
    if (!poly_ || !prepared_) throw std::runtime_error("GEOS could not build the polygon");
  }
  ~GeosPrepared() {
    GEOSPreparedGeom_destroy_r(ctx_, prepared_);
    GEOSGeom_destroy_r(ctx_, poly_);
    GEOS_finish_r(ctx_);
  }
  GeosPrepared(const GeosPrepared&) = delete;
  GeosPrepared& operator=(const GeosPrepared&) = delete;

  // GEOS 3.11 has no contains-by-coordinates: a caller makes a point geometry per query
  bool contains(Vec2 p) const {
    GEOSGeometry* pt = GEOSGeom_createPointFromXY_r(ctx_, p.x, p.y);
    const char r = GEOSPreparedContains_r(ctx_, prepared_, pt);
    GEOSGeom_destroy_r(ctx_, pt);
    return r == 1;
  }

 private:
  GEOSContextHandle_t ctx_;
  GEOSGeometry* poly_ = nullptr;
  const GEOSPreparedGeometry* prepared_ = nullptr;
};

std::vector<K::Point_2> cgalPolygon(const ConvexPolygon& polygon) {
  std::vector<K::Point_2> out;
  for (Vec2 p : polygon.vertices()) out.emplace_back(p.x, p.y);
  return out;
}

Mesh cgalMesh(const ConvexPolyhedron& p) {
  Mesh m;
  std::vector<Mesh::Vertex_index> ids;
  for (Vec3 v : p.vertices()) ids.push_back(m.add_vertex(K::Point_3(v.x, v.y, v.z)));
  for (const auto& t : p.triangles()) m.add_face(ids[t[0]], ids[t[1]], ids[t[2]]);
  return m;
}

void geosLocate(benchmark::State& state) {
  const GeosPrepared geos(polygon(state.range(0)));
  geos.contains({0, 0});  // GEOS indexes the edges on the first query: not a query's time
  timeEachPoint(state, points<Vec2>(state.range(0), kLocatePoints),
                [&](Vec2 p) { return geos.contains(p); });
}

void geosBuild(benchmark::State& state) {
  const ConvexPolygon& p = polygon(state.range(0));
  for (auto _ : state) {
    GeosPrepared geos(p);
    benchmark::DoNotOptimize(&geos);
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

void cgalLocate2D(benchmark::State& state) {
  const std::vector<K::Point_2> poly = cgalPolygon(polygon(state.range(0)));
  timeEachPoint(state, points<Vec2>(state.range(0), kLocatePoints), [&](Vec2 p) {
    return CGAL::bounded_side_2(poly.begin(), poly.end(), K::Point_2(p.x, p.y), K());
  });
}

void cgalLocate3D(benchmark::State& state) {
  const Mesh mesh = cgalMesh(polyhedron(state.range(0)));
  const CGAL::Side_of_triangle_mesh<Mesh, K> side(mesh);
  side(K::Point_3(0, 0, 0));  // builds the AABB tree, which is not part of a query's time
  timeEachPoint(state, points<Vec3>(state.range(0), kLocatePoints),
                [&](Vec3 p) { return side(K::Point_3(p.x, p.y, p.z)); });
  state.counters["faces"] = static_cast<double>(polyhedron(state.range(0)).faceCount());
}

void cgalBuild3D(benchmark::State& state) {
  const Mesh mesh = cgalMesh(polyhedron(state.range(0)));
  for (auto _ : state) {
    CGAL::Side_of_triangle_mesh<Mesh, K> side(mesh);
    // the AABB tree is built on the first query
    benchmark::DoNotOptimize(side(K::Point_3(0, 0, 0)));
  }
  state.SetItemsProcessed(state.iterations() * state.range(0));
}

[[maybe_unused]] const bool registered = [] {
  for (std::int64_t n : {8, 64, 1024, 16384, 262144, 1048576}) {
    benchmark::RegisterBenchmark("Locate2D/geos", geosLocate)->Arg(n);
    benchmark::RegisterBenchmark("Build2D/geos", geosBuild)->Arg(n);
    if (n <= 16384) benchmark::RegisterBenchmark("Locate2D/cgal", cgalLocate2D)->Arg(n);
  }
  for (std::int64_t f : {100, 1000, 10000, 100000, 1000000}) {
    benchmark::RegisterBenchmark("Locate3D/cgal", cgalLocate3D)->Arg(f);
    benchmark::RegisterBenchmark("Build3D/cgal", cgalBuild3D)->Arg(f);
  }
  return true;
}();

}  // namespace
