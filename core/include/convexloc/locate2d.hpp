// convexloc — point location in a convex polygon: the paper's five methods.
//
// Every locator answers exactly (see Location); a point with an infinite or NaN coordinate is
// Outside. They share one interface:
//   locate(p)            one point
//   locate(points, out)  a batch; allocates nothing per point
//   trace(p)             the steps taken: cell, predicates and their signs, result
//   stats()              size and shape of the subdivision
//   cells()              the subdivision as drawable geometry, with the edges each cell holds
// A locator keeps its own copy of the vertices; the polygon may go away after the build.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <utility>
#include <variant>
#include <vector>

#include "convexloc/detail/locator_variant.hpp"
#include "convexloc/detail/sink_queries.hpp"
#include "convexloc/geometry.hpp"
#include "convexloc/methods.hpp"
#include "convexloc/polygon.hpp"
#include "convexloc/table.hpp"

namespace convexloc {

// === Common result types

// one edge test: sign of orient2d(edge start, edge end, point); > 0 is the inner side
struct EdgeTest {
  std::uint32_t edge = 0;
  int sign = 0;
};

// one ray test: sign of orient2d(apex, vertex, point); > 0 means the point is
// counter-clockwise of the ray from the apex through the vertex
struct RayTest {
  std::uint32_t vertex = 0;
  int sign = 0;
};

// one probe of the slab method's binary search: the vertex y at rank `rank` (ascending,
// distinct) against the point's y; `above`: p.y >= y, the search goes on above it
struct SlabProbe {
  std::uint32_t rank = 0;
  double y = 0.0;
  bool above = false;
};

// the uniform method's index, eq. (4): slab = floor((y - yMin) / height), computed as
// (y - yMin) * slabs / (box height) and clamped to the last slab
struct UniformIndex {
  double yMin = 0.0;        // the bounding box's bottom
  double height = 0.0;      // one slab's height, (box height) / slabs
  double value = 0.0;       // (y - yMin) * slabs / (box height), before the floor
  std::uint32_t slabs = 0;  // the slab count
};

// the polar index: the octant from the signs of dx, dy and |dy| > |dx|, then the slab
// k = floor(ratio * q) with ratio = min(|dx|, |dy|) / max(|dx|, |dy|), and the cell
// base + step * k of that octant
struct PolarIndexTrace {
  Vec2 direction{};         // p - centre
  double ratio = 0.0;       // min / max of |dx|, |dy|
  bool steep = false;       // |dy| > |dx|: the ratio is |dx| / |dy|, else |dy| / |dx|
  std::uint32_t slab = 0;   // k, 0 .. q - 1
  std::uint32_t slabs = 0;  // q, the slabs per octant
  std::int64_t base = 0;    // the octant's cell for k = 0
  std::int64_t step = 0;    // +1 or -1: the cell is base + step * k
};

// What one query did, step by step.
struct Trace2D {
  Method2D method = Method2D::Halfplane;
  Location result = Location::Outside;
  bool outsideBox = false;      // decided by the bounding box before any cell
  std::int64_t cell = -1;       // slab or polar cell index; -1 when none was used
  int octant = -1;              // polar: 0..7 counter-clockwise from +x, else -1
  bool crowded = false;         // the cell held many edges and was searched by bisection
  bool atCentre = false;        // polar: the point is the centre itself
  bool byRadius = false;        // polar: decided by the cell's radii, before any edge test
  double distance = 0.0;        // polar: |p - centre| (approximate, for display)
  double innerRadius = 0.0;     // polar: nearer than this to the centre, a point of the cell
  double outerRadius = 0.0;     //   is inside; farther than outerRadius, outside
  Vec2 apex{};                  // wedge: vertex 0; polar: the centre (vertex 0 on the fan)
  std::vector<RayTest> rays;    // bisection steps (wedge, crowded polar cells)
  std::vector<EdgeTest> edges;  // edges tested, in order
  // the numbers of each step, for teaching
  bool radiusFilter = true;       // polar: the radius filter ran (TraceOptions::radii)
  std::vector<SlabProbe> probes;  // slab: the binary search's probes, in order
  UniformIndex uniform;           // uniform: eq. (4) with its numbers (slabs 0 when unused)
  PolarIndexTrace polar;          // polar: the index's numbers (slabs 0 when no cell)
};

// Size and shape of a subdivision. Methods without cells report zero cells.
struct Stats2D {
  std::size_t edges = 0;
  std::size_t cells = 0;
  std::size_t entries = 0;  // sum over cells of the edges listed
  std::size_t maxPerCell = 0;
  double meanPerCell = 0.0;
  std::size_t crowdedCells = 0;  // cells searched by bisection rather than tested edge by edge
  std::size_t bytes = 0;         // memory the locator holds, vertices included
  double bytesPerEdge = 0.0;
  double buildSeconds = 0.0;
  std::vector<std::size_t> histogram;  // histogram[k]: cells holding k edges; the last bucket
                                       // counts every cell holding at least that many
};

// One cell of a subdivision, for drawing and teaching.
struct Cell2D {
  std::uint32_t index = 0;
  int octant = -1;                   // polar only
  std::vector<Vec2> outline;         // the cell clipped to the locator's box, CCW
  Vec2 dirLo{}, dirHi{};             // polar: directions of the two bounding rays
  Vec2 hitLo{}, hitHi{};             // polar: where those rays leave the box
  double y0 = 0.0, y1 = 0.0;         // slab, uniform: the y range
  std::vector<std::uint32_t> edges;  // edges listed in the cell
};

// edges per cell above which a cell is searched by bisection
inline constexpr std::size_t kCrowdedCell = 8;

// === halfplane, O(N): inside iff on the inner side of every edge (eq. 1)

// locate, the batch and trace come from SinkQueries (convexloc/detail/sink_queries.hpp)
class HalfplaneLocator : public detail::SinkQueries<HalfplaneLocator, Vec2, Trace2D> {
 public:
  // keeps a copy of the vertices; there is nothing else to build
  explicit HalfplaneLocator(const ConvexPolygon& polygon);
  // the edges and the memory held; no cells
  Stats2D stats() const;
  // none: the method has no cells
  std::vector<Cell2D> cells() const { return {}; }

