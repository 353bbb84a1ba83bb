// The cube map's tables (CubemapLocator::tables()) and a locator loaded from them: the same
// answers as the built one on random and hard points (vertices, points on faces and edges
// and their ulp neighbours, cell borders, the centre), for round and crowded shapes (zones
// and fans among them); the loaded locator reports it was loaded and the build's time; a
// damaged table (an index out of range, a truncated array, a cycle, a centre outside, another
// version) is refused with a ParseError naming the problem.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "../bench/cad_family.hpp"
#include "adversarial3d.hpp"
#include "convexloc/error.hpp"
#include "convexloc/generate3d.hpp"
#include "convexloc/locate3d.hpp"

using namespace convexloc;

namespace {

// a node's count marks (core/src/cubemap/index.hpp): an inner node, and the lowest flag bit
// of a zone or sector leaf
constexpr std::uint32_t kInner = 0xffffffffu, kFlagged = 0x40000000u;

ConvexPolyhedron generated(PolyhedronKind kind, std::size_t n, std::uint64_t seed = 1) {
  return ConvexPolyhedron(generatePolyhedron(kind, n, seed));
}

// random points, hard ones near the surface, and the cube map's own (cell borders, rays
// from the centre, the centre with its ulp neighbours), and every vertex
std::vector<Vec3> probePoints(const ConvexPolyhedron& p, const CubemapLocator& cm) {
  Rng rng(7);
  std::vector<Vec3> pts = generatePoints3D(p, 3000, 3, false);
  for (const auto& more :
       {generatePoints3D(p, 2000, 4, true), adversarial3d::surfacePoints(p, 400, rng),
        adversarial3d::cubemapPoints(p, cm, rng)})
    pts.insert(pts.end(), more.begin(), more.end());
  pts.insert(pts.end(), p.vertices().begin(), p.vertices().end());
  return pts;
}

// the loaded locator answers as the built one does, point by point and in a batch
void expectSameAnswers(const ConvexPolyhedron& p, const CubemapLocator& built,
                       const CubemapLocator& loaded) {
  const std::vector<Vec3> pts = probePoints(p, built);
  std::vector<Location> a(pts.size()), b(pts.size());
  built.locate(pts, a);
  loaded.locate(pts, b);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < pts.size(); ++i)
    differ += a[i] != b[i] || loaded.locate(pts[i]) != a[i] ||
              (i % 11 == 0 && loaded.trace(pts[i], TraceOptions{.radii = false}).result != a[i]);
  EXPECT_EQ(differ, 0u);
  EXPECT_EQ(loaded.locate(*built.centre()), Location::Inside);
}

struct Shape {
  std::string name;
  std::function<ConvexPolyhedron()> make;
  bool zones = false, fans = false;  // the crowded leaves it must have
};

class CubemapTablesRoundTrip : public ::testing::TestWithParam<Shape> {};

TEST_P(CubemapTablesRoundTrip, LoadsTheSameLocatorWithoutBuilding) {
  const ConvexPolyhedron p = GetParam().make();
  const CubemapLocator built(p);
  const CubemapTables t = built.tables();
  const CubemapLocator loaded(p, t);
  EXPECT_FALSE(built.loaded());
  EXPECT_TRUE(loaded.loaded());
  const Stats3D s = built.stats(), l = loaded.stats();
  EXPECT_EQ(l.buildSeconds, s.buildSeconds);  // the build's time, carried: nothing was built
  EXPECT_EQ(l.cells, s.cells);
  EXPECT_EQ(l.nodes, s.nodes);
  EXPECT_EQ(l.entries, s.entries);
  EXPECT_EQ(l.maxLevel, s.maxLevel);
  EXPECT_LE(l.bytes, s.bytes);  // the same tables, without the build's spare capacity
  EXPECT_TRUE(!GetParam().zones || s.zoneCells > 0) << "no zone leaf to carry";
  EXPECT_TRUE(!GetParam().fans || s.sectorCells > 0) << "no fan leaf to carry";
  EXPECT_EQ(l.zoneCells, s.zoneCells);
  EXPECT_EQ(l.sectorCells, s.sectorCells);
  EXPECT_EQ(loaded.resolution(), built.resolution());
  EXPECT_EQ(loaded.cubeHalfSize(), built.cubeHalfSize());
  // the tables come back as they went
  const CubemapTables again = loaded.tables();
  EXPECT_EQ(again.nodes, t.nodes);
  EXPECT_EQ(again.entries, t.entries);
  EXPECT_EQ(again.zoneRanges, t.zoneRanges);
  EXPECT_EQ(again.sectorKeys, t.sectorKeys);
  EXPECT_EQ(again.sectorPoints, t.sectorPoints);
  EXPECT_EQ(again.slabs, t.slabs);
  EXPECT_EQ(t.slabs.size(), 5 * s.nodes);
  expectSameAnswers(p, built, loaded);
}

