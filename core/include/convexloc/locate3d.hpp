// convexloc — point location in a convex polyhedron: halfspace, walk and the paper's cube map.
//
// Every locator answers exactly (see Location) and shares the 2D interface:
//   locate(p)            one point
//   locate(points, out)  a batch; allocates nothing per point
//   trace(p)             the steps taken: cube face and cell, walk path, plane tests, result
//   stats()              size and shape of the subdivision
//   cells()              the subdivision as drawable geometry, with the faces each cell holds
// "Face" below means a plane face of ConvexPolyhedron::planes() (adjacent coplanar triangles
// merged; where none are coplanar, face t is triangle t); a walk crosses triangles. A locator keeps
// its own copy of what it needs; the polyhedron may go away after the build. A point with an
// infinite or NaN coordinate is reported Outside.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>
#include <string_view>
#include <variant>
#include <vector>

#include "convexloc/detail/locator_variant.hpp"
#include "convexloc/detail/sink_queries.hpp"
#include "convexloc/geometry.hpp"
#include "convexloc/methods.hpp"
#include "convexloc/polyhedron.hpp"
#include "convexloc/table.hpp"

namespace convexloc {

// === Common result types

// one plane test: sign of orient3d(a, b, c, p) for face (a, b, c); > 0 is the inner side
struct FaceTest {
  std::uint32_t face = 0;
  int sign = 0;
};

// one walk test at `face`: sign of orient3d(centre, a, b, p) for its edge `edge` from corner
// edge to corner edge + 1; > 0 means p's direction lies beyond that edge and the walk crosses
struct WalkTest {
  std::uint32_t face = 0;
  std::uint8_t edge = 0;
  int sign = 0;
};

// one bisection step in a zone: sign of orient3d(centre, a, b, p) for the zone's edge k from
// vertex a to b; the sign of the zone's faces before that edge means p's direction lies before it
struct ZoneTest {
  std::uint32_t edge = 0;
  std::uint32_t a = 0, b = 0;
  int sign = 0;
};

// one bisection step in a sector leaf: sign of orient3d(centre, q, v, p) for the leaf's
// sorted face k, whose corner v is its key and q a second point of the leaf's axis; the
// leaf's sign means p's direction lies past v around the axis
struct SectorTest {
  std::uint32_t index = 0;
  std::uint32_t vertex = 0;
  int sign = 0;
};

// What one query did, step by step.
struct Trace3D {
  Method3D method = Method3D::Halfspace;
  Location result = Location::Outside;
  bool nonFinite = false;      // the point has an infinite or NaN coordinate
  bool atCentre = false;       // the point is the centre itself
  bool fallback = false;       // answered by testing every face (no centre, overflow, walk cap)
  bool crowded = false;        // cubemap: the cell held many faces: searched by a walk, or by
                               // bisection over a zone (zoneSteps) or around an axis
                               // (sectorSteps)
  bool byRadius = false;       // cubemap: decided by the cell's radii, before any face test
  bool bySlab = false;         // cubemap: decided by the cell's slab, after its radii
  double distance = 0.0;       // cubemap: |p - centre| (approximate, for display)
  double innerRadius = 0.0;    // cubemap: nearer than this to the centre, a point of the cell
  double outerRadius = 0.0;    //   is inside; farther than outerRadius, outside
  std::optional<Vec3> centre;  // walk, cubemap: the centre strictly inside
  int cubeFace = -1;           // cubemap: 0..5 for +x, -x, +y, -y, +z, -z
  int level = -1;              // cubemap: quadtree level of the cell (0: the base grid)
  std::uint32_t cellI = 0, cellJ = 0;  // cubemap: the cell's column (s) and row (t) at that level
  double s = 0.0, t = 0.0;          // cubemap: the point's coordinates on the cube face, in [-1, 1]
  std::vector<std::uint32_t> path;  // walk: the faces visited, in order
  std::vector<WalkTest> steps;      // walk: every edge test
  std::vector<FaceTest> faces;      // plane tests, in order
  std::vector<ZoneTest> zoneSteps;  // cubemap: the bisection over a zone of thin faces
  std::vector<SectorTest> sectorSteps;  // cubemap: the bisection around a sector leaf's axis
  bool radiusFilter = true;             // cubemap: the radius filter ran (TraceOptions::radii)
  Vec3 direction{};                     // cubemap: p - centre, whose largest |coordinate| picks
                                        // the cube face and whose quotients are s and t
  std::uint32_t cellsPerSide = 0;       // cubemap: cells per side of the cube face at `level`;
                                        // cellI = floor((s + 1) / 2 * cellsPerSide), clamped
};

// Size and shape of a subdivision. Methods without cells report zero cells.
struct Stats3D {
  std::size_t faces = 0;      // plane faces (adjacent coplanar triangles merged)
  std::size_t triangles = 0;  // the triangles they are made of
  std::size_t vertices = 0;
  std::size_t cells = 0;    // cubemap: leaf cells over all levels
  std::size_t nodes = 0;    // cubemap: quadtree nodes, leaves and inner ones
  std::size_t entries = 0;  // sum over cells of the faces listed
  std::size_t maxPerCell = 0;
  double meanPerCell = 0.0;
  std::size_t crowdedCells = 0;  // cells searched by a walk or a zone's bisection rather than
                                 // tested face by face
  std::size_t zoneCells = 0;     // cubemap: crowded cells searched by bisection over a zone
  std::size_t sectorCells = 0;   // cubemap: crowded cells searched by bisection around an axis
  std::uint32_t resolution = 0;  // cubemap: G, the base grid is G x G on each cube face
  int maxLevel = 0;              // cubemap: the deepest quadtree level
  bool centred = false;       // a centre strictly inside exists (else every query tests all faces)
  std::size_t bytes = 0;      // memory the locator holds, vertices included
  double bytesPerFace = 0.0;  // bytes per triangle (the input's size)
  double buildSeconds = 0.0;
  std::vector<std::size_t> histogram;  // histogram[k]: cells holding k faces; the last bucket
                                       // counts every cell holding at least that many
};

// the cube map's faces by number (Trace3D::cubeFace, Cell3D::cubeFace): face 2a + 1 looks
// down axis a, face 2a up it
inline constexpr std::array<std::string_view, 6> kCubeFaceNames = {"+x", "-x", "+y",
                                                                   "-y", "+z", "-z"};

// One cubemap cell, for drawing and teaching: a square on a cube face and the pyramid it
// spans from the centre.
struct Cell3D {
  std::uint32_t index = 0;     // position in cells()
  int cubeFace = 0;            // 0..5 for +x, -x, +y, -y, +z, -z
  int level = 0;               // quadtree level (0: the base grid)
  std::uint32_t i = 0, j = 0;  // column and row among the (G * 2^level)^2 cells of the face
  double s0 = 0, s1 = 0, t0 = 0, t1 = 0;  // the square in cube-face coordinates
  Vec3 apex{};                            // the centre, apex of the cell's pyramid
  std::array<Vec3, 4> corners{};     // the square's corners on the drawing cube around the centre,
                                     // (s0,t0), (s1,t0), (s1,t1), (s0,t1)
  std::vector<std::uint32_t> faces;  // faces listed in the cell
};

// faces per cell above which a cubemap cell is searched by a walk
inline constexpr std::size_t kCrowdedCell3D = 8;

namespace detail {
// the surface a 3D locator keeps its own copy of, so that the polyhedron may go away
struct SurfaceCopy {
  std::vector<Vec3> vertices;
  std::vector<ConvexPolyhedron::Triangle> faces;  // the plane faces: ConvexPolyhedron::planes()
  std::size_t triangles = 0;                      // ConvexPolyhedron::faceCount()
  SurfaceCopy() = default;
  explicit SurfaceCopy(const ConvexPolyhedron& polyhedron);
  // the bytes both buffers hold
  std::size_t bytes() const noexcept;
};

// The triangles a walk crosses, their adjacency and the plane face of each. Where no two
// triangles are coplanar (plane face t is triangle t) only the adjacency is kept: the
// triangles are the surface's faces.
struct WalkMesh {
  std::vector<ConvexPolyhedron::Triangle> neighbours;  // ConvexPolyhedron::neighbours()
  std::vector<ConvexPolyhedron::Triangle> triangles;   // ConvexPolyhedron::triangles(), or empty
  std::vector<std::uint32_t> planeOf;                  // ConvexPolyhedron::planeOf(), or empty
  std::vector<std::uint32_t> firstTriangle;            // the lowest triangle of each plane face
  WalkMesh() = default;
  explicit WalkMesh(const ConvexPolyhedron& polyhedron);
  // the triangles, given the surface's faces
  const std::vector<ConvexPolyhedron::Triangle>& trianglesOf(const SurfaceCopy& s) const noexcept {
    return triangles.empty() ? s.faces : triangles;
  }
  // the plane face of triangle t
  std::uint32_t plane(std::uint32_t t) const noexcept { return planeOf.empty() ? t : planeOf[t]; }
  // a triangle of plane face f
  std::uint32_t triangle(std::uint32_t f) const noexcept {
    return firstTriangle.empty() ? f : firstTriangle[f];
  }
  // the bytes its buffers hold
  std::size_t bytes() const noexcept;
};

}  // namespace detail

// === halfspace, O(F): inside iff on the inner side of every face plane (eq. 2)

// locate, the batch and trace come from SinkQueries
class HalfspaceLocator : public detail::SinkQueries<HalfspaceLocator, Vec3, Trace3D> {
 public:
  // keeps a copy of the surface; needs no centre
  explicit HalfspaceLocator(const ConvexPolyhedron& polyhedron);
  // faces, vertices, memory and build time; no cells
  Stats3D stats() const;
  // none: the method has no cells
  std::vector<Cell3D> cells() const { return {}; }