 private:
  friend SinkQueries;
  static constexpr Method2D kMethod = Method2D::Halfplane;
  template <class Sink>
  Location run(Vec2 p, Sink& sink) const noexcept;
  std::vector<Vec2> vertices_;
  double buildSeconds_ = 0.0;
};

// === wedge, O(log N): bisection over the fan of diagonals from vertex 0 (eq. 3)

// locate, the batch and trace come from SinkQueries
class WedgeLocator : public detail::SinkQueries<WedgeLocator, Vec2, Trace2D> {
 public:
  // keeps a copy of the vertices: the fan needs no table
  explicit WedgeLocator(const ConvexPolygon& polygon);
  // the fan triangles counted as cells
  Stats2D stats() const;
  // the fan triangles (vertex 0, i, i+1), each holding edge i
  std::vector<Cell2D> cells() const;

 private:
  friend SinkQueries;
  static constexpr Method2D kMethod = Method2D::Wedge;
  template <class Sink>
  Location run(Vec2 p, Sink& sink) const noexcept;
  // the trace's apex is vertex 0 and its cell the fan triangle whose edge was tested
  void completeTrace(Trace2D& t) const;
  std::vector<Vec2> vertices_;
  double buildSeconds_ = 0.0;
};

// === slab, O(log N): horizontal slabs at the vertices' y, binary search, two active edges

// locate, the batch and trace come from SinkQueries
class SlabLocator : public detail::SinkQueries<SlabLocator, Vec2, Trace2D> {
 public:
  // one slab between each two consecutive distinct vertex y, with its two active edges
  explicit SlabLocator(const ConvexPolygon& polygon);
  // the slabs, two edges each
  Stats2D stats() const;
  // the slabs clipped to the polygon's bounding box, bottom to top
  std::vector<Cell2D> cells() const;

