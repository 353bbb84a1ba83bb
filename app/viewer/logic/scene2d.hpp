// convexloc-viewer — the 2D scene: the polygon, the chosen method and its locator, the
// sprayed points and their classes, the placed point and its trace, the hovered cell and
// a vertex being dragged. GL-free. Every classification and every cell comes from core;
// the scene only keeps them, and counts what changed so the renderer re-uploads only that.
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

namespace convexloc::viewer {

// what a spray asks for
struct SpraySettings {
  std::size_t count = 2000;
  std::uint64_t seed = 1;
  bool nearBoundary = false;  // core's hard cases on and next to the boundary
};

// the point placed by a click, and what the locator did with it
struct Probe {
  Vec2 point{};
  Trace2D trace;
};

// one method timed by `compare`
struct CompareRow {
  Method2D method = Method2D::Halfplane;
  std::size_t points = 0;  // how many of the spray were located in the time budget
  double nsPerPoint = 0.0;
  double buildMs = 0.0;
  std::size_t bytes = 0;
  std::size_t cells = 0;
  std::size_t disagreements = 0;  // answers differing from the current method's (0 expected)
};

// a vertex being dragged
struct Drag {
  std::size_t vertex = 0;  // its index in the current polygon
  Vec2 cursor{};           // where the mouse is
  bool rejected = false;   // the shape with the vertex at the cursor is not valid
  std::string message;     // why, when rejected
};

// counters bumped when a part changes, so that drawing rebuilds only that part
struct Versions {
  std::uint64_t shape = 0;      // the polygon
  std::uint64_t structure = 0;  // the locator and its cells (bumped with the shape too)
  std::uint64_t points = 0;     // the spray or its classes
  std::uint64_t overlay = 0;    // probe, hover, drag
  std::uint64_t section = 0;    // 3D: the slicing plane's section
};

// above this many cells a subdivision is not drawn (nor hovered): its statistics still are
inline constexpr std::size_t kMaxDrawnCells = std::size_t{1} << 18;

// how many edges the cells of a method list at the least (the base of the tint)
std::size_t baseEdgesPerCell(Method2D m);

class Scene2D {
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
  // a polygon file (.txt, one vertex per line); false and error() when it cannot be used
  bool loadFile(const std::string& path);
  const ConvexPolygon& polygon() const { return *polygon_; }
  // what the shape is, in words ("random, 16 vertices, seed 7", a file name)
  const std::string& label() const { return label_; }

  // === Method
  void setMethod(Method2D m);
  Method2D method() const { return method_; }
  // Slabs (uniform) or slabs per octant (polar), 0 = chosen by core; other methods have
  // none. On a value core refuses, keeps the locator, returns false and sets error().
  // A resolution set here stays for new shapes; the default scene's goes back to core's
  // choice when another shape comes.
  bool setResolution(std::uint32_t r);
  std::uint32_t resolution() const { return resolution_[static_cast<std::size_t>(method_)]; }
  // the resolution the locator actually uses (core's choice when 0 was asked)
  std::uint32_t effectiveResolution() const;
  const Locator2D& locator() const { return *locator_; }
  // the cells, as core reports them; empty when there are more than kMaxDrawnCells
  const std::vector<Cell2D>& cells() const { return cells_; }
  // the locator has cells, but too many to draw
  bool cellsOmitted() const { return stats_.cells > cells_.size(); }
  const Stats2D& stats() const { return stats_; }
  // the polar centre, when the method is polar and core found one strictly inside
  std::optional<Vec2> centre() const;

  // === Spray
  void spray(const SpraySettings& s);
  void clearSpray();
  const SpraySettings& spraySettings() const { return spray_; }
  std::span<const Vec2> points() const { return points_; }
  std::span<const Location> classes() const { return classes_; }
  // points per class, indexed by Location
  const std::array<std::size_t, 3>& counts() const { return counts_; }
  // nanoseconds per point of the last batch classification, and the seconds it took
  double locateNsPerPoint() const { return locateNsPerPoint_; }

  // === Probe: a placed point and its trace
  void place(Vec2 p);
  void clearProbe();
  const std::optional<Probe>& probe() const { return probe_; }

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

  // === Compare: every method timed on the current spray (a temporary one when empty),
  // at most about `secondsPerMethod` each
  std::vector<CompareRow> compare(double secondsPerMethod = 0.12) const;

  // === Errors: the last problem, for the UI; `errorSerial` grows with each new one
  const std::string& error() const { return error_; }
  std::uint64_t errorSerial() const { return errorSerial_; }
  void clearError() { error_.clear(); }
  void setError(std::string message);

  const Versions& versions() const { return versions_; }

 private:
  bool adopt(ConvexPolygon polygon, std::string label, bool respray);
  bool rebuildLocator();
  void classify();
  void retrace();

  std::optional<ConvexPolygon> polygon_;
  std::string label_;
  Method2D method_ = Method2D::Polar;
  std::array<std::uint32_t, 5> resolution_{};
  std::array<bool, 5> chosen_{};  // the resolution was set through setResolution
  std::optional<Locator2D> locator_;
  std::vector<Cell2D> cells_;
  Stats2D stats_;

  SpraySettings spray_;
  std::vector<Vec2> points_;
  std::vector<Location> classes_;
  std::array<std::size_t, 3> counts_{};
  double locateNsPerPoint_ = 0.0;

  std::optional<Probe> probe_;
  std::ptrdiff_t hovered_ = -1;
  std::optional<Vec2> hoverPoint_;
  std::optional<Drag> drag_;

  std::string error_;
  std::uint64_t errorSerial_ = 0;
  Versions versions_;
};

}  // namespace convexloc::viewer
