// convexloc (internal) — the cube map's build, as a class whose steps are named member
// functions: choose G, aim from the centre, fit the base grid to the memory budget, fill the
// base cells, split crowded cells into quadtrees, flatten, then the radii (cubemap/radii.cpp).
// What makes the lists conservative: cubemap/index.hpp.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "convexloc/geometry.hpp"
#include "convexloc/locate3d.hpp"

namespace convexloc {

namespace cubemap {

// a convex polygon in (s, t) with at most 4 + 3 vertices
struct Poly {
  Vec2 p[8];
  int n = 0;
};

// a face's cone from the centre: edge-plane normals with their error bounds, and the vertex
// directions (all scaled by a power of two)
struct Cone {
  double n[3][3];
  double bound[3];
  double d[3][3];
};

// exact scaling by a power of two: x * 2^shift
struct PowerOfTwo {
  int shift = 0;
  double factor = 1.0;  // 2^shift, when that is a normal double
  explicit PowerOfTwo(int s) : shift(s), factor(s > -1000 && s < 1000 ? std::ldexp(1.0, s) : 0.0) {}
  double operator()(double x) const { return factor != 0.0 ? x * factor : std::ldexp(x, shift); }
};

// the deepest quadtree level
inline constexpr int kMaxLevel = 30;
// the fewest fan faces a leaf searches by bisection (cubemap/sectors.cpp): fewer are split
// or walked
inline constexpr std::uint32_t kFanLeaf = 32;
// the largest G accepted
inline constexpr std::uint32_t kMaxResolution = 8192;

// the deepest level for base resolution g: at most 2^31 cells per side
int depthFor(std::uint32_t g);
// the half-size of the cube around c that holds the vertices: their largest coordinate
// difference from c
double cubeExtent(std::span<const Vec3> vertices, Vec3 c);

}  // namespace cubemap

// Builds a CubemapLocator in place; one use.
class CubemapBuilder {
 public:
  // copies the surface and chooses G; throws UsageError for a resolution above the largest
  CubemapBuilder(CubemapLocator& locator, const ConvexPolyhedron& polyhedron,
                 std::uint32_t resolution);
  // runs every step; without a usable centre the locator gets no cells (G = 0)
  void build();

 private:
  using Node = CubemapLocator::Node;
  // what a node costs: itself and its slab
  static constexpr std::size_t kNodeBytes = sizeof(Node) + sizeof(CubemapLocator::Slab);
  // a cell waiting to be split: its node, place and level, its faces and when it was queued
  struct Pending {
    std::uint32_t node;
    std::uint32_t i, j;
    std::uint8_t face, level;
    std::uint32_t faces = 0;
    std::uint64_t order = 0;
  };
  // the heap order of the refinement: the cell listing more faces first, then the earlier
  static bool morePressing(const Pending& a, const Pending& b) {
    return a.faces != b.faces ? a.faces < b.faces : a.order > b.order;
  }

  // === base grid (build.cpp)
  // the default G for `faces` faces
  static std::uint32_t defaultResolution(std::size_t faces);
  // the default G for `faces` plane faces made of `triangles` triangles
  static std::uint32_t defaultResolution(std::size_t faces, std::size_t triangles);
  // the centre and the cube around it that holds the polyhedron; false when there is none
  // or the directions from it overflow
  bool aimFromCentre();
  // the base grid, coarsened to fit, and its lists (zone ranges where crowded cells lie
  // over a zone); false when a direction overflows
  bool buildBaseGrid();
  // the bytes the nodes, the entries and the zone ranges use
  std::size_t liveBytes() const;
  // what the cells may use: 120 bytes per triangle and kFixedBudget in all, less the surface
  std::size_t memoryBudget() const;
  // visit(face, cube face, polygon) for every cube face each triangle's cone meets, plane
  // face by plane face (face: the triangle's plane face); false when a direction overflows
  template <class Visit>
  bool forEachProjection(Visit&& visit) const;
  // coarsens G until the base grid fits the budget; counts[c]: faces of base cell c
  bool fitBaseGrid(std::vector<std::uint32_t>& counts);
  // lists each base cell's faces, in CSR form
  void fillBaseCells(const std::vector<std::uint32_t>& counts);