 private:
  friend SinkQueries;
  static constexpr Method2D kMethod = Method2D::Slab;
  template <class Sink>
  Location run(Vec2 p, Sink& sink) const noexcept;
  std::vector<Vec2> vertices_;
  std::vector<double> vertexYs_;            // distinct vertex y, ascending
  std::vector<std::uint32_t> activeEdges_;  // per slab: rising edge, falling edge
  Box2 box_{};
  double buildSeconds_ = 0.0;
};

// === uniform, O(1): equal horizontal slabs (eq. 4), each listing its active edges

// locate, the batch and trace come from SinkQueries
class UniformLocator : public detail::SinkQueries<UniformLocator, Vec2, Trace2D> {
 public:
  // `slabs` equal slabs over the bounding box's height (0 chooses from the edge count; at
  // most 2^26); throws UsageError when the table would exceed 2^32 entries
  explicit UniformLocator(const ConvexPolygon& polygon, std::uint32_t slabs = 0);
  // the slabs and the edges they list
  Stats2D stats() const;
  // the slabs clipped to the polygon's bounding box, bottom to top
  std::vector<Cell2D> cells() const;
  // the number of slabs built (1 where the box is too tall or too flat for the arithmetic)
  std::uint32_t slabCount() const noexcept { return slabCount_; }
  // the slab a point with this y maps to (the index function of queries and build alike)
  std::uint32_t slabOf(double y) const noexcept;

 private:
  friend SinkQueries;
  static constexpr Method2D kMethod = Method2D::Uniform;
  // === Build steps
  void chooseSlabs(std::uint32_t slabs);
  std::pair<std::uint32_t, std::uint32_t> slabRange(std::uint32_t edge) const;
  std::vector<std::uint32_t> countEntries() const;
  std::vector<std::uint64_t> layOutSlabs(const std::vector<std::uint32_t>& count);
  void fillSlabs(std::vector<std::uint64_t>& cursor);
  // === Query
  template <class Sink>
  Location run(Vec2 p, Sink& sink) const noexcept;
  std::vector<Vec2> vertices_;
  std::vector<std::uint32_t> offsets_;  // CSR: slab s lists entries [offsets_[s], offsets_[s+1])
  std::vector<std::uint32_t> entries_;  // rising edges by y, then falling, then horizontal
  std::vector<std::uint32_t> rising_;   // per slab: how many leading entries are rising
  std::vector<std::uint32_t> falling_;  // per slab: how many entries after those are falling
  Box2 box_{};
  std::uint32_t slabCount_ = 1;
  double slabScale_ = 0.0;  // slabs per unit of y: (y - box_.lo.y) * slabScale_ is the slab
  double buildSeconds_ = 0.0;
};

// === polar, O(1): the paper's polar slabs around a centre strictly inside

namespace detail {
// What the polar index function reads (it lives in core's src/polar/index.hpp): the cell of
// p is cellBase[o] + cellStep[o] * k for p's octant index o and slab k within the octant.
struct PolarIndex {
  std::int64_t cellBase[8] = {};  // per octant index: its first cell, or its last
  std::int64_t cellStep[8] = {};  // +1 or -1: how the cell follows the ratio
  Vec2 centre{};                  // the centre; vertex 0 where the locator has none
  std::uint32_t slabsPerOctant = 1;
  double slabScale = 1.0;  // slabsPerOctant as a double: the ratio's scale to a slab
};
}  // namespace detail

class PolarLocator {
 public:
  // `slabsPerOctant` = 0 chooses from the edge count (at most 2^23); throws UsageError when
  // the table would exceed 2^32 entries. Without a double point strictly inside, or where
  // the directions from it overflow, builds no table and answers by bisecting the fan.
  explicit PolarLocator(const ConvexPolygon& polygon, std::uint32_t slabsPerOctant = 0);
  // the class of p (exact)
  Location locate(Vec2 p) const noexcept;
  // out[i] = locate(points[i]) over the shorter of the two spans; allocates nothing
  void locate(std::span<const Vec2> points, std::span<Location> out) const noexcept;
  // the steps locate(p) takes, and its answer
  Trace2D trace(Vec2 p) const { return trace(p, TraceOptions{}); }
  // the same with `options`: without the radii, the cell's edges decide (the paper's query)
  Trace2D trace(Vec2 p, TraceOptions options) const;
  // the cells and the edges they list
  Stats2D stats() const;
  // every cell, counter-clockwise from +x, clipped to box(); none without a centre
  std::vector<Cell2D> cells() const;
  // the centre, a double point strictly inside the polygon; none where the locator bisects
  // the fan instead (no such point, or directions from it overflow)
  std::optional<Vec2> centre() const noexcept {
    if (entries_.empty()) return std::nullopt;  // every centred table lists each edge
    return index_.centre;
  }
  // the slabs in each of the 8 octants
  std::uint32_t slabsPerOctant() const noexcept { return index_.slabsPerOctant; }
  // the number of cells, 8 * slabsPerOctant()
  std::uint32_t cellCount() const noexcept { return 8 * index_.slabsPerOctant; }
  // the cell a point maps to, or -1 for the centre and for directions too large to compute
  // (the index function of queries and build alike)
  std::int64_t cellIndex(Vec2 p) const noexcept;
  // the edges cell `cell` (0 <= cell < cellCount()) lists, counter-clockwise
  std::span<const std::uint32_t> cellEdges(std::int64_t cell) const noexcept {
    const auto c = static_cast<std::size_t>(cell);
    return {entries_.data() + offsets_[c], offsets_[c + 1] - offsets_[c]};
  }
  // the box the cells are drawn to (the polygon's bounding box)
  Box2 box() const noexcept { return box_; }

