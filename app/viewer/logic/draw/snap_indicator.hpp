// convexloc-viewer — the snap indicator: where the pointer's position snaps, drawn over the
// 2D scene. GL-free.
#pragma once

#include <string>

#include "logic/base/colour.hpp"
#include "logic/base/draw_list.hpp"
#include "logic/scene/scene2d.hpp"

namespace convexloc::viewer {

// what a snap names beside its square: "vertex 3", "edge 3-4", "centre", "grid",
// "vertex 4 (edge 3-4 holds no double here)"; "" when free (`n`: the polygon's vertex
// count, for an edge's far end)
std::string snapText(const Snap& s, std::size_t n);

// a square where the scene's snap mark is, and snapText beside it; nothing without a mark
void snapIndicator(const Scene2D& scene, const Palette& palette, DrawList& out);

}  // namespace convexloc::viewer