INSTANTIATE_TEST_SUITE_P(
    Shapes, CubemapTablesRoundTrip,
    ::testing::Values(
        Shape{"sphere", [] { return generated(PolyhedronKind::SphereHull, 3000); }},
        Shape{"coplanar", [] { return generated(PolyhedronKind::Coplanar, 600); }},
        Shape{"tiny_faces", [] { return generated(PolyhedronKind::TinyFaces, 2000); }},
        Shape{"cylinder", [] { return generated(PolyhedronKind::Cylinder, 4000); }, true},
        Shape{"tall_cad_cylinder",
              [] {
                return cadfamily::polyhedron({512, 10, false});
              },
              false, true}),
    [](const ::testing::TestParamInfo<Shape>& param) { return param.param.name; });

// === damaged tables

// loading `t` over `p` throws a ParseError whose text holds `expected`
void expectRefused(const ConvexPolyhedron& p, const CubemapTables& t, const std::string& expected) {
  try {
    CubemapLocator loaded(p, t);
    ADD_FAILURE() << "loaded; expected an error about: " << expected;
  } catch (const ParseError& e) {
    EXPECT_NE(std::string(e.what()).find(expected), std::string::npos) << e.what();
    EXPECT_EQ(std::string(e.what()).rfind("cube map tables: ", 0), 0u) << e.what();
  }
}

// the tables of a cube map with a quadtree (tiny faces crowd one corner), for damaging
class DamagedTables : public ::testing::Test {
 protected:
  const ConvexPolyhedron p = generated(PolyhedronKind::TinyFaces, 3000);
  const CubemapTables good = CubemapLocator(p).tables();

  void expectRefused(const CubemapTables& t, const std::string& expected) const {
    ::expectRefused(p, t, expected);
  }
  // the index of the first node that is a plain leaf listing something, and of an inner one
  std::size_t firstLeaf() const {
    for (std::size_t k = 0;; ++k)
      if (good.nodes[2 * k + 1] != kInner && good.nodes[2 * k + 1] > 0 &&
          good.nodes[2 * k + 1] < kFlagged)
        return k;
  }
  std::size_t firstInner() const {
    std::size_t k = 0;
    while (2 * k < good.nodes.size() && good.nodes[2 * k + 1] != kInner) ++k;
    return k;
  }
};

TEST_F(DamagedTables, TheUndamagedLoad) {
  EXPECT_NO_THROW(CubemapLocator(p, good));
  ASSERT_LT(2 * firstInner(), good.nodes.size());  // the cases below need an inner node
}

TEST_F(DamagedTables, AnotherVersion) {
  CubemapTables t = good;
  t.version = CubemapTables::kVersion + 1;
  expectRefused(t, "version");
}

TEST_F(DamagedTables, AnEntryOutOfRange) {
  CubemapTables t = good;
  t.entries[good.nodes[2 * firstLeaf()]] = static_cast<std::uint32_t>(p.planeCount());
  expectRefused(t, "lists face");
}

TEST_F(DamagedTables, MarksThatDoNotFit) {
  CubemapTables t = good;
  t.nodes[2 * firstLeaf() + 1] = 0x80000000u;  // a zone leaf naming no range
  expectRefused(t, "names no range");
  t.nodes[2 * firstLeaf() + 1] = 0xc0000001u;  // both zone and fan
  expectRefused(t, "both zone and fan");
  ASSERT_TRUE(good.zoneRanges.empty());
  t.nodes[2 * firstLeaf() + 1] = 0x80000001u;  // a zone leaf, where there are no zones
  expectRefused(t, "names range");
}

