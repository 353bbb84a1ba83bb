// convexloc-viewer — typed coordinates: a point, a vertex, a line's two ends, a plane's three
// points, each as exact doubles typed in fields, and a line or plane through chosen
// vertices, so that a degenerate position ("touches", "on the boundary") can be shown live.
#pragma once

#include "logic/app/model.hpp"

namespace convexloc::viewer {

// A field holding a double as the shortest digits that read back as it; what is typed is
// taken on Enter or when the field is left, when it reads wholly as a number (else the
// field turns red and `v` stays). True when `v` changed.
bool exactField(const char* id, double& v, float width);

// an exact field between - and + buttons that step `v` onto the multiples of `step` (the
// grid point below or above); true when `v` changed
bool steppedField(const char* id, double& v, double step);

// the 2D panel: the placed point, a vertex, and in the Lines mode the line
void typedCoordinates2D(Model& model);

// the Planes mode's plane: three points typed, or three vertices chosen
void typedPlane3D(Model& model);

// the slicing plane's offset typed, stepped by +/- on a grid of 1, 2 or 5 times a power of ten
void typedSliceOffset(Model& model);

}  // namespace convexloc::viewer