 private:
  friend SinkQueries;
  static constexpr Method3D kMethod = Method3D::Halfspace;
  // the sign of every face plane, in order, up to the first outer side
  template <class Sink>
  Location run(Vec3 p, Sink& sink) const noexcept;
  detail::SurfaceCopy surface_;
  double buildSeconds_ = 0.0;
};

// === walk, O(sqrt F) expected: across face adjacency toward the face the ray from the
// centre through the point leaves by (ref. [11]), then one plane test

// locate (walks from the start face nearest p's direction, then tests one plane), the batch
// and trace (the faces visited, every edge test, the final plane test) come from SinkQueries
class WalkLocator : public detail::SinkQueries<WalkLocator, Vec3, Trace3D> {
 public:
  // keeps the surface and its adjacency, and about F^(1/3) start faces spread over it
  explicit WalkLocator(const ConvexPolyhedron& polyhedron);
  // the centre, when the polyhedron has one (else every query tests all faces)
  std::optional<Vec3> centre() const noexcept { return centre_; }
  // faces, vertices, memory and build time; no cells
  Stats3D stats() const;
  // none: the walk has no cells
  std::vector<Cell3D> cells() const { return {}; }

 private:
  friend SinkQueries;
  static constexpr Method3D kMethod = Method3D::Walk;
  template <class Sink>
  Location run(Vec3 p, Sink& sink) const noexcept;
  // the trace's centre is the walk's
  void completeTrace(Trace3D& t) const { t.centre = centre_; }
  detail::SurfaceCopy surface_;
  detail::WalkMesh mesh_;
  std::vector<std::uint32_t> startFaces_;              // triangles a walk may start from
  std::vector<std::array<float, 3>> startDirections_;  // theirs from the centre, unit length
  std::optional<Vec3> centre_;
  std::uint32_t maxVisits_ = 0;  // faces a walk visits before it gives up and tests all
  double buildSeconds_ = 0.0;
};

// === cubemap, O(1): the paper's "spherical" subdivision

class CubemapBuilder;

// A CubemapLocator's tables as plain arrays (CubemapLocator::tables()), from which the
// constructor below makes the same locator again without building: what a saved or pickled
// cube map carries. Loading checks the structure (CubemapLocator's load constructor says
// what); the lists themselves are trusted to be this version's builder's.
struct CubemapTables {
  // the tables' layout; a load refuses any other (a caller may rebuild instead)
  static constexpr std::uint32_t kVersion = 1;
  std::uint32_t version = kVersion;
  std::uint32_t resolution = 0;             // G; 0: no cells (no centre), every other table empty
  Vec3 centre{};                            // strictly inside
  double buildSeconds = 0.0;                // the build's, which stats() goes on reporting
  std::vector<std::uint32_t> nodes;         // per node: first, count (index.hpp's marks)
  std::vector<float> radii;                 // per node: in2, out2 (NaN for an inner node)
  std::vector<std::uint32_t> entries;       // the leaves' lists
  std::vector<std::uint32_t> zones;         // per zone: first, size, sigma (1; 0 for -1)
  std::vector<std::uint32_t> zoneEdges;     // per edge: its two vertices
  std::vector<std::uint32_t> zoneFaces;     // per zone place: its face
  std::vector<std::uint32_t> zoneRanges;    // per range: zone, lo, span
  std::vector<double> sectorPoints;         // per fan: axis, reference (6 doubles)
  std::vector<std::uint32_t> sectors;       // per fan: sign (1; 0 for -1), first, size, back
  std::vector<std::uint32_t> sectorFaces;   // per fan place: its face
  std::vector<std::uint32_t> sectorKeys;    // and its key (index.hpp)
  std::vector<std::uint32_t> sectorRanges;  // per range: fan, from, to
  std::vector<float> slabs;  // per node: normal (3), lo, hi; empty: no slabs (none decides)
};

// A centre c strictly inside; the direction d = p - c picks a cube face by its dominant axis
// and a point (s, t) = (d_u, d_v) / |d_major| in [-1, 1]^2 on it; a G x G grid per cube face,
// refined as a quadtree where cells are crowded, lists in each cell every face whose central
// projection meets it (built conservatively with the query's own index function); the query
// tests p against those faces' planes, unless the cell's two radii decide first (most points
// of a large polyhedron). Memory stays within 128 bytes per face plus 32 KiB (the constant
// lets a small polyhedron have a grid worth drawing). The correctness argument heads
// core/src/cubemap/index.hpp.
class CubemapLocator {
 public:
  // A zone: faces F_0 .. F_(n-1) around one direction, F_k between edges E_k and E_(k+1)
  // (mod n), every edge exactly parallel to the direction (a cylinder's or a prism's sides).
  // The planes through the centre and each E_k share one line, so they are ordered by angle
  // around it: a crowded leaf over a zone keeps a range of it, searched by bisection.
  struct Zone {
    std::uint32_t first = 0, size = 0;  // E_k and F_k at zoneEdges_/zoneFaces_[first + k]
    int sigma = 1;                      // orient3d's sign for a point before an edge
  };
  // a leaf's range of a zone: the faces F_lo .. F_(lo + span - 1), indices mod the size
  struct ZoneRange {
    std::uint32_t zone = 0, lo = 0, span = 0;
  };
  // A fan (cubemap/sectors.cpp): `size` thin faces sorted by the angle of a key corner around
  // the axis through the centre and `axis`, all strictly on the `sign` side of the plane
  // through the axis and `reference`, at sectorFaces_ / sectorKeys_[first ..]; a bisection
  // finds p's place among the keys, and the faces of that place's window are tested (`back`
  // faces before the place past the last key).
  struct Sectors {
    Vec3 axis{}, reference{};
    int sign = 1;
    std::uint32_t first = 0, size = 0, back = 0;
  };
  // a leaf's places in a fan: keys from .. to - 1 are searched
  struct SectorRange {
    std::uint32_t fan = 0, from = 0, to = 0;
  };
  // `resolution` = G, 0 chooses from the face count; at most 8192. A grid that would not fit
  // the memory budget is coarsened: stats().resolution tells the G used.
  explicit CubemapLocator(const ConvexPolyhedron& polyhedron, std::uint32_t resolution = 0);
  // The locator whose tables() these are, over the polyhedron it was built from, without
  // building. Checked, else ParseError naming the table and the problem: the version; G in
  // the builder's range and the deepest level the builder gives it; every table's size;
  // every index in range (nodes, entries, zones and fans, their edges, faces, keys and
  // ranges, and the places a bisection reaches); the quadtree a tree no deeper than that
  // level; the centre finite and strictly inside every face plane (exact predicates);
  // marks and signs valid, radii numbers (NaN exactly at inner nodes), slabs none or one
  // per node of numbers. So no query of a loaded locator reads outside its tables. Not
  // checked (trusted to be this version's builder's, as the version says): that each cell
  // lists every face it must and that its radii and slabs are sound, on which exact answers
  // rest (cubemap/index.hpp).
  CubemapLocator(const ConvexPolyhedron& polyhedron, const CubemapTables& tables);
  // the tables, to load with the constructor above
  CubemapTables tables() const;
  // whether it was loaded from tables rather than built (stats() then reports the build's
  // time, carried in the tables)
  bool loaded() const noexcept { return loaded_; }
  // aims at p's cell; its radii decide, else its faces' planes (or a walk in a crowded cell)
  Location locate(Vec3 p) const noexcept;
  // locate(p) for each point, in stages that overlap the tables' cache misses (AVX2 where the
  // CPU has it); the same answers
  void locate(std::span<const Vec3> points, std::span<Location> out) const noexcept;
  // the cube face and cell, the radii, the plane tests or the walk
  Trace3D trace(Vec3 p) const { return trace(p, TraceOptions{}); }
  // the same with `options`: without the radii, the cell's faces decide (the paper's query)
  Trace3D trace(Vec3 p, TraceOptions options) const;
  // cells, nodes, entries per cell, levels, memory and build time
  Stats3D stats() const;
  // every leaf cell, cube face by cube face
  std::vector<Cell3D> cells() const;
  // the centre, when the polyhedron has one (else there are no cells and every query tests
  // all faces)
  std::optional<Vec3> centre() const noexcept;
  // G, the base grid's cells per side on each cube face (0 when there are no cells)
  std::uint32_t resolution() const noexcept { return resolution_; }
  // half the side of the cube, centred on the centre, that cells() draws on (it encloses
  // the polyhedron)
  double cubeHalfSize() const noexcept { return cubeHalfSize_; }
  // the faces listed in the leaf cell p maps to (the ones a query of p may test; a zone
  // leaf's range in full, a fan leaf's faces from the first its places' windows hold to the
  // last), in increasing order; empty for the centre and where there is no cell
  std::vector<std::uint32_t> cellFaces(Vec3 p) const;
  // the surface it locates in: its vertices, and its plane faces (ConvexPolyhedron::planes())
  std::span<const Vec3> vertices() const noexcept { return surface_.vertices; }
  std::span<const ConvexPolyhedron::Triangle> faces() const noexcept { return surface_.faces; }

