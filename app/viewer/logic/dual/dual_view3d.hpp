// convexloc-viewer — what the 3D Planes mode draws, from what core reports: beside the
// polyhedron the plane's patch, its section, the extreme vertices and the vertices the dual
// cells proposed; in the dual view the dual polyhedron P* (the hull of the unit face
// normals), its cube map's cells of the direction y and of -y, the dual faces they list, and
// y itself. GL-free; world coordinates (the dual view's placement).
#pragma once

#include "logic/base/colour.hpp"
#include "logic/base/draw_list.hpp"
#include "logic/dual/planes3d.hpp"

namespace convexloc::viewer {

// the colour of a crossing: crosses as inside, touches as boundary, misses as outside
Rgba crossingColour(const Palette& palette, Crossing c);

// The Planes mode's drawing: `solid` holds what hides behind the polyhedron (the patch, the
// section, the dual polyhedron and its cells: depth-tested), `overlay` the marks and labels
// that show through. Nothing when the mode is off.
void buildPlanes3D(const Planes3D& planes, const Palette& palette, bool labels, DrawList& solid,
                   DrawList& overlay);

}  // namespace convexloc::viewer
