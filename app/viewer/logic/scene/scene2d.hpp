// convexloc-viewer — the 2D scene: the polygon, the chosen method and its locator, the
// sprayed points and their classes, the placed point and its trace (all kept by
// SceneState), the hovered cell and a vertex being dragged. GL-free.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "convexloc/generate2d.hpp"
#include "convexloc/locate2d.hpp"
#include "convexloc/polygon.hpp"
#include "logic/scene/scene_common.hpp"
#include "logic/view/snap.hpp"

namespace convexloc::viewer {

// the 2D dimension, for SceneState
struct Traits2D : SceneTypes<Vec2, ConvexPolygon, Locator2D, Cell2D, Stats2D, Method2D, Trace2D> {
  static constexpr std::span<const Method2D> kMethods = kAllMethods2D;
  static constexpr Method2D kDefaultMethod = Method2D::Polar;
  // each method keeps its own resolution
  static constexpr std::size_t kSlots = std::size(kAllMethods2D);
  static constexpr std::size_t slot(Method2D m) { return static_cast<std::size_t>(m); }
  static constexpr std::uint32_t compareResolution(Method2D, std::uint32_t r) { return r; }
  static constexpr std::size_t kCompareSpray = 100000, kCompareChunk = 4096;
  static std::vector<Vec2> sprayPoints(const ConvexPolygon& p, std::size_t n, std::uint64_t seed,
                                       bool nearBoundary);
  static ConvexPolygon readShape(const std::string& path);
};

// the point placed by a click, and what the locator did with it
using Probe = PlacedPoint<Vec2, Trace2D>;
// one method timed by `compare`
using CompareRow = MethodTiming<Method2D>;

// a vertex being dragged
struct Drag {
  std::size_t vertex = 0;  // its index in the current polygon
  Vec2 cursor{};           // where the mouse is
  bool rejected = false;   // the shape with the vertex at the cursor is not valid
  std::string message;     // why, when rejected
};

// how many edges the cells of a method list at the least (the base of the tint)
std::size_t baseEdgesPerCell(Method2D m);

// The 2D scene: SceneState over a convex polygon, plus the hovered cell and a vertex being
// dragged.
class Scene2D : public SceneState<Traits2D> {
 public:
  // the default scene: a random convex polygon with polar slabs and a spray of points
  Scene2D();

  // === Shape
  // Makes `points` the shape (validated and normalised by core). On failure keeps the
  // current shape, returns false, and error() says why; `lines` (empty or one per point)
  // and `source` name the witness's line ("file.txt:7: not convex: reflex vertex ...").
  bool setShape(std::span<const Vec2> points, std::string label,
                std::span<const std::size_t> lines = {}, const std::string& source = "");
  // a generated polygon (core's generators); false and error() on a bad argument
  bool generate(PolygonKind kind, std::size_t n, std::uint64_t seed);
  const ConvexPolygon& polygon() const { return *shape_; }
  // the input points of the last setShape that normalisation dropped (repeated, or on the
  // segment between two vertices), none after a file, a generator's shape or a drag
  std::span<const Vec2> droppedPoints() const { return dropped_; }

  // === Method
  // the resolution the locator actually uses (core's choice when 0 was asked): slabs
  // (uniform) or slabs per octant (polar); other methods have none
  std::uint32_t effectiveResolution() const;
  // the polar centre, when the method is polar and core found one strictly inside
  std::optional<Vec2> centre() const;

  // === Hover: the cell under the cursor (by core's outlines), -1 for none
  void hover(std::optional<Vec2> p);
  std::ptrdiff_t hoveredCell() const { return hovered_; }
  std::optional<Vec2> hoverPoint() const { return hoverPoint_; }

  // === Drag a vertex
  // starts dragging vertex `i` (ignored when there is no such vertex)
  void beginDrag(std::size_t i);
  // Moves the dragged vertex to `p`. When the polygon so edited is valid and keeps every
  // vertex, it becomes the shape (the spray stays and is classified again) and true is
  // returned; otherwise the last valid shape stays and drag()->message says why.
  bool dragTo(Vec2 p);
  // ends the drag; a rejected last position becomes error()
  void endDrag();
  const std::optional<Drag>& drag() const { return drag_; }

  // === Snap indicator: what the pointer's position snaps to (drawn over the scene), or none
  void setSnapMark(std::optional<Snap> s);
  const std::optional<Snap>& snapMark() const { return snapMark_; }

 private:
  void cellsChanged() override;
  bool adoptShape(ConvexPolygon polygon, std::string label) override;
  // a fresh shape gets a new spray; an edited one keeps its points
  bool adopt(ConvexPolygon polygon, std::string label, bool fresh);

  std::ptrdiff_t hovered_ = -1;
  std::optional<Vec2> hoverPoint_;
  std::optional<Drag> drag_;
  std::optional<Snap> snapMark_;
  std::vector<Vec2> dropped_;
};

}  // namespace convexloc::viewer
