// convexloc-viewer — the paper's rule for uniform slabs (Fig. 5): slabs as thin as the
// smallest y-gap between two vertices, (ymax - ymin) / gap of them, beside the bounded
// count convexloc builds. Geometry for display only: no point is classified here.
#pragma once

#include <optional>
#include <string>

#include "convexloc/polygon.hpp"
#include "logic/base/colour.hpp"
#include "logic/base/draw_list.hpp"
#include "logic/scene/scene2d.hpp"

namespace convexloc::viewer {

// the smallest gap between two different vertex y values, and what the paper's rule makes of it
struct YGap {
  double lo = 0.0, hi = 0.0;  // the two y values the gap lies between
  double ymin = 0.0, ymax = 0.0;
  double gap() const { return hi - lo; }
  // the paper's uniform slab count, (ymax - ymin) / gap
  double paperSlabs() const { return (ymax - ymin) / gap(); }
};

// the bytes the paper's slabs need at the least: two edge indices (4 bytes each) a slab
inline constexpr double kPaperBytesPerSlab = 8.0;

// the polygon's smallest y-gap; none when all vertices share one y (impossible for a polygon)
std::optional<YGap> smallestYGap(const ConvexPolygon& polygon);

// the paper's slab count and memory for the smallest gap, and convexloc's count and memory
// when the method is uniform, one line each ("" without a gap)
std::string yGapCostText(const Scene2D& scene);

// The gap marked on the drawing: two horizontal lines through its vertices and a dimension
// arrow between them, labelled with the gap.
void drawYGap(const Scene2D& scene, const Palette& pal, DrawList& out);

}  // namespace convexloc::viewer
