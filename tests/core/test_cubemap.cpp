// The cubemap's structure: cells that are conservative (checked directly, for directions
// strictly inside too, which exactness alone cannot see), memory within 128 bytes per face on
// hostile shapes, statistics and cells that agree, and traces that tell what happened.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "adversarial3d.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/locate3d.hpp"
#include "reference3d.hpp"
#include "shapes3d.hpp"

using namespace convexloc;

namespace {

// the regular n-gon bipyramid: every face runs from a pole to the equator, so each crosses
// a long row of cells
MeshData spindle(std::uint32_t n) {
  MeshData m;
  for (std::uint32_t i = 0; i < n; ++i) {
    const double a = 2 * 3.14159265358979323846 * i / n;
    m.addVertex({std::cos(a), std::sin(a), 0});
  }
  const std::uint32_t top = m.addVertex({0, 0, 1}), bottom = m.addVertex({0, 0, -1});
  for (std::uint32_t i = 0; i < n; ++i) {
    m.addFace({i, (i + 1) % n, top});
    m.addFace({(i + 1) % n, i, bottom});
  }
  return m;
}

// the memory bound the issue sets: 128 bytes per input triangle plus a constant
void expectWithinBudget(const ConvexPolyhedron& p, const char* what) {
  const CubemapLocator cm(p);
  const Stats3D s = cm.stats();
  EXPECT_EQ(s.triangles, p.faceCount()) << what;
  EXPECT_LE(s.bytes, 128 * s.triangles + 65536) << what;
  EXPECT_LE(s.bytesPerFace, 128.0) << what;
  std::printf(
      "[ info     ] %s: %zu faces (%zu triangles), G = %u, %zu cells (levels 0..%d), %zu over a "
      "zone, %.1f bytes per triangle, built in %.3f s\n",
      what, s.faces, s.triangles, s.resolution, s.cells, s.maxLevel, s.zoneCells, s.bytesPerFace,
      s.buildSeconds);
}

// Checks that the cell a point maps to lists a face whose closed cone from the centre holds
// the point's direction (exact tests, independent of core's predicates).
class ConeCheck {
 public:
  ConeCheck(const ConvexPolyhedron& p, const CubemapLocator& cm) : p_(p), c_(*cm.centre()) {
    for (const Cell3D& cell : cm.cells())
      cells_[{cell.cubeFace, cell.level, cell.i, cell.j}] = cell.faces;
  }
  // false when the cell of x misses every face x's direction leaves through
  bool listed(const CubemapLocator& cm, Vec3 x) const {
    const Trace3D t = cm.trace(x);
    if (t.atCentre || t.fallback) return true;
    const auto it = cells_.find({t.cubeFace, t.level, t.cellI, t.cellJ});
    if (it == cells_.end()) return false;
    for (std::uint32_t f : it->second)
      if (inCone(f, x)) return true;
    return false;
  }

 private:
  // x - c lies in the closed cone from c of a triangle of plane face f
  bool inCone(std::uint32_t f, Vec3 x) const {
    auto v = p_.vertices();
    for (std::uint32_t tri : p_.planeTriangles(f)) {
      const auto& t = p_.triangles()[tri];
      const int orientation = reftest::orient(v[t[0]], v[t[1]], v[t[2]], c_);  // > 0: c inside
      bool inside = true;
      for (int k = 0; k < 3; ++k)
        inside &= orientation * reftest::orient(c_, v[t[k]], v[t[(k + 1) % 3]], x) <= 0;
      if (inside) return true;
    }
    return false;
  }
  const ConvexPolyhedron& p_;
  Vec3 c_;
  std::map<std::tuple<int, int, std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> cells_;
};

}  // namespace

TEST(Cubemap3D, MemoryStaysWithin128BytesPerFace) {
  expectWithinBudget(ConvexPolyhedron(generatePolyhedron(PolyhedronKind::TinyFaces, 100000, 1)),
                     "tiny-faces");
  expectWithinBudget(ConvexPolyhedron(generatePolyhedron(PolyhedronKind::Geodesic, 100000, 1)),
                     "geodesic");
  expectWithinBudget(ConvexPolyhedron(generatePolyhedron(PolyhedronKind::ThinSlab, 20000, 1)),
                     "thin-slab");
  expectWithinBudget(ConvexPolyhedron(spindle(20000)), "spindle");
  expectWithinBudget(ConvexPolyhedron(generatePolyhedron(PolyhedronKind::Cylinder, 65536, 1)),
                     "cylinder");
  expectWithinBudget(ConvexPolyhedron(generatePolyhedron(PolyhedronKind::Prism, 40000, 1)),
                     "prism");
  // a resolution far too fine for the shape is coarsened to fit
  const ConvexPolyhedron tetra(generatePolyhedron(PolyhedronKind::Tetrahedron, 4, 1));
  const CubemapLocator fine(tetra, 8192);
  EXPECT_LT(fine.resolution(), 8192u);
  EXPECT_LE(fine.stats().bytes, 128 * 4 + 65536);
}