 private:
  friend class CubemapBuilder;
  // A leaf also keeps two squared distances from the centre, rounded outward: a point of the
  // cell nearer than sqrt(in2) is inside (nearer than every point of the listed faces that
  // the cell's pyramid sees), one farther than sqrt(out2) outside (beyond where its ray
  // leaves the polyhedron). Most points of a large polyhedron are decided by these 16
  // bytes, without a face test. An inner node's two are NaN: they decide nothing, so a
  // batch that reads them sends the point down.
  struct Node {
    std::uint32_t first = 0;  // leaf: first entry; inner node: first of its 4 children
    std::uint32_t count = 0;  // leaf: number of entries; kInner for an inner node
    float in2 = 0.0f;
    float out2 = 0.0f;
  };
  // A leaf's slab (cubemap/slabs.cpp), beside its node: a point of the cell that its radii
  // leave open, with v = n . (p - c), is inside when v < lo and outside when v > hi (lo and hi
  // bound n . (y - c) over the points y where the cell's rays may leave, rounded outward). A
  // flat part of the surface, where the radii leave a thick shell, is decided by it. Disabled
  // (lo = -inf, hi = +inf) at inner nodes and where no bound holds.
  struct Slab {
    float n[3] = {0.0f, 0.0f, 0.0f};
    float lo = -std::numeric_limits<float>::infinity();
    float hi = std::numeric_limits<float>::infinity();
  };
  // where a query's direction points: cube face, coordinates on it, deepest-level cell
  struct Aim {
    int face = 0;
    double s = 0.0, t = 0.0, d2 = 0.0;   // d2: squared distance from the centre
    std::uint64_t deepI = 0, deepJ = 0;  // the cell's column and row at the deepest level
    std::uint32_t baseCell = 0;          // the base cell (a node index) holding it
  };
  // 1: aimed; 0: p is the centre; -1: no cell (not finite, no centre, direction overflows)
  [[gnu::always_inline]] int aim(Vec3 p, Aim& a) const noexcept;
  // the leaf holding cell (deepI, deepJ) of the deepest level, down from `node` at `level`
  // (which becomes the leaf's level)
  [[gnu::always_inline]] std::uint32_t leafAt(std::uint64_t deepI, std::uint64_t deepJ,
                                              std::uint32_t node, int& level) const noexcept;
  // p's answer in a leaf over a zone: bisection over the zone's edges, then the zone face found
  // and the leaf's other faces
  template <class Sink>
  Location fromZone(Vec3 p, const Node& leaf, Sink& sink) const noexcept;
  // p's answer in a sector leaf: bisection around its axis, then the faces near p's place and
  // the leaf's others
  template <class Sink>
  Location fromSectors(Vec3 p, const Node& leaf, Sink& sink) const noexcept;
  // the faces leaf `nd` lists, a zone's range expanded
  std::vector<std::uint32_t> leafFaces(const Node& nd) const;
  // the whole query; run and fromLeaf stay out of line, apart from the inline aim and radii
  // that decide most points in locate() and the batch
  template <class Sink>
  [[gnu::noinline]] Location run(Vec3 p, Sink& sink) const noexcept;
  // p's answer from its leaf (d2: its squared distance from the centre): the radii, else
  // the leaf's faces, or a walk
  template <class Sink>
  [[gnu::noinline]] Location fromLeaf(Vec3 p, double d2, const Node& leaf,
                                      Sink& sink) const noexcept;
  // visit(node, cube face, level, i, j) for every leaf, cube face by cube face, each base
  // cell's quadtree depth first, children in order
  template <class Visit>
  void forEachLeaf(Visit&& visit) const;
  detail::SurfaceCopy surface_;
  detail::WalkMesh mesh_;  // the triangles a crowded cell's walk crosses
  std::vector<Zone> zones_;
  std::vector<std::array<std::uint32_t, 2>> zoneEdges_;  // E_k from vertex to vertex, along
                                                         // the zone's direction
  std::vector<std::uint32_t> zoneFaces_;
  std::vector<ZoneRange> zoneRanges_;       // a zone leaf's first entry indexes these
  std::vector<Sectors> sectors_;            // the fans
  std::vector<std::uint32_t> sectorFaces_;  // each fan's faces, in order
  std::vector<std::uint32_t> sectorKeys_;   // and their keys (cubemap/index.hpp)
  std::vector<SectorRange> sectorRanges_;   // a sector leaf's first entry indexes these
  Table<Node> nodes_;                       // 6 G^2 base cells, then blocks of 4 children
  Table<std::uint32_t> entries_;            // each leaf's faces
  Table<Slab> slabs_;                       // each node's slab, at its index (none: empty)
  Vec3 centre_{};
  bool centred_ = false;
  std::uint32_t resolution_ = 1;  // G
  int deepestLevel_ = 0;          // the deepest level a cell may have
  double deepScale_ = 0.0;        // G * 2^(deepest - 1): (s + 1) * deepScale_ is the deepest index
  double cubeHalfSize_ = 1.0;
  double buildSeconds_ = 0.0;
  bool loaded_ = false;
};

// === Any of the three, chosen at run time

// locate, the batch, trace, stats, cells, method() and get<T>() come from LocatorVariant
// (convexloc/detail/locator_variant.hpp)
class Locator3D : public detail::LocatorVariant<Method3D, Vec3, Trace3D, Stats3D, Cell3D,
                                                HalfspaceLocator, WalkLocator, CubemapLocator> {
 public:
  // builds `method`; `resolution` is the cubemap's G (0 chooses), ignored by the others
  Locator3D(const ConvexPolyhedron& polyhedron, Method3D method, std::uint32_t resolution = 0);
};

}  // namespace convexloc