 private:
  // Squared distances from the centre, per cell, rounded outward: a point of the cell nearer
  // than sqrt(in2) is inside, one farther than sqrt(out2) is outside (src/detail/radii.hpp).
  struct Radii {
    float in2 = 0.0f;
    float out2 = 0.0f;
  };
  // === Build steps (polar/build.cpp, polar/radii.cpp)
  struct EdgeSpans;
  void layOutOctants(std::uint32_t slabsPerOctant);
  void buildWithoutCentre();
  EdgeSpans spanEdges() const;
  void fillCells(const EdgeSpans& spans);
  void orderCells(const EdgeSpans& spans);
  void buildRadii();
  void padRing();
  // === Query (polar/query.hpp)
  template <class Sink>
  Location run(Vec2 p, Sink& sink) const noexcept;
  template <class Sink>
  Location searchRange(Vec2 p, std::uint32_t first, std::uint32_t count, Sink& sink) const noexcept;
  // the vertexCount_ vertices (vertices_ repeats the first two at its end)
  std::span<const Vec2> ring() const noexcept { return {vertices_.data(), vertexCount_}; }

  std::vector<Vec2> vertices_;
  Table<std::uint32_t> offsets_;  // CSR over cellCount() cells
  Table<std::uint32_t> entries_;  // each cell's edges in counter-clockwise order
  Table<Radii> radii_;            // per cell
  detail::PolarIndex index_;
  Box2 box_{};
  std::uint32_t vertexCount_ = 0;
  double buildSeconds_ = 0.0;
};

// === Any of the five, chosen at run time

// locate, the batch, trace, stats, cells, method() and get<T>() come from LocatorVariant
// (convexloc/detail/locator_variant.hpp)
class Locator2D
    : public detail::LocatorVariant<Method2D, Vec2, Trace2D, Stats2D, Cell2D, HalfplaneLocator,
                                    WedgeLocator, SlabLocator, UniformLocator, PolarLocator> {
 public:
  // builds `method`; `resolution` is the uniform slab count or the polar slabs per octant
  // (0 chooses from the polygon), ignored by the other methods
  Locator2D(const ConvexPolygon& polygon, Method2D method, std::uint32_t resolution = 0);
};

}  // namespace convexloc