TEST(Cubemap3D, SpindleStaysExact) {
  const ConvexPolyhedron p(spindle(1000));
  const reftest::Reference ref(p);
  const CubemapLocator cm(p);
  Rng rng(5);
  std::vector<Vec3> pts = generatePoints3D(p, 2000, 6, true);
  auto more = adversarial3d::cubemapPoints(p, cm, rng);
  pts.insert(pts.end(), more.begin(), more.end());
  for (Vec3 q : pts) ASSERT_EQ(cm.locate(q), ref.locate(q)) << q.x << ' ' << q.y << ' ' << q.z;
}

TEST(Cubemap3D, EveryDirectionFindsItsExitFaceInItsCell) {
  for (auto [kind, n, g] : {std::tuple{PolyhedronKind::Geodesic, std::size_t{1280}, 0u},
                            std::tuple{PolyhedronKind::Geodesic, std::size_t{1280}, 1u},
                            std::tuple{PolyhedronKind::TinyFaces, std::size_t{2000}, 0u},
                            std::tuple{PolyhedronKind::Icosahedron, std::size_t{20}, 7u},
                            std::tuple{PolyhedronKind::ThinSlab, std::size_t{400}, 0u},
                            std::tuple{PolyhedronKind::Offset, std::size_t{500}, 0u},
                            std::tuple{PolyhedronKind::Cylinder, std::size_t{4000}, 0u},
                            std::tuple{PolyhedronKind::Prism, std::size_t{4000}, 0u}}) {
    SCOPED_TRACE(std::string(toString(kind)) + " G " + std::to_string(g));
    const ConvexPolyhedron p(generatePolyhedron(kind, n, 2));
    const CubemapLocator cm(p, g);
    const ConeCheck check(p, cm);
    const Vec3 c = *cm.centre();
    Rng rng(8);
    std::size_t missed = 0;
    // random directions, at random distances (inside and outside)
    for (int i = 0; i < 20000; ++i) {
      const double z = rng.uniform(-1, 1), a = rng.uniform(0, 6.283185307179586);
      const double r = std::sqrt(1 - z * z),
                   scale = std::ldexp(rng.uniform(), static_cast<int>(rng.below(8)) - 6);
      const Vec3 x{c.x + scale * r * std::cos(a), c.y + scale * r * std::sin(a), c.z + scale * z};
      missed += !check.listed(cm, x);
    }
    // the adversarial set: cell borders, cube edges and diagonals, with their ulp neighbours
    for (Vec3 x : adversarial3d::cubemapPoints(p, cm, rng)) missed += !check.listed(cm, x);
    EXPECT_EQ(missed, 0u);
  }
}

TEST(Cubemap3D, RadiusDecisionsAreSound) {
  // Inside by the inner radius must mean: on the inner side of every face the cell lists;
  // Outside by the outer radius: on the outer side of one of them (the ray leaves through a
  // listed face before p). Checked exactly on random and adversarial points, independently
  // of how core bounds the radii.
  for (auto [kind, n] : {std::pair{PolyhedronKind::Geodesic, std::size_t{1280}},
                         std::pair{PolyhedronKind::Cube, std::size_t{12}},
                         std::pair{PolyhedronKind::TinyFaces, std::size_t{2000}},
                         std::pair{PolyhedronKind::ThinSlab, std::size_t{400}},
                         std::pair{PolyhedronKind::Offset, std::size_t{500}}}) {
    SCOPED_TRACE(std::string(toString(kind)));
    const ConvexPolyhedron p(generatePolyhedron(kind, n, 3));
    const CubemapLocator cm(p);
    std::map<std::tuple<int, int, std::uint32_t, std::uint32_t>, std::vector<std::uint32_t>> lists;
    for (const Cell3D& cell : cm.cells())
      lists[{cell.cubeFace, cell.level, cell.i, cell.j}] = cell.faces;
    Rng rng(12);
    std::vector<Vec3> pts = generatePoints3D(p, 4000, 13, true);
    auto more = adversarial3d::cubemapPoints(p, cm, rng);
    pts.insert(pts.end(), more.begin(), more.end());
    auto v = p.vertices();
    std::size_t inner = 0, outer = 0;
    for (Vec3 x : pts) {
      const Trace3D t = cm.trace(x);
      if (!t.byRadius) continue;
      const std::string at =
          std::to_string(x.x) + " " + std::to_string(x.y) + " " + std::to_string(x.z);
      EXPECT_TRUE(t.faces.empty()) << at;
      const auto it = lists.find({t.cubeFace, t.level, t.cellI, t.cellJ});
      ASSERT_NE(it, lists.end()) << at;
      int lowest = 1;
      for (std::uint32_t f : it->second) {
        const auto& tri = p.planes()[f];
        const int side = reftest::orient(v[tri[0]], v[tri[1]], v[tri[2]], x);
        if (t.result == Location::Inside) {
          EXPECT_GT(side, 0) << at << " face " << f;
        }
        lowest = std::min(lowest, side);
      }
      if (t.result == Location::Outside) {
        EXPECT_LT(lowest, 0) << at;
      } else {
        ASSERT_EQ(t.result, Location::Inside) << at;
      }
      (t.result == Location::Inside ? inner : outer) += 1;
    }
    EXPECT_GT(inner, 0u);
    EXPECT_GT(outer, 0u);
  }
}

