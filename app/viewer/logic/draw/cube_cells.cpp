// convexloc-viewer — a cube-map cell drawn.
#include "logic/draw/cube_cells.hpp"

#include "logic/scene/scene3d.hpp"

namespace convexloc::viewer {

CubeCellPlace placeOf(const Cell3D& cell) {
  CubeCellPlace p;
  for (std::size_t k = 0; k < 4; ++k) p.corners[k] = toGlm(cell.corners[k]);
  p.apex = toGlm(cell.apex);
  return p;
}

void fillCubeCell(const CubeCellPlace& cell, Rgba colour, DrawList& out) {
  const auto& k = cell.corners;
  out.triangle(k[0], k[1], k[2], colour);
  out.triangle(k[0], k[2], k[3], colour);
}

void outlineCubeCell(const CubeCellPlace& cell, Rgba colour, float width, DrawList& out) {
  for (std::size_t k = 0; k < 4; ++k)
    out.segment(cell.corners[k], cell.corners[(k + 1) % 4], colour, width);
}

void cubeCellPyramid(const CubeCellPlace& cell, Rgba colour, float side, float edge,
                     DrawList& out) {
  for (std::size_t k = 0; k < 4; ++k) {
    out.segment(cell.corners[k], cell.corners[(k + 1) % 4], colour, side);
    out.segment(cell.apex, cell.corners[k], colour, edge, 5.0f);
  }
}

}  // namespace convexloc::viewer
