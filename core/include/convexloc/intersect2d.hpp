// convexloc — a line against a convex polygon: misses, touches or crosses, where it meets the
// boundary, and segment clipping. Exact for the doubles given.
//
// A line is given by two distinct double points p1 != p2 and runs from p1 towards p2. With
// f(v) = orient2d(p1, p2, v), the exact sign of (p2 - p1) x (v - p1): the line misses the
// polygon when every vertex has the same strict sign, touches it when no two vertices have
// strictly opposite signs but one or two lie on it, and crosses it otherwise. Every method
// finds the vertices where f is largest and smallest and decides from their two exact signs;
// they differ only in how they find them:
//   vertices   O(N)      every vertex's sign (the baseline)
//   bisection  O(log N)  the extreme vertices by bisection over the ring
//   dual       O(1)      the polar locator of the dual polygon proposes them (see
//                        core/src/intersect/dual_polar.cpp for when the O(1) holds)
// Where the line meets the boundary (entry and exit) and clipping add O(log N) bisection to
// the bisection and dual methods, O(N) to the vertices method.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "convexloc/crossing.hpp"
#include "convexloc/geometry.hpp"
#include "convexloc/polygon.hpp"

namespace convexloc {

class PolarLocator;

namespace detail {
class DualPolar2D;
struct LineProbe;
}  // namespace detail

// === Results

// the 2D line methods, slowest first
enum class LineMethod : std::uint8_t { Vertices, Bisection, Dual };
// every 2D line method, in order
inline constexpr LineMethod kAllLineMethods[] = {LineMethod::Vertices, LineMethod::Bisection,
                                                 LineMethod::Dual};
// "vertices", "bisection", "dual": what --method takes
std::string_view toString(LineMethod m) noexcept;
// the cost of one classification: "O(N)", "O(log N)", "O(1)"
std::string_view costOf(LineMethod m) noexcept;
// the method with that name, if any
std::optional<LineMethod> parseLineMethod(std::string_view name) noexcept;

// Where a line meets the boundary: vertex `index` itself (atVertex), or the inside of edge
// `index` (from vertex index to index + 1), never at its ends.
struct BoundaryHit {
  std::uint32_t index = 0;
  bool atVertex = false;
  friend bool operator==(const BoundaryHit&, const BoundaryHit&) = default;
};

// A line against the polygon. For a line that touches or crosses, entry and exit are where it
// meets the boundary first and last, in the line's direction: for a crossing line the two
// points where it enters and leaves; for a line along an edge that edge's two vertices; for a
// line through one vertex only, that vertex twice.
struct LineHit {
  Crossing crossing = Crossing::Misses;
  BoundaryHit entry{};
  BoundaryHit exit{};
  friend bool operator==(const LineHit&, const LineHit&) = default;
};

// a segment from a to b (a == b for a single point)
struct Segment2D {
  Vec2 a{};
  Vec2 b{};
  friend bool operator==(const Segment2D&, const Segment2D&) = default;
};

// What one classification did, step by step.
struct LineTrace {
  LineMethod method = LineMethod::Dual;
  Crossing crossing = Crossing::Misses;
  ExtremeVertices extremes;       // where f is largest and smallest, its exact signs there
  std::int64_t cell = -1;         // dual: the polar cell of the line's normal w, -1 when none
  std::int64_t opposite = -1;     // dual: the polar cell of -w
  std::uint32_t startMax = 0;     // dual: the vertex w's direction cell proposed (largest f)
  std::uint32_t startMin = 0;     // dual: the vertex -w's direction cell proposed (smallest f)
  std::uint32_t climbSteps = 0;   // dual: moves from the proposals to the extremes
  bool bisected = false;          // dual: a climb ran long and bisection finished it
  std::uint32_t comparisons = 0;  // exact comparisons of two vertices along the normal
};

// Size of what a method built.
struct LineStats {
  std::size_t vertices = 0;
  std::size_t dualVertices = 0;  // dual: vertices of the dual polygon (normals and antipodes)
  std::size_t cells = 0;         // dual: polar cells
  std::size_t maxPerCell = 0;    // dual: most dual edges one cell lists
  std::size_t bytes = 0;
  double buildSeconds = 0.0;
};

// === The intersector

// A convex polygon prepared for line queries by one method. Keeps its own copy of the vertices.
class LineIntersector {
 public:
  explicit LineIntersector(const ConvexPolygon& polygon, LineMethod method = LineMethod::Dual);
  ~LineIntersector();
  LineIntersector(LineIntersector&&) noexcept;
  LineIntersector& operator=(LineIntersector&&) noexcept;

  LineMethod method() const noexcept { return method_; }
  // the polygon's vertices, counter-clockwise
  std::span<const Vec2> vertices() const noexcept { return ring_; }
  // How the line through p1 and p2 meets the polygon. Precondition: p1 != p2.
  Crossing classify(Vec2 p1, Vec2 p2) const noexcept;
  // a batch: out[i] for the line through lines[2i] and lines[2i + 1]; allocates nothing
  void classify(std::span<const Vec2> lines, std::span<Crossing> out) const noexcept;
  // How it meets the polygon, and where (entry and exit). Precondition: p1 != p2.
  LineHit intersect(Vec2 p1, Vec2 p2) const noexcept;
  // The part of the segment from s1 to s2 inside the closed polygon, in the segment's own
  // direction; none when they do not meet. Its ends are s1, s2 or vertices where the
  // segment reaches them, otherwise the exact point where it crosses an edge rounded to
  // the nearest double. Precondition: s1 != s2.
  std::optional<Segment2D> clip(Vec2 s1, Vec2 s2) const;
  // the steps classify takes
  LineTrace trace(Vec2 p1, Vec2 p2) const;
  LineStats stats() const;
  // dual: the dual polygon (unit normals of the edges and their antipodes) and its polar
  // locator, whose cells are the ones trace() names; null for the other methods
  const PolarLocator* dualLocator() const noexcept;
  // dual: the dual polygon's vertices, counter-clockwise (the polygon dualLocator() was built
  // on); empty for the other methods
  std::span<const Vec2> dualVertices() const noexcept;

 private:
  // the vertices where f is largest and smallest, and their exact signs; records in `trace`
  // when given
  ExtremeVertices extremes(Vec2 p1, Vec2 p2, LineTrace* trace) const noexcept;
  // dual: the ring index of a vertex where the probe's f is largest, confirmed in polar cell
  // c's window or climbed to from its proposal, and its coordinates in `at`; counts moves
  // in `steps`, sets `bisected` when bisection finished a long climb
  std::uint32_t largestFrom(std::int64_t c, detail::LineProbe& probe, Vec2& at,
                            std::uint32_t& steps, bool& bisected) const noexcept;
  // dual: the crossing from the cells of the line's normal (up) and of its opposite (down)
  Crossing classifyInCells(Vec2 p1, Vec2 p2, std::int64_t up, std::int64_t down) const noexcept;
  LineMethod method_;
  std::vector<Vec2> ring_;
  std::unique_ptr<detail::DualPolar2D> dual_;
  double buildSeconds_ = 0.0;
};

// The point of the line through p1, p2 and the line through a, b, which must cross exactly
// once, each coordinate rounded to the nearest double (ties to even).
Vec2 roundedIntersection(Vec2 p1, Vec2 p2, Vec2 a, Vec2 b);

}  // namespace convexloc