TEST(Cubemap3D, StatsAndCellsAgree) {
  const ConvexPolyhedron p(generatePolyhedron(PolyhedronKind::TinyFaces, 3000, 4));
  const CubemapLocator cm(p);
  const Stats3D s = cm.stats();
  const std::vector<Cell3D> cells = cm.cells();
  EXPECT_EQ(s.faces, p.planeCount());
  EXPECT_EQ(s.triangles, p.faceCount());
  EXPECT_EQ(s.vertices, p.vertexCount());
  EXPECT_TRUE(s.centred);
  EXPECT_EQ(s.resolution, cm.resolution());
  EXPECT_EQ(cells.size(), s.cells);
  EXPECT_GT(s.maxLevel, 0);  // the tiny cap forces refinement
  std::size_t entries = 0, most = 0, crowded = 0, histogram = 0;
  for (std::size_t k : s.histogram) histogram += k;
  EXPECT_EQ(histogram, s.cells);
  const Vec3 c = *cm.centre();
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const Cell3D& cell = cells[i];
    EXPECT_EQ(cell.index, i);
    entries += cell.faces.size();
    most = std::max(most, cell.faces.size());
    crowded += cell.faces.size() > kCrowdedCell3D;
    ASSERT_GE(cell.cubeFace, 0);
    ASSERT_LT(cell.cubeFace, 6);
    EXPECT_LT(cell.s0, cell.s1);
    EXPECT_LT(cell.t0, cell.t1);
    EXPECT_EQ(cell.apex, c);
    for (const Vec3& k : cell.corners) {
      const double d = std::max({std::fabs(k.x - c.x), std::fabs(k.y - c.y), std::fabs(k.z - c.z)});
      EXPECT_NEAR(d, cm.cubeHalfSize(), 1e-9 * cm.cubeHalfSize());
    }
  }
  EXPECT_EQ(entries, s.entries);
  EXPECT_EQ(most, s.maxPerCell);
  EXPECT_EQ(crowded, s.crowdedCells);
  EXPECT_NEAR(s.meanPerCell, static_cast<double>(entries) / cells.size(), 1e-9);
  EXPECT_GT(s.bytes, 0u);
  EXPECT_GE(s.buildSeconds, 0.0);
  // the base grid covers each cube face once: level-0 areas plus refined areas add to 4 * 6
  double area = 0;
  for (const Cell3D& cell : cells) area += (cell.s1 - cell.s0) * (cell.t1 - cell.t0);
  EXPECT_NEAR(area, 24.0, 1e-9);
}

TEST(Cubemap3D, DefaultAndChosenResolution) {
  const ConvexPolyhedron p(generatePolyhedron(PolyhedronKind::Geodesic, 5120, 1));
  EXPECT_EQ(CubemapLocator(p).resolution(), 36u);  // round(sqrt(5120 / 4))
  const ConvexPolyhedron large(generatePolyhedron(PolyhedronKind::Geodesic, 300000, 1));
  // past G = 160: about 8 faces per base cell
  EXPECT_EQ(CubemapLocator(large).resolution(),
            static_cast<std::uint32_t>(std::lround(std::sqrt(large.faceCount() / 8.0))));
  EXPECT_GT(CubemapLocator(large).resolution(), 160u);
  const ConvexPolyhedron small(generatePolyhedron(PolyhedronKind::Icosahedron, 20, 1));
  // the smallest default, 16, halved to fit the constant budget with every node's slab
  EXPECT_EQ(CubemapLocator(small).resolution(), 8u);
  EXPECT_EQ(CubemapLocator(p, 5).resolution(), 5u);
  EXPECT_EQ(Locator3D(p, Method3D::Cubemap, 5).stats().resolution, 5u);
}

