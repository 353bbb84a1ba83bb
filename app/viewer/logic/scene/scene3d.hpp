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
#include <utility>
#include <vector>

#include <glm/glm.hpp>

#include "convexloc/generate3d.hpp"
#include "convexloc/locate3d.hpp"
#include "convexloc/polyhedron.hpp"
#include "logic/scene/scene_common.hpp"
#include "logic/view/camera3d.hpp"

namespace convexloc::viewer {

// A grid of samples over the slicing plane's rectangle, each classified by the locator:
// the section of the polyhedron as core sees it.
struct Section {
  std::uint32_t n = 0;            // n x n samples
  glm::dvec3 corner{0.0};         // the rectangle's first corner
  glm::dvec3 du{0.0}, dv{0.0};    // one sample step along each in-plane axis
  std::vector<Location> classes;  // row-major, v outer
};

// === Shared with the Planes mode
// samples per side of a section's grid
inline constexpr std::uint32_t kSectionSamples = 160;
// The section over the parallelogram corner + [0, n] du + [0, n] dv: n x n samples, each at
// the middle of its square, classified by the locator in one batch.
Section sampleSection(const Locator3D& locator, glm::dvec3 corner, glm::dvec3 du, glm::dvec3 dv,
                      std::uint32_t n);
// the position in `cells` of the cube-map cell a trace used, or -1
std::ptrdiff_t cellOf(const std::vector<Cell3D>& cells, const Trace3D& trace);

// the point placed on the slicing plane, and what the locator did with it
using Probe3D = PlacedPoint<Vec3, Trace3D>;
// one 3D method timed by `compare`
using CompareRow3D = MethodTiming<Method3D>;

// the 3D dimension, for SceneState
struct Traits3D
    : SceneTypes<Vec3, ConvexPolyhedron, Locator3D, Cell3D, Stats3D, Method3D, Trace3D> {
  static std::vector<Vec3> sprayPoints(const ConvexPolyhedron& p, std::size_t n, std::uint64_t seed,
                                       bool nearBoundary);
  static ConvexPolyhedron readShape(const std::string& path);
  // --hull: a mesh file opens as the convex hull of its vertices, its faces ignored
  static inline bool hullOfFiles = false;
  static constexpr std::span<const Method3D> kMethods = kAllMethods3D;
  static constexpr Method3D kDefaultMethod = Method3D::Cubemap;
  // one grid size, kept across methods; only the cube map reads it when compared
  static constexpr std::size_t kSlots = 1;
  static constexpr std::size_t slot(Method3D) { return 0; }
  static constexpr std::uint32_t compareResolution(Method3D m, std::uint32_t g) {
    return m == Method3D::Cubemap ? g : 0;
  }
  static constexpr std::size_t kCompareSpray = 50000, kCompareChunk = 2048;
};

// how many faces the cells of a 3D method list at the least (the base of the tint)
inline constexpr std::size_t kBaseFacesPerCell = 1;

// "dodecahedron, 12 faces (36 triangles)": a generated shape by its plane faces (the
// triangles where they differ), with the seed where the kind is random
std::string generatedLabel(PolyhedronKind kind, const ConvexPolyhedron& p, std::uint64_t seed);

// The 3D scene: SceneState over a convex polyhedron, plus the slicing plane and its
// section, and the hovered and the pinned cell.
class Scene3D : public SceneState<Traits3D> {
 public:
  // the default scene: an icosahedron with the cube map
  Scene3D();

  // === Shape
  // Makes `mesh` the shape (validated by core). On failure keeps the current one, returns
  // false, and error() says why ("file.off:12: not convex: ...").
  bool setMesh(const MeshData& mesh, std::string label, const std::string& source = "");
  // a generated polyhedron (core's generators); false and error() on a bad argument
  bool generate(PolyhedronKind kind, std::size_t n, std::uint64_t seed);
  const ConvexPolyhedron& polyhedron() const { return *shape_; }
  // the polyhedron's box, as GLM vectors
  Bounds3 bounds() const;

  // === Method
  // the cube map's grid size in use (core's choice when 0 was asked), 0 for other methods
  std::uint32_t effectiveResolution() const;
  // the centre strictly inside (walk, cube map), when core found one
  std::optional<Vec3> centre() const;
  // half the side of the cube the cells are drawn on (0 without cells)
  double cubeHalfSize() const;

  // === Slicing plane and its section
  void setSlice(SlicePlane s);
  const SlicePlane& slice() const { return slice_; }
  // the plane's rectangle: the polyhedron's box grown by 15% in the two in-plane axes
  std::array<glm::dvec3, 4> sliceRectangle() const;
  // where the ray meets the plane inside its rectangle, if it does
  std::optional<glm::dvec3> hitSlice(const Ray3& ray) const;
  const Section& section() const { return section_; }

  // the position in cells() of the cell the probe's query used, or -1
  std::ptrdiff_t probeCell() const;

  // === Cells under the cursor and pinned: positions in cells(), -1 for none
  void hover(std::optional<Ray3> ray);
  std::ptrdiff_t hoveredCell() const { return hovered_; }
  // Pins a cell (-1: none, which also drops the second). A pinned cell survives a switch
  // to a method without cells and back: the same cell of the same grid is pinned again.
  void pin(std::ptrdiff_t cell);
  std::ptrdiff_t pinnedCell() const { return pinned_; }
  // a second pinned cell, shown beside the first (a figure compares two cells); -1: none
  void pinSecond(std::ptrdiff_t cell);
  std::ptrdiff_t secondPinnedCell() const { return pinned2_; }
  // a cell listing exactly one face and a cell listing the most faces on the same cube
  // face, far apart (-1 where there is none): the paper's Fig. 7
  std::pair<std::ptrdiff_t, std::ptrdiff_t> typicalCells() const;
  // the cell whose square on the drawing cube the ray leaves it by (the far side), or -1
  std::ptrdiff_t pickCell(const Ray3& ray) const;

 private:
  void cellsChanged() override;
  bool adoptShape(ConvexPolyhedron poly, std::string label) override;
  void dropChosenCell() override { pinned_ = pinned2_ = -1; }
  void resection();
  // a cell by its place on the cube and the grid size, to pin it again in new cells
  struct CellKey {
    int cubeFace = 0, level = 0;
    std::uint32_t i = 0, j = 0, grid = 0;
  };
  std::optional<CellKey> keyOf(std::ptrdiff_t cell) const;
  std::ptrdiff_t findCell(const std::optional<CellKey>& key) const;

  SlicePlane slice_;
  Section section_;
  std::ptrdiff_t hovered_ = -1;
  std::ptrdiff_t pinned_ = -1;
  std::ptrdiff_t pinned2_ = -1;
  std::optional<CellKey> pinKey_, pinKey2_;  // the pinned cells, by place
};

// conversions between core's points and GLM's vectors
inline glm::dvec3 toGlm(Vec3 p) {
  return {p.x, p.y, p.z};
}
inline Vec3 toVec3(glm::dvec3 p) {
  return {p.x, p.y, p.z};
}

}  // namespace convexloc::viewer