  // === quadtree (build.cpp)
  // splits crowded cells, the most crowded first, while the budget allows
  void refineCrowdedCells();
  // queues the crowded base cells, and the fan leaves with other faces (where the fan's
  // surface meets another, which neither radii nor a slab bound tightly); a split fan leaf's
  // children list all their faces until encodeSectors
  void queueCrowdedBaseCells();
  // queues a crowded cell (its node holds its list)
  void queue(Pending q);
  // a leaf's faces: its list, or a fan leaf's expanded (fanLeafFaces, into expanded_)
  std::span<const std::uint32_t> parentFaces(const Node& nd);
  // sorts the triangles of the parent's faces into the small ones (placed by their projected
  // boxes) and the others (by their cones' polygons)
  void sortFaces(const Pending& q, std::span<const std::uint32_t> faces);
  // how many levels the split goes down at once: more than 1 where every small face stays in
  // one cell (a chain)
  int chainLevels(const Pending& q) const;
  // narrows [i0, i1] x [j0, j1] to the cells at scale K that the small faces' boxes meet
  void smallFacesCells(double K, std::int64_t& i0, std::int64_t& i1, std::int64_t& j0,
                       std::int64_t& j1) const;
  // fills the children's lists, level by level down the chain; returns how many entries
  std::size_t listChildren(const Pending& q, int levels);
  // a split where one child keeps every face while the others share many gains nothing
  bool splitIsFutile(std::size_t parent, std::size_t added) const;
  // appends the children down the chain, top down
  void commitChildren(const Pending& q, int levels);
  // appends the 4 children of `node` (whose children start at cell i0, j0 of `level`) with
  // their lists; queues the crowded ones; returns the index of the first
  std::uint32_t addChildren(std::uint32_t node, std::int64_t i0, std::int64_t j0, std::uint8_t face,
                            int level, std::vector<std::uint32_t> (&lists)[4]);
  // rewrites the entries with the leaves' lists only
  void compactEntries();

  // === zones (zones.cpp)
  using ZoneRange = CubemapLocator::ZoneRange;
  // the zones of thin faces (zoneOf_, positionOf_ and the locator's zone tables)
  void findZones();
  // rewrites each crowded leaf over a zone as a range of it (bisection); repacks the entries
  void encodeZones();
  // the entries a leaf's count stands for
  static std::uint32_t entryCount(std::uint32_t count);
  // the zone most of `list` lies in, the range of it holding them, and the other faces;
  // false when no zone holds more than a crowded cell's worth
  bool rangeOf(const std::uint32_t* list, std::uint32_t count,
               const std::vector<std::uint32_t>& zoneOf,
               const std::vector<std::uint32_t>& positionOf, ZoneRange& r,
               std::vector<std::uint32_t>& others) const;
  // whether the cell's directions and the range's edges lie within a quarter turn around
  // the zone's axis (then bisection over the range is exact)
  bool zoneFits(const ZoneRange& r, int cf, int level, std::uint64_t i, std::uint64_t j) const;

  // === sectors (sectors.cpp)
  // the fans of thin faces around an axis (fanOf_, fanFrom_, fanTo_ and the locator's tables)
  void findFans();
  // sorts `faces` (strictly on the sigma side of the plane through c, q and r) into a fan by
  // their first corners around the axis through c and q, with each place's window; faces
  // whose angles span too many keys stay out of it
  void addFan(std::vector<std::uint32_t>& faces, Vec3 q, Vec3 r, int sigma);
  // rewrites each crowded leaf that no zone holds and that lies over a fan as a range of it
  // with its other faces; repacks the entries
  void encodeSectors();
  // a fan leaf's faces for its radii: its others and the fan faces its places need
  void fanLeafFaces(const Node& nd, std::vector<std::uint32_t>& faces) const;

  // === radii (radii.cpp)
  // each leaf's two radii and its slab; inner nodes get NaN radii and a disabled slab
  void setLeafRadii();

  // === slabs (slabs.cpp)
  // the slab of leaf `node`, cell (i, j) at `level` of cube face `cf`, listing `faces` (after
  // its radii, whose outer bound its rounding margin rests on); left disabled where no bound
  // is sure
  void setLeafSlab(std::uint32_t node, int cf, int level, std::uint64_t i, std::uint64_t j,
                   std::span<const std::uint32_t> faces);
  // the slab direction of that cell: the unit normal of the face its middle ray leaves by
  // (among a spread sample of `faces`), as floats; false when none is found
  bool slabNormal(std::span<const std::uint32_t> faces, int cf, int level, std::uint64_t i,
                  std::uint64_t j, float (&n)[3]) const;

  CubemapLocator& locator_;
  const ConvexPolyhedron& polyhedron_;  // for the build only: its plane faces' triangles
  std::optional<Vec3> centre_;          // the polyhedron's
  cubemap::PowerOfTwo scale_{0};        // brings the cube's half-size into [1, 2)
  std::size_t budget_ = 0;              // bytes the cells may use
  // the refinement's state
  std::vector<Pending> queue_;  // a heap by morePressing
  std::uint64_t queued_ = 0;
  std::size_t live_ = 0;         // bytes the nodes and the leaves' entries use
  std::size_t liveEntries_ = 0;  // entries the leaves list
  std::vector<std::uint32_t> small_, large_, expanded_;
  std::vector<std::array<double, 4>> smallBoxes_;  // (s0, s1, t0, t1)
  std::array<double, 4> smallBounds_{};            // the box around all of them
  std::vector<cubemap::Poly> largePolys_;
  std::vector<std::uint32_t> zoneOf_, positionOf_;  // each face's zone and place in it
  // each face's fan, and the places whose windows hold it
  std::vector<std::uint32_t> fanOf_, fanFrom_, fanTo_;
  std::vector<std::uint32_t> lists_[cubemap::kMaxLevel + 1][4];
};

}  // namespace convexloc