TEST(Trace3D, CubemapTellsFaceCellAndTests) {
  const ConvexPolyhedron p(shapes3d::cube());
  const CubemapLocator cm(p);
  const Vec3 c = *cm.centre();
  const Trace3D out = cm.trace({c.x + 5, c.y + 1, c.z - 2});
  EXPECT_EQ(out.method, Method3D::Cubemap);
  EXPECT_EQ(out.result, Location::Outside);
  EXPECT_EQ(out.cubeFace, 0);  // +x
  EXPECT_DOUBLE_EQ(out.s, 1.0 / 5);
  EXPECT_DOUBLE_EQ(out.t, -2.0 / 5);
  EXPECT_GE(out.level, 0);
  // far beyond every corner: the cell's outer radius decides, no face is tested
  EXPECT_TRUE(out.byRadius);
  EXPECT_GT(out.distance, out.outerRadius);
  EXPECT_TRUE(out.faces.empty());
  // nearer than every face the cell sees: the inner radius decides
  const Trace3D neg = cm.trace({c.x, c.y, c.z - 0.5});
  EXPECT_EQ(neg.cubeFace, 5);  // -z
  EXPECT_EQ(neg.result, Location::Inside);
  EXPECT_TRUE(neg.byRadius);
  EXPECT_LT(neg.distance, neg.innerRadius);
  // just short of the surface and just past it along one ray, between the radii of its
  // cell (the nearest and farthest points of the face's part the cell sees): the cell's
  // slab decides (its one face's plane, up to rounding), no face is tested
  const Trace3D in = cm.trace({c.x + 0.99999, c.y + 0.499995, c.z + 0.099999});
  EXPECT_FALSE(in.byRadius);
  EXPECT_TRUE(in.bySlab);
  EXPECT_EQ(in.result, Location::Inside);
  EXPECT_TRUE(in.faces.empty());
  const Trace3D beyond = cm.trace({c.x + 1.00001, c.y + 0.500005, c.z + 0.100001});
  EXPECT_FALSE(beyond.byRadius);
  EXPECT_TRUE(beyond.bySlab);
  EXPECT_EQ(beyond.result, Location::Outside);
  // without the radii and slabs, the paper's query: plane tests decide
  const Trace3D plain = cm.trace({c.x + 1.00001, c.y + 0.500005, c.z + 0.100001}, {.radii = false});
  EXPECT_FALSE(plain.bySlab);
  ASSERT_FALSE(plain.faces.empty());
  EXPECT_EQ(plain.faces.back().sign, -1);
  // on the surface: neither radii nor slab decide, a plane test gives 0
  const Trace3D on = cm.trace({c.x + 1, c.y + 0.5, c.z + 0.1});
  EXPECT_FALSE(on.byRadius || on.bySlab);
  EXPECT_EQ(on.result, Location::Boundary);
  ASSERT_FALSE(on.faces.empty());
  const Trace3D at = cm.trace(c);
  EXPECT_TRUE(at.atCentre);
  EXPECT_EQ(at.result, Location::Inside);
  EXPECT_EQ(cm.trace({1, 0.25, 0.5}).result, Location::Boundary);
}

TEST(Trace3D, WalkRecordsItsPath) {
  const ConvexPolyhedron p(generatePolyhedron(PolyhedronKind::Geodesic, 5120, 1));
  const WalkLocator walk(p);
  Rng rng(2);
  double steps = 0;
  const int n = 2000;
  for (int i = 0; i < n; ++i) {
    const Vec3 q{rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2), rng.uniform(-1.2, 1.2)};
    const Trace3D t = walk.trace(q);
    ASSERT_FALSE(t.path.empty());
    ASSERT_FALSE(t.fallback);
    ASSERT_EQ(t.faces.size(), 1u);
    EXPECT_EQ(t.faces[0].face, t.path.back());
    for (std::size_t k = 0; k + 1 < t.steps.size(); ++k)
      if (t.steps[k].sign > 0) {
        EXPECT_NE(t.steps[k].face, t.steps[k + 1].face);
      }
    steps += static_cast<double>(t.path.size());
  }
  // jump and walk: far fewer faces than sqrt(F) on average
  EXPECT_LT(steps / n, std::sqrt(5120.0));
  std::printf("[ info     ] walk: %.1f faces visited per query on %zu faces\n", steps / n,
              p.faceCount());
}

