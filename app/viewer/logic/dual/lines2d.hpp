// convexloc-viewer — the 2D scene's Lines mode (the dual problem): a line placed by two
// points, what core's LineIntersector (dual method) reports about it, and where the dual
// view sits beside the polygon. GL-free; everything shown is core's answer, nothing here
// decides a classification.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "convexloc/intersect2d.hpp"
#include "convexloc/locate2d.hpp"
#include "logic/base/format.hpp"
#include "logic/narration/steps.hpp"
#include "logic/scene/scene2d.hpp"

namespace convexloc::viewer {

// a line and what core reports about it
struct LineProbe2D {
  Vec2 p1{}, p2{};
  std::size_t vertices = 0;          // the polygon's vertex count
  LineTrace trace;                   // the dual cell, its proposals, the climb, the extremes
  LineHit hit;                       // misses, touches or crosses; entry and exit
  std::optional<Vec2> entry, exit;   // where it meets the boundary (crossing edges rounded)
  std::optional<Segment2D> clipped;  // the part of the segment p1-p2 inside the polygon
};

// The dual view's square beside the primal frame: dual point d is drawn at world point
// middle + scale * (d - dualMiddle).
struct DualInset {
  Box2 primal;         // the primal frame: the polygon's box, grown a little
  Box2 frame;          // the inset square, right of the primal frame
  Vec2 dualMiddle{};   // the dual point drawn at the inset's middle
  double scale = 1.0;  // world units per dual unit
  glm::dvec2 toWorld(Vec2 d) const;
  Vec2 toDual(glm::dvec2 w) const;
  // both frames, for fitting the camera
  Box2 both() const;
};

// The inset for a polygon whose box is `bounds`, showing the dual square of half-side
// `dualHalf` around `dualMiddle`: a square as tall as the primal frame (or as wide, if
// wider), a small gap to its right.
DualInset makeDualInset(const Box2& bounds, Vec2 dualMiddle, double dualHalf);

// The Lines mode: off by default; when on, it follows the scene's shape with a
// LineIntersector of the dual method and answers the line placed.
class Lines2D {
 public:
  bool enabled() const { return enabled_; }
  void setEnabled(bool on);
  // follows the scene's shape (rebuilds the intersector when it changed); call every frame
  void sync(const Scene2D& scene);
  // the line through p1 and p2 (kept across shape changes); false and ignored when p1 == p2
  bool setLine(Vec2 p1, Vec2 p2);
  void clearLine();
  // grows the primal frame to hold the line's two points (a line given on the command line
  // shows whole); the frame returns to the polygon's when the mode is turned off
  void frameLine();
  const std::optional<LineProbe2D>& line() const { return line_; }

  // what core built: the intersector (null until synced while on) and its dual's cells
  const LineIntersector* intersector() const { return intersector_.get(); }
  const std::vector<Cell2D>& dualCells() const { return dualCells_; }
  std::span<const Vec2> dualVertices() const;
  // the dual locator's centre c*, when it has one
  std::optional<Vec2> dualCentre() const;
  const DualInset& inset() const { return inset_; }
  // The dual point core aims the cell with: c* + w / |w|_max, w = (p2 - p1) turned a quarter
  // counter-clockwise (the line's normal); none without a line or a centre.
  std::optional<Vec2> dualPoint() const;
  // grows with every change that the drawing shows
  std::uint64_t version() const { return version_; }

 private:
  void rebuild(const ConvexPolygon& polygon);
  void answer();
  bool enabled_ = false;
  std::optional<std::pair<Vec2, Vec2>> asked_;
  std::optional<Box2> framed_;  // what the primal frame holds beside the polygon
  std::unique_ptr<LineIntersector> intersector_;
  std::vector<Cell2D> dualCells_;
  DualInset inset_;
  std::optional<LineProbe2D> line_;
  std::uint64_t shapeSeen_ = ~std::uint64_t{0};
  const Scene2D* sceneSeen_ = nullptr;
  std::uint64_t version_ = 0;
};

// The extreme vertices' lines of a trace (shared with the Planes mode): where the side
// function `side` ("f", "G") is largest and smallest, its exact signs there, the count of
// exact comparisons.
void describeExtremes(const ExtremeVertices& extremes, const char* side, std::uint32_t comparisons,
                      std::vector<TraceLine>& out);

// The line's answer told for a student: the classification, the dual cell and what it
// proposed, the climb, the extremes with their signs, entry and exit, the clipped segment.
std::vector<TraceLine> describeLine(const LineProbe2D& line, std::span<const Vec2> dualVertices,
                                    const PolarLocator* dual);

}  // namespace convexloc::viewer