TEST_F(DamagedTables, ALeafsEntriesPastTheEnd) {
  CubemapTables t = good;
  t.nodes[2 * firstLeaf()] = static_cast<std::uint32_t>(good.entries.size());
  expectRefused(t, "run past");
}

TEST_F(DamagedTables, TruncatedArrays) {
  CubemapTables t = good;
  t.radii.pop_back();
  expectRefused(t, "radii holds");
  t = good;
  t.nodes.resize(t.nodes.size() - 2);
  expectRefused(t, "radii holds");
  t = good;
  t.nodes.resize(t.nodes.size() - 8), t.radii.resize(t.radii.size() - 8);  // a block short
  expectRefused(t, "block of nodes");
  t = good;
  t.entries.resize(t.entries.size() / 2);
  expectRefused(t, "entries");
}

TEST_F(DamagedTables, ChildrenOutOfOrderOrShared) {
  CubemapTables t = good;
  const std::size_t inner = firstInner();
  t.nodes[2 * inner] += 1;  // not a block boundary
  expectRefused(t, "not a block");
  // a node whose children include itself: a cycle, refused before any query could loop
  t = good;
  const std::uint32_t child = good.nodes[2 * inner];
  t.nodes[2 * child] = child;
  t.nodes[2 * child + 1] = kInner;
  t.radii[2 * child] = t.radii[2 * child + 1] = std::nanf("");
  expectRefused(t, "children");
}

TEST(DamagedZoneTables, ARangeOutOfItsZoneOrAZoneOutOfItsEdges) {
  const ConvexPolyhedron p = generated(PolyhedronKind::Cylinder, 4000);
  const CubemapTables good = CubemapLocator(p).tables();
  ASSERT_FALSE(good.zoneRanges.empty());
  CubemapTables t = good;
  t.zoneRanges[2] = t.zones[3 * t.zoneRanges[0] + 1] + 1;  // span past the zone's size
  expectRefused(p, t, "zone range 0");
  t = good;
  t.zones[1] = static_cast<std::uint32_t>(t.zoneFaces.size()) + 1;
  expectRefused(p, t, "zone 0");
  t = good;
  t.zoneEdges[0] = static_cast<std::uint32_t>(p.vertices().size());
  expectRefused(p, t, "zone_edges[0]");
  t = good;
  t.zoneFaces.pop_back();  // truncated
  expectRefused(p, t, "zone_faces");
}

TEST(DamagedFanTables, AKeyOrARangeOutOfItsFan) {
  const ConvexPolyhedron p = cadfamily::polyhedron({512, 10, false});
  const CubemapTables good = CubemapLocator(p).tables();
  ASSERT_FALSE(good.sectorRanges.empty());
  CubemapTables t = good;
  t.sectorRanges[2] = t.sectors[4 * t.sectorRanges[0] + 2] + 1;  // past the fan's keys
  expectRefused(p, t, "sector range 0");
  t = good;
  t.sectorKeys[0] |= 1u << 27;  // the first key's window reaching before the fan
  expectRefused(p, t, "reaches before");
  t = good;
  t.sectorPoints[0] = std::nan("");
  expectRefused(p, t, "non-finite");
}

TEST_F(DamagedTables, TheCentreOutsideOrTheGridWrong) {
  CubemapTables t = good;
  t.centre = p.vertices()[0];  // on the surface: not strictly inside
  expectRefused(t, "strictly inside");
  t.centre = {std::nan(""), 0, 0};
  expectRefused(t, "not finite");
  t = good;
  t.resolution = 8193;
  expectRefused(t, "resolution");
  t.resolution = good.resolution + 1;  // the base cells no longer match the nodes
  expectRefused(t, "base cells");
  t = good;
  t.resolution = 0;
  expectRefused(t, "yet there are tables");
}

TEST_F(DamagedTables, RadiiThatAreNotNumbersOrAtAnInnerNode) {
  CubemapTables t = good;
  t.radii[2 * firstLeaf()] = std::nanf("");
  expectRefused(t, "radii");
  t = good;
  t.radii[2 * firstInner()] = 1.0f;
  expectRefused(t, "inner but has radii");
}

}  // namespace