TEST(Trace3D, HalfspaceTestsUntilTheFirstOuterSide) {
  const ConvexPolyhedron p(generatePolyhedron(PolyhedronKind::Icosahedron, 20, 1));
  const HalfspaceLocator h(p);
  const Trace3D in = h.trace({0, 0, 0});
  EXPECT_EQ(in.faces.size(), 20u);
  EXPECT_EQ(in.result, Location::Inside);
  const Trace3D out = h.trace({0, 0, 5});
  EXPECT_EQ(out.faces.back().sign, -1);
  EXPECT_EQ(out.result, Location::Outside);
  EXPECT_EQ(h.stats().cells, 0u);
  EXPECT_TRUE(h.cells().empty());
}

// A point whose squared distance from the centre, as the locator computes it, equals its
// cell's outer bound exactly is not beyond that bound: the radii must leave it to the face
// tests (a '>=' in their comparison would call it inside). Found by stepping a coordinate
// ulp by ulp across the bound's sphere; checked one point per call, traced, and in a batch
// (the AVX2 stage where the CPU has it) against the exact reference.
TEST(Cubemap3D, ExactlyOnTheOuterBoundGoesToTheFaceTests) {
  for (auto [kind, n] : {std::pair{PolyhedronKind::Geodesic, std::size_t{80}},
                         std::pair{PolyhedronKind::Cube, std::size_t{12}},
                         std::pair{PolyhedronKind::Geodesic, std::size_t{1280}}}) {
    SCOPED_TRACE(std::string(toString(kind)) + " " + std::to_string(n));
    const ConvexPolyhedron p(generatePolyhedron(kind, n, 3));
    const CubemapLocator cm(p);
    ASSERT_TRUE(cm.centre().has_value());
    const Vec3 c = *cm.centre();
    const auto v = p.vertices();
    auto reference = [&](Vec3 q) {
      bool zero = false;
      for (const auto& t : p.triangles()) {
        const int s = reftest::orient(v[t[0]], v[t[1]], v[t[2]], q);
        if (s < 0) return Location::Outside;
        zero |= s == 0;
      }
      return zero ? Location::Boundary : Location::Inside;
    };
    Rng rng(5);
    std::vector<Vec3> found;
    for (int trial = 0; trial < 20000 && found.size() < 64; ++trial) {
      const Vec3 u{rng.uniform(-1, 1), rng.uniform(-1, 1), rng.uniform(-1, 1)};
      const double len = std::sqrt(u.x * u.x + u.y * u.y + u.z * u.z);
      if (!(len > 0.1)) continue;
      const Trace3D seed = cm.trace({c.x + u.x, c.y + u.y, c.z + u.z});
      if (seed.level < 0 || !(seed.outerRadius > 0)) continue;
      // the stored bound (a float): the trace shows its square root
      const float out2 = static_cast<float>(seed.outerRadius * seed.outerRadius);
      ASSERT_EQ(std::sqrt(static_cast<double>(out2)), seed.outerRadius);
      const double k = seed.outerRadius / len;
      Vec3 q{c.x + u.x * k, c.y + u.y * k, c.z + u.z * k};
      const double outward = u.x > 0 ? HUGE_VAL : -HUGE_VAL;
      for (int step = 0; step < 64; ++step) {
        const double dx = q.x - c.x, dy = q.y - c.y, dz = q.z - c.z;
        const double d2 = dx * dx + dy * dy + dz * dz;  // as the locator computes it
        if (d2 == static_cast<double>(out2)) {
          const Trace3D t = cm.trace(q);
          if (t.cubeFace == seed.cubeFace && t.level == seed.level && t.cellI == seed.cellI &&
              t.cellJ == seed.cellJ) {
            EXPECT_FALSE(t.byRadius);
            EXPECT_EQ(t.result, reference(q));
            EXPECT_EQ(cm.locate(q), t.result);
            found.push_back(q);
          }
          break;
        }
        q.x = std::nextafter(q.x, d2 < static_cast<double>(out2) ? outward : -outward);
      }
    }
    EXPECT_GE(found.size(), 16u);
    // the batch, with each point between two decided ones (4-point groups mix them)
    std::vector<Vec3> batch;
    for (Vec3 q : found) {
      batch.push_back(c);
      batch.push_back(q);
      batch.push_back({c.x + 100, c.y, c.z});
    }
    std::vector<Location> out(batch.size());
    cm.locate(batch, out);
    for (std::size_t i = 1; i < batch.size(); i += 3) EXPECT_EQ(out[i], reference(batch[i]));
  }
}
