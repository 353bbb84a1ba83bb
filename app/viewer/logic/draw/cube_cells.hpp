// convexloc-viewer — a cube-map cell drawn: its square on the drawing cube, filled or
// outlined, and its pyramid from the centre. The 3D structure, the build animation and the
// dual view all draw cells with these, so a cell looks the same wherever it shows.
#pragma once

#include <array>

#include <glm/glm.hpp>

#include "convexloc/locate3d.hpp"
#include "logic/base/colour.hpp"
#include "logic/base/draw_list.hpp"

namespace convexloc::viewer {

// where a cell is drawn: its square's four corners, in order around it, and the pyramid's apex
struct CubeCellPlace {
  std::array<glm::dvec3, 4> corners;
  glm::dvec3 apex{0.0};
};

// the cell where core puts it: on the drawing cube around the centre
CubeCellPlace placeOf(const Cell3D& cell);
// the square, filled (two triangles)
void fillCubeCell(const CubeCellPlace& cell, Rgba colour, DrawList& out);
// the square's four sides
void outlineCubeCell(const CubeCellPlace& cell, Rgba colour, float width, DrawList& out);
// the pyramid: each side of the square (`side` wide) and the dashed edge from the apex to its
// corner (`edge` wide)
void cubeCellPyramid(const CubeCellPlace& cell, Rgba colour, float side, float edge, DrawList& out);

}  // namespace convexloc::viewer
