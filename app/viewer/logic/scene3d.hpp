// convexloc-viewer — the 3D scene: the polyhedron, the chosen method and its locator (the
// cube map's cells), sprayed points, a slicing plane with the section core classifies on
// it, a point placed on that plane with its trace, the hovered and the pinned cell. GL-free;
// every class and every cell comes from core.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "convexloc/generate3d.hpp"
#include "convexloc/locate3d.hpp"
#include "convexloc/polyhedron.hpp"
#include "logic/camera3d.hpp"
#include "logic/scene2d.hpp"

namespace convexloc::viewer {

// the point placed on the slicing plane, and what the locator did with it
struct Probe3D {
  Vec3 point{};
  Trace3D trace;
};

// A grid of samples over the slicing plane's rectangle, each classified by the locator:
// the section of the polyhedron as core sees it.
struct Section {
  std::uint32_t n = 0;            // n x n samples
  glm::dvec3 corner{0.0};         // the rectangle's first corner
  glm::dvec3 du{0.0}, dv{0.0};    // one sample step along each in-plane axis
  std::vector<Location> classes;  // row-major, v outer
};

// one 3D method timed by `compare`
struct CompareRow3D {
  Method3D method = Method3D::Halfspace;
  std::size_t points = 0;
  double nsPerPoint = 0.0;
  double buildMs = 0.0;
  std::size_t bytes = 0;
  std::size_t cells = 0;
  std::size_t disagreements = 0;
};

// how many faces the cells of a 3D method list at the least (the base of the tint)
inline constexpr std::size_t kBaseFacesPerCell = 1;

class Scene3D {
 public:
  // the default scene: an icosahedron with the cube map
  Scene3D();

  // === Shape
  // Makes `mesh` the shape (validated by core). On failure keeps the current one, returns
  // false, and error() says why ("file.off:12: not convex: ...").
  bool setMesh(const MeshData& mesh, std::string label, const std::string& source = "");
  bool generate(PolyhedronKind kind, std::size_t n, std::uint64_t seed);
  bool loadFile(const std::string& path);
  const ConvexPolyhedron& polyhedron() const { return *poly_; }
  const std::string& label() const { return label_; }
  // the polyhedron's box, as GLM vectors
  Bounds3 bounds() const;

  // === Method
  void setMethod(Method3D m);
  Method3D method() const { return method_; }
  // the cube map's grid size G, 0 = chosen by core (other methods have none)
  bool setResolution(std::uint32_t g);
  std::uint32_t resolution() const { return resolution_; }
  std::uint32_t effectiveResolution() const;
  const Locator3D& locator() const { return *locator_; }
  // the cells, as core reports them; empty when there are more than kMaxDrawnCells
  const std::vector<Cell3D>& cells() const { return cells_; }
  bool cellsOmitted() const { return stats_.cells > cells_.size(); }
  const Stats3D& stats() const { return stats_; }
  // the centre strictly inside (walk, cube map), when core found one
  std::optional<Vec3> centre() const;
  // half the side of the cube the cells are drawn on (0 without cells)
  double cubeHalfSize() const;

  // === Spray
  void spray(const SpraySettings& s);
  void clearSpray();
  const SpraySettings& spraySettings() const { return spray_; }
  std::span<const Vec3> points() const { return points_; }
  std::span<const Location> classes() const { return classes_; }
  const std::array<std::size_t, 3>& counts() const { return counts_; }
  double locateNsPerPoint() const { return locateNsPerPoint_; }

  // === Slicing plane and its section
  void setSlice(SlicePlane s);
  const SlicePlane& slice() const { return slice_; }
  // the plane's rectangle: the polyhedron's box grown by 15% in the two in-plane axes
  std::array<glm::dvec3, 4> sliceRectangle() const;
  // where the ray meets the plane inside its rectangle, if it does
  std::optional<glm::dvec3> hitSlice(const Ray3& ray) const;
  const Section& section() const { return section_; }

  // === Probe: a point placed (on the plane) and its trace
  void place(Vec3 p);
  void clearProbe();
  const std::optional<Probe3D>& probe() const { return probe_; }
  // the position in cells() of the cell the probe's query used, or -1
  std::ptrdiff_t probeCell() const;

  // === Cells under the cursor and pinned: positions in cells(), -1 for none
  void hover(std::optional<Ray3> ray);
  std::ptrdiff_t hoveredCell() const { return hovered_; }
  void pin(std::ptrdiff_t cell);
  std::ptrdiff_t pinnedCell() const { return pinned_; }
  // the cell whose square on the drawing cube the ray leaves it by (the far side), or -1
  std::ptrdiff_t pickCell(const Ray3& ray) const;

  // === Compare every method on the spray
  std::vector<CompareRow3D> compare(double secondsPerMethod = 0.12) const;

  // === Errors and versions, as in the 2D scene
  const std::string& error() const { return error_; }
  std::uint64_t errorSerial() const { return errorSerial_; }
  void setError(std::string message);
  const Versions& versions() const { return versions_; }

 private:
  bool adopt(ConvexPolyhedron poly, std::string label);
  bool rebuildLocator();
  void classify();
  void resection();
  void retrace();

  std::optional<ConvexPolyhedron> poly_;
  std::string label_;
  Method3D method_ = Method3D::Cubemap;
  std::uint32_t resolution_ = 0;
  bool chosen_ = false;  // the grid size was set through setResolution
  std::optional<Locator3D> locator_;
  std::vector<Cell3D> cells_;
  Stats3D stats_;

  SpraySettings spray_;
  std::vector<Vec3> points_;
  std::vector<Location> classes_;
  std::array<std::size_t, 3> counts_{};
  double locateNsPerPoint_ = 0.0;

  SlicePlane slice_;
  Section section_;
  std::optional<Probe3D> probe_;
  std::ptrdiff_t hovered_ = -1;
  std::ptrdiff_t pinned_ = -1;

  std::string error_;
  std::uint64_t errorSerial_ = 0;
  Versions versions_;
};

// conversions between core's points and GLM's vectors
inline glm::dvec3 toGlm(Vec3 p) {
  return {p.x, p.y, p.z};
}
inline Vec3 toVec3(glm::dvec3 p) {
  return {p.x, p.y, p.z};
}

}  // namespace convexloc::viewer
